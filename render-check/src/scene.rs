//! The scene: world-space boxes (each may be rotated) on a ground plane, a camera and a light
//! (docs/rendered.md has the JSON format), its triangles and its exact ray cast.

use glam::{DMat4, DQuat, DVec3};
use serde::{Deserialize, Serialize};

/// A box in world space: the axis-aligned box `min`..`max`, then rotated about its centre by
/// `rotation_deg`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneBox {
    /// Smallest corner before the rotation.
    pub min: [f64; 3],
    /// Largest corner before the rotation.
    pub max: [f64; 3],
    /// Rotation about the box's centre, degrees: `[a, b, c]` turns it by a about the world X
    /// axis, then b about world Y, then c about world Z (right-handed). Default none.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub rotation_deg: [f64; 3],
}

fn is_zero(r: &[f64; 3]) -> bool {
    *r == [0.0; 3]
}

impl SceneBox {
    /// An axis-aligned box.
    pub fn aligned(min: [f64; 3], max: [f64; 3]) -> Self {
        Self {
            min,
            max,
            rotation_deg: [0.0; 3],
        }
    }

    /// Whether the box is rotated.
    pub fn is_rotated(&self) -> bool {
        !is_zero(&self.rotation_deg)
    }

    /// The centre (fixed by the rotation).
    pub fn centre(&self) -> DVec3 {
        0.5 * (v(self.min) + v(self.max))
    }

    /// The rotation (about the centre): X first, then Y, then Z, world axes.
    pub fn rotation(&self) -> DQuat {
        let [a, b, c] = self.rotation_deg.map(f64::to_radians);
        DQuat::from_rotation_z(c) * DQuat::from_rotation_y(b) * DQuat::from_rotation_x(a)
    }

    /// A point of the unrotated box moved by the rotation.
    pub fn place(&self, p: DVec3) -> DVec3 {
        if self.is_rotated() {
            let c = self.centre();
            c + self.rotation() * (p - c)
        } else {
            p
        }
    }

    /// The world-space axis-aligned bounds of the rotated box (its eight corners' bounds).
    pub fn world_bounds(&self) -> (DVec3, DVec3) {
        let (lo, hi) = (v(self.min), v(self.max));
        let mut a = DVec3::INFINITY;
        let mut b = DVec3::NEG_INFINITY;
        for k in 0..8 {
            let c = DVec3::new(
                if k & 1 == 0 { lo.x } else { hi.x },
                if k & 2 == 0 { lo.y } else { hi.y },
                if k & 4 == 0 { lo.z } else { hi.z },
            );
            let p = self.place(c);
            a = a.min(p);
            b = b.max(p);
        }
        (a, b)
    }
}

/// The camera: a right-handed look-at with a vertical field of view.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    /// Eye position, world space.
    pub eye: [f64; 3],
    /// A point the camera looks at.
    pub target: [f64; 3],
    /// The up direction.
    pub up: [f64; 3],
    /// Near plane distance.
    pub near: f64,
    /// Far plane distance.
    pub far: f64,
    /// Vertical field of view, degrees (full angle).
    pub fov_y_deg: f64,
}

/// A scene as the JSON file gives it (an unknown key is an error naming it).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Height of the ground plane y = ground_y.
    pub ground_y: f64,
    /// Half the side of the square of ground that is drawn, centred below the camera.
    pub ground_half_extent: f64,
    /// The boxes (casters and receivers).
    pub boxes: Vec<SceneBox>,
    /// The camera.
    pub camera: Camera,
    /// The direction the light travels, world space (any length).
    pub light_dir: [f64; 3],
    /// Shadow-map resolution per map (texels along each side).
    pub map_resolution: u32,
}

fn v(a: [f64; 3]) -> DVec3 {
    DVec3::from_array(a)
}

impl Scene {
    /// Reads and checks a scene file.
    pub fn load(path: &std::path::Path) -> Result<Self, String> {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let s: Scene =
            serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
        s.validate()
            .map_err(|e| format!("{}: {e}", path.display()))?;
        Ok(s)
    }

