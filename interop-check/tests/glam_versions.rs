//! One frame driven from glam 0.32 (Bevy 0.19) and glam 0.33 (Bevy 0.20, rerun, rapier) through
//! mint and through plain arrays: every input arrives bit for bit as the crate's own glam 0.34
//! value, and every upload value comes back bit for bit.

use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, Frame, FrameInput, FrameScheme,
};
use shadow_aliasing::glam as g34;
use shadow_aliasing::maps::{ClipDepth, WarpRule};

const NEAR: f64 = 0.1;
const FAR: f64 = 400.0;
const HALF_FOV: f64 = 0.6;
const ASPECT: f64 = 16.0 / 9.0;
const DEPTHS: [ClipDepth; 2] = [ClipDepth::NegOneToOne, ClipDepth::ZeroToOne];

/// The frame every path must reproduce: the crate's own glam 0.34 types, made from the same
/// column arrays the other versions' view matrices hold.
fn own_frame(view_cols: [[f64; 4]; 4], sun: [f64; 3], boxes: &[([f64; 3], [f64; 3])]) -> Frame {
    let camera = Camera::new(
        g34::DMat4::from_cols_array_2d(&view_cols),
        NEAR,
        FAR,
        HALF_FOV,
        ASPECT,
    )
    .unwrap();
    let boxes: Vec<Aabb> = boxes
        .iter()
        .map(|(a, b)| Aabb::new(g34::DVec3::from_array(*a), g34::DVec3::from_array(*b)).unwrap())
        .collect();
    run(camera, g34::DVec3::from_array(sun), &boxes)
}

fn run(camera: Camera, sun: g34::DVec3, boxes: &[Aabb]) -> Frame {
    let input = FrameInput::new(camera, sun, 2048, 1080)
        .receivers(Bound::Boxes(&boxes[..1]))
        .casters(Bound::Boxes(boxes))
        .scheme(FrameScheme::Cascades {
            splits: CascadeSplits::Fractions {
                fractions: &[0.05, 0.2, 0.5],
                overlap: 0.1,
            },
            rule: WarpRule::Lispsm,
        });
    let f = frame(&input).unwrap();
    assert_eq!(f.len(), 4, "four cascades");
    f
}

const BOXES: [([f64; 3], [f64; 3]); 2] = [
    ([-300.0, -1.0, -300.0], [300.0, 0.0, 300.0]),
    ([-4.0, 0.0, -30.0], [4.0, 25.0, -22.0]),
];
const SUN: [f64; 3] = [0.35, -1.0, -0.25];

fn bits(m: [[f32; 4]; 4]) -> [[u32; 4]; 4] {
    m.map(|c| c.map(f32::to_bits))
}

/// Every upload value of `f` equals `own`'s bit for bit, read back into the caller's glam through
/// `back` (a matrix as column arrays, however the caller's glam got it).
fn same_uploads(
    f: &Frame,
    own: &Frame,
    back: impl Fn(&shadow_aliasing::frame::FrameMap, ClipDepth) -> [[f32; 4]; 4],
) {
    assert_eq!(f, own);
    for (m, o) in f.maps().iter().zip(own.maps().iter()) {
        for d in DEPTHS {
            assert_eq!(bits(back(m, d)), bits(o.world_to_clip_cols(d)));
            assert_eq!(m.gpu(d).to_bytes(), o.gpu(d).to_bytes());
        }
    }
}

#[test]
fn glam_032_through_mint_and_arrays() {
    use glam032 as g;
    let view = g::DMat4::look_at_rh(
        g::DVec3::new(10.0, 6.0, 40.0),
        g::DVec3::new(12.0, 2.0, -10.0),
        g::DVec3::Y,
    );
    let own = own_frame(view.to_cols_array_2d(), SUN, &BOXES);
    let sun = g::DVec3::from_array(SUN);
    let boxes: Vec<Aabb> = BOXES
        .iter()
        .map(|(a, b)| {
            let (a, b) = (g::DVec3::from_array(*a), g::DVec3::from_array(*b));
            Aabb::new(mint::Vector3::from(a), mint::Vector3::from(b)).unwrap()
        })
        .collect();
    // Through mint: the caller's types go in as they are and come back as the caller's.
    let cam = Camera::new(mint::ColumnMatrix4::from(view), NEAR, FAR, HALF_FOV, ASPECT).unwrap();
    let f = run(cam, mint::Vector3::from(sun).into(), &boxes);
    same_uploads(&f, &own, |m, d| {
        g::Mat4::from(m.to_mint(d)).to_cols_array_2d()
    });
    // Through arrays.
    let cam = Camera::new(
        g34::DMat4::from_cols_array_2d(&view.to_cols_array_2d()),
        NEAR,
        FAR,
        HALF_FOV,
        ASPECT,
    )
    .unwrap();
    let f = run(cam, g34::DVec3::from_array(sun.to_array()), &boxes);
    same_uploads(&f, &own, |m, d| {
        g::Mat4::from_cols_array_2d(&m.world_to_clip_cols(d)).to_cols_array_2d()
    });
}

