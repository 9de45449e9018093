//! The per-point error of any shadow matrix measured from the matrix alone by central
//! differences, with no gradient formula of the crate: the audit the planner's and the
//! controller's tests hold the frame's reported errors to.

use glam::{DMat4, DVec3};

/// The per-point error of the eye → light clip matrix `m` at the eye-space point `p`, measured
/// from the matrix alone by central differences (no gradient formula of the crate): the Jacobian
/// J of (s, t) = ((x/w + 1)/2, (y/w + 1)/2) over the plane Π perpendicular to the light `l`. A
/// texel of unit resolution spans |J⁻¹ e_s| = |∇t| / |det J| along s and 1 / |∇t| across the
/// t-isolines (Lloyd 2006 §3's w_ls, w_lt), a pixel of an image 1 high 2 z tan θ at depth z.
/// Returns (m_x, m_z) at unit resolutions.
pub fn audit_point(m: &DMat4, l: DVec3, p: DVec3, tan: f64) -> (f64, f64) {
    let u = l.any_orthonormal_vector();
    let v = l.cross(u);
    let st = |q: DVec3| {
        let h = *m * q.extend(1.0);
        glam::DVec2::new(0.5 * (h.x / h.w + 1.0), 0.5 * (h.y / h.w + 1.0))
    };
    let d = 1e-6 * (1.0 + p.length());
    let du = (st(p + d * u) - st(p - d * u)) / (2.0 * d);
    let dv = (st(p + d * v) - st(p - d * v)) / (2.0 * d);
    let det = (du.x * dv.y - dv.x * du.y).abs();
    let grad_t = du.y.hypot(dv.y);
    let pixel = 2.0 * -p.z * tan;
    (grad_t / det / pixel, 1.0 / grad_t / pixel)
}

/// The largest per-point error (max of m_x, m_z at unit resolutions, [`audit_point`]) over a
/// frame map's focus body, from its eye → light clip matrix alone, for the frame input it was
/// built from (its light and field of view).
pub fn body_max(
    m: &shadow_aliasing::frame::FrameMap,
    inp: &shadow_aliasing::frame::FrameInput<'_>,
) -> f64 {
    let l = inp
        .camera
        .world_to_eye()
        .transform_vector3(inp.light_dir_world)
        .normalize();
    let tan = inp.camera.view().tan_half_fov();
    let mat = m.shadow.matrix();
    m.body()
        .iter()
        .map(|p| {
            let (mx, mz) = audit_point(&mat, l, *p, tan);
            mx.max(mz)
        })
        .fold(0.0, f64::max)
}