    /// Checks every number (finite, boxes non-empty, camera valid, light pointing down).
    pub fn validate(&self) -> Result<(), String> {
        let c = &self.camera;
        let all = [
            self.ground_y,
            self.ground_half_extent,
            c.near,
            c.far,
            c.fov_y_deg,
        ]
        .into_iter()
        .chain(c.eye)
        .chain(c.target)
        .chain(c.up)
        .chain(self.light_dir);
        if all.into_iter().any(|x| !x.is_finite()) {
            return Err("every number must be finite".into());
        }
        if self.ground_half_extent <= 0.0 {
            return Err("ground_half_extent must be positive".into());
        }
        for (i, b) in self.boxes.iter().enumerate() {
            if b.min.iter().chain(&b.max).any(|x| !x.is_finite())
                || (0..3).any(|k| b.max[k] <= b.min[k])
            {
                return Err(format!(
                    "boxes[{i}] must have finite corners with max > min (got min {:?}, max {:?})",
                    b.min, b.max
                ));
            }
            if b.rotation_deg.iter().any(|x| !x.is_finite()) {
                return Err(format!(
                    "boxes[{i}].rotation_deg must be finite (got {:?})",
                    b.rotation_deg
                ));
            }
        }
        if !(c.near > 0.0 && c.far > c.near) {
            return Err("camera needs 0 < near < far".into());
        }
        if !(c.fov_y_deg > 0.0 && c.fov_y_deg < 179.0) {
            return Err("camera fov_y_deg must lie in (0, 179)".into());
        }
        let f = v(c.target) - v(c.eye);
        if f.length() == 0.0 || f.cross(v(c.up)).length() < 1e-9 * f.length() * v(c.up).length() {
            return Err("camera target must differ from eye and not lie along up".into());
        }
        let l = v(self.light_dir);
        if l.length() <= 0.0 || l.y >= 0.0 {
            return Err("light_dir must be non-zero and travel downwards (y < 0)".into());
        }
        if self.map_resolution < 16 || self.map_resolution > 8192 {
            return Err("map_resolution must lie in [16, 8192]".into());
        }
        Ok(())
    }

    /// The unit direction the light travels.
    pub fn light(&self) -> DVec3 {
        v(self.light_dir).normalize()
    }

    /// World → eye (right-handed, −Z forward).
    pub fn world_to_eye(&self) -> DMat4 {
        let c = &self.camera;
        glam::dcamera::rh::view::look_at_mat4(v(c.eye), v(c.target), v(c.up))
    }

    /// The built-in scene (module docs of `setups`): rows of boxes, thin poles, a floating slab
    /// and a tall tower behind the camera (outside the view frustum).
    pub fn builtin() -> Self {
        let mut boxes = Vec::new();
        // Rows of boxes of varied heights.
        for (r, z) in [-8.0, -18.0, -30.0, -45.0, -65.0, -90.0].iter().enumerate() {
            for (c, x) in [-14.0, -5.0, 4.0, 13.0].iter().enumerate() {
                let h = 1.0 + ((r * 3 + c * 5) % 4) as f64;
                let w = 1.0 + 0.25 * ((r + c) % 3) as f64;
                boxes.push(SceneBox::aligned([x - w, 0.0, z - w], [x + w, h, z + w]));
            }
        }
        // Thin poles.
        for (x, z) in [
            (-9.0, -12.0),
            (0.5, -14.0),
            (8.0, -24.0),
            (-2.0, -38.0),
            (18.0, -55.0),
        ] {
            boxes.push(SceneBox::aligned(
                [x - 0.12, 0.0, z - 0.12],
                [x + 0.12, 6.0, z + 0.12],
            ));
        }
        // A floating slab.
        boxes.push(SceneBox::aligned([-7.0, 4.0, -28.0], [5.0, 4.5, -21.0]));
        // A tall tower behind the camera, outside the view frustum.
        boxes.push(SceneBox::aligned([-4.0, 0.0, 12.0], [2.0, 45.0, 18.0]));
        Scene {
            ground_y: 0.0,
            ground_half_extent: 260.0,
            boxes,
            camera: Camera {
                eye: [0.0, 6.0, 0.0],
                target: [0.0, 0.0, -40.0],
                up: [0.0, 1.0, 0.0],
                near: 0.5,
                far: 120.0,
                fov_y_deg: 60.0,
            },
            light_dir: [0.0, -1.0, 0.0],
            map_resolution: 1024,
        }
    }