#[test]
fn glam_033_through_mint_and_arrays_single_precision_view() {
    use glam033 as g;
    // An engine's f32 view matrix (Bevy's `GlobalTransform` is f32): widened exactly.
    let view = g::camera::rh::view::look_at_mat4(
        g::Vec3::new(-20.0, 9.0, 15.0),
        g::Vec3::new(0.0, 1.0, -30.0),
        g::Vec3::Y,
    );
    let wide = view.to_cols_array_2d().map(|c| c.map(f64::from));
    let own = own_frame(wide, SUN, &BOXES);
    let boxes: Vec<Aabb> = BOXES
        .iter()
        .map(|(a, b)| {
            let (a, b) = (g::DVec3::from_array(*a), g::DVec3::from_array(*b));
            Aabb::new(mint::Vector3::from(a), mint::Vector3::from(b)).unwrap()
        })
        .collect();
    let sun = g::DVec3::from_array(SUN);
    let cam =
        Camera::from_mat4(mint::ColumnMatrix4::from(view), NEAR, FAR, HALF_FOV, ASPECT).unwrap();
    let f = run(cam, mint::Vector3::from(sun).into(), &boxes);
    same_uploads(&f, &own, |m, d| {
        g::Mat4::from(m.to_mint(d)).to_cols_array_2d()
    });
    // The f64 matrix through mint too.
    for m in f.maps().iter() {
        let w = g::DMat4::from(m.world_to_clip_mint(ClipDepth::ZeroToOne));
        assert_eq!(
            w.to_cols_array().map(f64::to_bits),
            m.world_to_clip(ClipDepth::ZeroToOne)
                .to_cols_array()
                .map(f64::to_bits)
        );
    }
    let cam = Camera::from_mat4(
        g34::Mat4::from_cols_array_2d(&view.to_cols_array_2d()),
        NEAR,
        FAR,
        HALF_FOV,
        ASPECT,
    )
    .unwrap();
    let f = run(cam, g34::DVec3::from_array(sun.to_array()), &boxes);
    same_uploads(&f, &own, |m, d| {
        g::Mat4::from_cols_array_2d(&m.world_to_clip_cols(d)).to_cols_array_2d()
    });
}

#[test]
fn both_versions_side_by_side_agree() {
    // The same view built by each version's own look_at (glam's code, not the crate's) gives the
    // same bits, so a Bevy 0.19 and a Bevy 0.20 renderer upload the same maps.
    let eye = [5.0, 3.0, 12.0];
    let at = [6.0, 1.0, -20.0];
    let v32 = glam032::DMat4::look_at_rh(eye.into(), at.into(), glam032::DVec3::Y);
    let v33 = glam033::dcamera::rh::view::look_at_mat4(eye.into(), at.into(), glam033::DVec3::Y);
    assert_eq!(v32.to_cols_array_2d(), v33.to_cols_array_2d());
    let boxes: Vec<Aabb> = BOXES
        .iter()
        .map(|(a, b)| Aabb::new(*a, *b).unwrap())
        .collect();
    let c32 = Camera::new(mint::ColumnMatrix4::from(v32), NEAR, FAR, HALF_FOV, ASPECT).unwrap();
    let c33 = Camera::new(mint::ColumnMatrix4::from(v33), NEAR, FAR, HALF_FOV, ASPECT).unwrap();
    let (f32_, f33) = (run(c32, SUN.into(), &boxes), run(c33, SUN.into(), &boxes));
    assert_eq!(f32_, f33);
    for (a, b) in f32_.maps().iter().zip(f33.maps().iter()) {
        let a = glam032::Mat4::from(a.to_mint(ClipDepth::ZeroToOne));
        let b = glam033::Mat4::from(b.to_mint(ClipDepth::ZeroToOne));
        assert_eq!(bits(a.to_cols_array_2d()), bits(b.to_cols_array_2d()));
    }
}
