//! The scene: world-space boxes on a ground plane, a camera and a light (docs/rendered.md has the
//! JSON format), its triangles and its exact ray cast.

use glam::{DMat4, DVec3};
use serde::{Deserialize, Serialize};

/// An axis-aligned box in world space.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Aabb {
    /// Smallest corner.
    pub min: [f64; 3],
    /// Largest corner.
    pub max: [f64; 3],
}

/// The camera: a right-handed look-at with a vertical field of view.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
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

/// A scene as the JSON file gives it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// Height of the ground plane y = ground_y.
    pub ground_y: f64,
    /// Half the side of the square of ground that is drawn, centred below the camera.
    pub ground_half_extent: f64,
    /// The boxes (casters and receivers).
    pub boxes: Vec<Aabb>,
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
                return Err(format!("box {i} must have finite corners with max > min"));
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
                boxes.push(Aabb {
                    min: [x - w, 0.0, z - w],
                    max: [x + w, h, z + w],
                });
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
            boxes.push(Aabb {
                min: [x - 0.12, 0.0, z - 0.12],
                max: [x + 0.12, 6.0, z + 0.12],
            });
        }
        // A floating slab.
        boxes.push(Aabb {
            min: [-7.0, 4.0, -28.0],
            max: [5.0, 4.5, -21.0],
        });
        // A tall tower behind the camera, outside the view frustum.
        boxes.push(Aabb {
            min: [-4.0, 0.0, 12.0],
            max: [2.0, 45.0, 18.0],
        });
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
}

/// One planar surface: the ground, or one face of a box.
#[derive(Debug, Clone, Copy)]
pub struct Surface {
    /// Unit outward normal, world space.
    pub normal: DVec3,
    /// A point of the plane, world space.
    pub point: DVec3,
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
}

impl Mesh {
    /// The ground as a grid of tiles (smaller triangles keep the rasterizer's interpolation
    /// accurate) and every box's six faces.
    pub fn build(scene: &Scene) -> Self {
        let mut m = Mesh {
            positions: Vec::new(),
            surface: Vec::new(),
            surfaces: Vec::new(),
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
        for b in &scene.boxes {
            let (lo, hi) = (v(b.min), v(b.max));
            let corner = |x: bool, y: bool, z: bool| {
                DVec3::new(
                    if x { hi.x } else { lo.x },
                    if y { hi.y } else { lo.y },
                    if z { hi.z } else { lo.z },
                )
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
                if normal == DVec3::NEG_Y && lo.y <= y {
                    continue;
                }
                let q = cs.map(|(x, y, z)| corner(x, y, z));
                let id = m.surfaces.len() as u32;
                m.surfaces.push(Surface {
                    normal,
                    point: q[0],
                });
                m.quad(q, id);
            }
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

/// Exact shadow test against the analytic scene: does the ray from `p` toward the light (against
/// `light`, the direction it travels) hit a box? `p` is first moved off its own surface along
/// `normal` by 10⁻⁶ of its distance scale, so a surface never shadows itself where it faces the
/// light. Slab tests, independent of any shadow map. The ground cannot occlude (the light comes
/// from above it).
pub fn ray_occluded(scene: &Scene, p: DVec3, normal: DVec3, light: DVec3) -> bool {
    let o = p + normal * 1e-6 * (1.0 + p.abs().max_element());
    let d = -light;
    for b in &scene.boxes {
        let (lo, hi) = (v(b.min), v(b.max));
        let mut t0 = 0.0f64;
        let mut t1 = f64::INFINITY;
        let mut hit = true;
        for k in 0..3 {
            if d[k].abs() < 1e-300 {
                if o[k] < lo[k] || o[k] > hi[k] {
                    hit = false;
                    break;
                }
            } else {
                let (a, b2) = ((lo[k] - o[k]) / d[k], (hi[k] - o[k]) / d[k]);
                let (a, b2) = if a < b2 { (a, b2) } else { (b2, a) };
                t0 = t0.max(a);
                t1 = t1.min(b2);
                if t0 > t1 {
                    hit = false;
                    break;
                }
            }
        }
        if hit && t1 > 0.0 {
            return true;
        }
    }
    false
}

/// Whether the surface faces the light enough to be lit at all: `n·(−L) > FACING` (the same
/// threshold the shader uses).
pub const FACING: f64 = 1e-3;