    /// The scene moved by `offset`: every box and the camera (the ground stays at `ground_y`
    /// when `offset.y` is 0, and is drawn centred below the camera).
    pub fn translated(&self, offset: DVec3) -> Self {
        let mut s = self.clone();
        let add = |a: [f64; 3]| (v(a) + offset).to_array();
        for b in &mut s.boxes {
            b.min = add(b.min);
            b.max = add(b.max);
        }
        s.camera.eye = add(s.camera.eye);
        s.camera.target = add(s.camera.target);
        s.ground_y += offset.y;
        s
    }

    /// The thin-caster scene (also `render-check/scenes/thin_casters.json`): under a sun 20°
    /// above the horizon, a tower 40 units tall and 1 wide outside the view whose shadow, 110
    /// units long and 1 wide, crosses the visible ground; three poles 0.2 wide leaning 10° (their
    /// feet sunk 0.3 into the ground, so the lean lifts no corner above it); and a slab floating
    /// 1.5 above the ground near the camera.
    pub fn thin_casters() -> Self {
        let pole = |x: f64, z: f64, rotation_deg: [f64; 3]| SceneBox {
            min: [x - 0.1, -0.3, z - 0.1],
            max: [x + 0.1, 5.0, z + 0.1],
            rotation_deg,
        };
        Scene {
            ground_y: 0.0,
            ground_half_extent: 200.0,
            boxes: vec![
                SceneBox::aligned([-40.5, 0.0, -30.5], [-39.5, 40.0, -29.5]),
                pole(-6.0, -14.0, [10.0, 0.0, 0.0]),
                pole(3.0, -20.0, [0.0, 0.0, -10.0]),
                pole(9.0, -32.0, [10.0, 45.0, 0.0]),
                SceneBox::aligned([-1.5, 1.5, -9.0], [1.5, 2.0, -6.0]),
            ],
            camera: Camera {
                eye: [0.0, 6.0, 0.0],
                target: [0.0, 0.0, -40.0],
                up: [0.0, 1.0, 0.0],
                near: 0.5,
                far: 120.0,
                fov_y_deg: 60.0,
            },
            // 20° elevation, travelling along (1, 0, −0.25) horizontally.
            light_dir: [
                0.9116357484973605,
                -0.3420201433256687,
                -0.22790893712434013,
            ],
            map_resolution: 1024,
        }
    }
}

/// One planar surface: the ground, or one face of a box.
#[derive(Debug, Clone, Copy)]
pub struct Surface {
    /// Unit outward normal, world space.
    pub normal: DVec3,
    /// A point of the plane, world space.
    pub point: DVec3,
}

/// One object of the mesh: the ground or one box, its vertices contiguous.
#[derive(Debug, Clone)]
pub struct Object {
    /// Its vertices in [`Mesh::positions`].
    pub vertices: std::ops::Range<u32>,
    /// Its world-space bounds (smallest corner).
    pub min: DVec3,
    /// Its world-space bounds (largest corner).
    pub max: DVec3,
}

/// The scene's triangles (world space), one surface id per face (id 0 is the ground; the GPU
/// target stores id + 1, 0 meaning sky).
pub struct Mesh {
    /// Triangle vertices, three per triangle.
    pub positions: Vec<DVec3>,
    /// The surface of each vertex's triangle.
    pub surface: Vec<u32>,
    /// The surfaces.
    pub surfaces: Vec<Surface>,
    /// The objects, the ground first and then each box in the scene's order (what culling
    /// decides about).
    pub objects: Vec<Object>,
}

impl Mesh {
    /// The ground as a grid of tiles (smaller triangles keep the rasterizer's interpolation
    /// accurate) and every box's six faces.
    pub fn build(scene: &Scene) -> Self {
        let mut m = Mesh {
            positions: Vec::new(),
            surface: Vec::new(),
            surfaces: Vec::new(),
            objects: Vec::new(),
        };
        let y = scene.ground_y;
        let e = scene.ground_half_extent;
        let c = scene.camera.eye;
        m.surfaces.push(Surface {
            normal: DVec3::Y,
            point: DVec3::new(0.0, y, 0.0),
        });
        let n = 48;
        let step = 2.0 * e / n as f64;
        for i in 0..n {
            for j in 0..n {
                let x0 = c[0] - e + i as f64 * step;
                let z0 = c[2] - e + j as f64 * step;
                let (x1, z1) = (x0 + step, z0 + step);
                let q = [
                    DVec3::new(x0, y, z0),
                    DVec3::new(x0, y, z1),
                    DVec3::new(x1, y, z1),
                    DVec3::new(x1, y, z0),
                ];
                m.quad(q, 0);
            }
        }
        m.objects.push(Object {
            vertices: 0..m.positions.len() as u32,
            min: DVec3::new(c[0] - e, y, c[2] - e),
            max: DVec3::new(c[0] + e, y, c[2] + e),
        });
        for b in &scene.boxes {
            let first = m.positions.len() as u32;
            let (lo, hi) = (v(b.min), v(b.max));
            let corner = |x: bool, y: bool, z: bool| {
                b.place(DVec3::new(
                    if x { hi.x } else { lo.x },
                    if y { hi.y } else { lo.y },
                    if z { hi.z } else { lo.z },
                ))
            };
            // (normal, four corners counter-clockwise seen from outside)
            let faces = [
                (
                    DVec3::X,
                    [
                        (true, false, false),
                        (true, true, false),
                        (true, true, true),
                        (true, false, true),
                    ],
                ),
                (
                    DVec3::NEG_X,
                    [
                        (false, false, true),
                        (false, true, true),
                        (false, true, false),
                        (false, false, false),
                    ],
                ),
                (
                    DVec3::Y,
                    [
                        (false, true, false),
                        (false, true, true),
                        (true, true, true),
                        (true, true, false),
                    ],
                ),
                (
                    DVec3::NEG_Y,
                    [
                        (false, false, true),
                        (false, false, false),
                        (true, false, false),
                        (true, false, true),
                    ],
                ),
                (
                    DVec3::Z,
                    [
                        (true, false, true),
                        (true, true, true),
                        (false, true, true),
                        (false, false, true),
                    ],
                ),
                (
                    DVec3::NEG_Z,
                    [
                        (false, false, false),
                        (false, true, false),
                        (true, true, false),
                        (true, false, false),
                    ],
                ),
            ];
            for (normal, cs) in faces {
                // A bottom face resting on the ground is never seen and covers only ground the
                // box hides: left out, so that no stored face is coplanar with a lit receiver.
                if normal == DVec3::NEG_Y && lo.y <= y && !b.is_rotated() {
                    continue;
                }
                let q = cs.map(|(x, y, z)| corner(x, y, z));
                let id = m.surfaces.len() as u32;
                let normal = if b.is_rotated() {
                    b.rotation() * normal
                } else {
                    normal
                };
                m.surfaces.push(Surface {
                    normal,
                    point: q[0],
                });
                m.quad(q, id);
            }
            let (min, max) = b.world_bounds();
            m.objects.push(Object {
                vertices: first..m.positions.len() as u32,
                min,
                max,
            });
        }
        m
    }

    fn quad(&mut self, q: [DVec3; 4], id: u32) {
        for k in [0, 1, 2, 0, 2, 3] {
            self.positions.push(q[k]);
            self.surface.push(id);
        }
    }
}

/// How far the exact tests move a surface point `p` off its surface (world units): 10⁻⁶ of its
/// distance from the camera (plus 10⁻⁶), so a surface never shadows itself where it faces the
/// light. Relative to the camera, not the world origin: 10⁵ from the origin a lift of 10⁻⁶ of
/// the coordinates (0.1 unit) moved the exact shadow boundary by a visible amount and widened
/// the band left out of the shadow comparison.
pub fn lift(scene: &Scene, p: DVec3) -> f64 {
    1e-6 * (1.0 + (p - v(scene.camera.eye)).abs().max_element())
}

/// Exact shadow test against the analytic scene: does the ray from `p` toward the light (against
/// `light`, the direction it travels) hit a box? `p` is first moved off its own surface along
/// `normal` by [`lift`]. Slab tests (a rotated box: in its own frame, the ray turned back by its
/// rotation), independent of any shadow map. The ground cannot occlude (the light comes from
/// above it).
pub fn ray_occluded(scene: &Scene, p: DVec3, normal: DVec3, light: DVec3) -> bool {
    let o = p + normal * lift(scene, p);
    let d = -light;
    scene.boxes.iter().any(|b| {
        let (lo, hi) = (v(b.min), v(b.max));
        if b.is_rotated() {
            let c = b.centre();
            let back = b.rotation().inverse();
            slab_hit(back * (o - c), back * d, lo - c, hi - c)
        } else {
            slab_hit(o, d, lo, hi)
        }
    })
}

/// Whether the ray `o + t d`, t > 0, meets the axis-aligned box `lo`..`hi`.
fn slab_hit(o: DVec3, d: DVec3, lo: DVec3, hi: DVec3) -> bool {
    let mut t0 = 0.0f64;
    let mut t1 = f64::INFINITY;
    for k in 0..3 {
        if d[k].abs() < 1e-300 {
            if o[k] < lo[k] || o[k] > hi[k] {
                return false;
            }
        } else {
            let (a, b) = ((lo[k] - o[k]) / d[k], (hi[k] - o[k]) / d[k]);
            let (a, b) = if a < b { (a, b) } else { (b, a) };
            t0 = t0.max(a);
            t1 = t1.min(b);
            if t0 > t1 {
                return false;
            }
        }
    }
    t1 > 0.0
}

/// Whether the surface faces the light enough to be lit at all: `n·(−L) > FACING` (the same
/// threshold the shader uses).
pub const FACING: f64 = 1e-3;

#[cfg(test)]
mod tests {
    use super::*;

    fn load_text(name: &str, text: &str) -> Result<Scene, String> {
        let dir = std::env::temp_dir().join(format!("rc-scene-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join(format!("{name}.json"));
        std::fs::write(&p, text).unwrap();
        let r = Scene::load(&p);
        std::fs::remove_dir_all(&dir).unwrap();
        r
    }

    const SMALL: &str = r#"{"ground_y": 0.0, "ground_half_extent": 100.0,
        "boxes": [{"min": [-2, 0, -12], "max": [2, 3, -8]}],
        "camera": {"eye": [0, 4, 0], "target": [0, 0, -20], "up": [0, 1, 0],
                   "near": 0.5, "far": 60, "fov_y_deg": 55},
        "light_dir": [0.4, -1.0, -0.3], "map_resolution": 256}"#;

    /// An unknown key is an error that names it, at every level (top, camera, box); the same
    /// file without it loads.
    #[test]
    fn unknown_keys_are_named() {
        assert!(load_text("ok", SMALL).is_ok());
        for (name, text) in [
            (
                "top",
                SMALL.replace("\"ground_y\"", "\"grund_y\": 1, \"ground_y\""),
            ),
            ("camera", SMALL.replace("\"near\"", "\"nera\": 1, \"near\"")),
            (
                "box",
                SMALL.replace("\"max\": [2", "\"rotation\": [1, 0, 0], \"max\": [2"),
            ),
        ] {
            let key = match name {
                "top" => "grund_y",
                "camera" => "nera",
                _ => "rotation",
            };
            let e = load_text(name, &text).unwrap_err();
            assert!(
                e.contains(key) && e.contains(&format!("{name}.json")),
                "{e}"
            );
        }
        // JSON has no infinity: a non-finite rotation can come only from code.
        let mut bad = Scene::thin_casters();
        bad.boxes[2].rotation_deg[1] = f64::NAN;
        let e = bad.validate().unwrap_err();
        assert!(e.contains("boxes[2].rotation_deg"), "{e}");
    }

    /// The scene file is the built-in thin-caster scene, number for number.
    #[test]
    fn thin_casters_file_is_the_builtin_scene() {
        let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/thin_casters.json");
        assert_eq!(Scene::load(&p).unwrap(), Scene::thin_casters());
        // A 20° sun.
        let l = Scene::thin_casters().light();
        assert!(((-l.y).asin().to_degrees() - 20.0).abs() < 1e-12);
    }

    /// A box turned 45° about the vertical: its footprint is the diamond |x| + |z| ≤ √2, which
    /// the ray cast straight down and the world bounds both see.
    #[test]
    fn rotated_box_is_cast_and_bounded() {
        let mut s = Scene::builtin();
        s.boxes = vec![SceneBox {
            min: [-1.0, 0.0, -1.0],
            max: [1.0, 1.0, 1.0],
            rotation_deg: [0.0, 45.0, 0.0],
        }];
        let down = DVec3::NEG_Y;
        let hit = |x: f64, z: f64| ray_occluded(&s, DVec3::new(x, -1.0, z), DVec3::Y, down);
        assert!(hit(1.40, 0.0) && !hit(1.42, 0.0));
        assert!(hit(0.70, 0.70) && !hit(0.72, 0.72));
        assert!(hit(0.0, -1.40) && !hit(0.0, -1.42));
        let (lo, hi) = s.boxes[0].world_bounds();
        let r2 = 2f64.sqrt();
        assert!((lo - DVec3::new(-r2, 0.0, -r2)).abs().max_element() < 1e-12);
        assert!((hi - DVec3::new(r2, 1.0, r2)).abs().max_element() < 1e-12);
    }

    /// A box turned 90° about Y is the axis-aligned box with x and z swapped: the two ray casts
    /// agree on a grid of points and light directions.
    #[test]
    fn quarter_turn_equals_the_swapped_box() {
        let mut a = Scene::builtin();
        a.boxes = vec![SceneBox {
            min: [-2.0, 0.0, -0.5],
            max: [2.0, 1.0, 0.5],
            rotation_deg: [0.0, 90.0, 0.0],
        }];
        let mut b = a.clone();
        b.boxes = vec![SceneBox::aligned([-0.5, 0.0, -2.0], [0.5, 1.0, 2.0])];
        let mut hits = 0;
        for l in [
            DVec3::NEG_Y,
            DVec3::new(0.3, -1.0, 0.2).normalize(),
            DVec3::new(-0.8, -0.5, 0.1).normalize(),
        ] {
            for i in -12..=12 {
                for j in -12..=12 {
                    let p = DVec3::new(0.23 * f64::from(i), 0.0, 0.23 * f64::from(j));
                    let (ha, hb) = (
                        ray_occluded(&a, p, DVec3::Y, l),
                        ray_occluded(&b, p, DVec3::Y, l),
                    );
                    assert_eq!(ha, hb, "{p} {l}");
                    hits += usize::from(ha);
                }
            }
        }
        assert!(hits > 20, "{hits}");
    }

    /// Every face of the thin-caster scene's boxes (leaning poles included) is planar, with the
    /// stored normal perpendicular to its edges and pointing out of its box.
    #[test]
    fn rotated_faces_have_outward_normals() {
        let s = Scene::thin_casters();
        let m = Mesh::build(&s);
        let mut rotated_faces = 0;
        for t in (0..m.positions.len()).step_by(3) {
            let id = m.surface[t] as usize;
            if id == 0 {
                continue;
            }
            let n = m.surfaces[id].normal;
            let (p0, p1, p2) = (m.positions[t], m.positions[t + 1], m.positions[t + 2]);
            let e = (p1 - p0).cross(p2 - p0).normalize();
            assert!((e - n).length() < 1e-9, "face {id}: {e} vs {n}");
            // Outward: the face's box (its bounds hold the face) has its centre behind it.
            let b = s
                .boxes
                .iter()
                .find(|b| {
                    let (lo, hi) = b.world_bounds();
                    [p0, p1, p2]
                        .iter()
                        .all(|p| p.cmpge(lo - 1e-9).all() && p.cmple(hi + 1e-9).all())
                })
                .expect("the face's box");
            assert!(n.dot(p0 - b.centre()) > 0.0, "face {id} points inward");
            rotated_faces += usize::from(b.is_rotated());
        }
        assert!(rotated_faces >= 3 * 6 * 2, "{rotated_faces}");
    }
}
