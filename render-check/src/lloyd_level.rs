//! Lloyd 2006's overhead case on the level set-up (docs/rendered.md, "What is measured", 4):
//! where the camera is level, the light straight down and every map's focus body has its frustum
//! slice's footprint, the rendered m_x, m_z of each ground pixel against Eq 7–8 at its depth and
//! the rendered maxima against Eq 9–10 ([`crate::perspective::lloyd2006`], written from the
//! paper).

use crate::perspective::lloyd2006;
use crate::schemes::{Built, Scheme, View};
use glam::DVec3;

/// Lloyd 2006's overhead case, where it applies: the camera level, the light straight down
/// (γ = 90°, light-space z along the view), a scheme whose maps are Lloyd's warps (uniform,
/// PSM, LiSPSM, minimax n′, z-partitions of LiSPSM), and every map's focus body with the footprint of
/// its frustum slice (its depth range `split`, its width z tan θ_x at both ends).
pub(crate) struct Lloyd {
    /// Per map: near, far, n′.
    maps: Vec<(f64, f64, f64)>,
    tan: f64,
    near: f64,
}

pub(crate) fn lloyd_applies(view: &View, built: &Built, scheme: Scheme) -> Option<Lloyd> {
    if !matches!(
        scheme,
        Scheme::Uniform | Scheme::Lispsm | Scheme::Minimax | Scheme::Cascades | Scheme::Psm
    ) || (view.light_eye - DVec3::NEG_Y).length() > 1e-9
    {
        return None;
    }
    let tan = view.frustum.tan_half_fov();
    let tan_x = tan * view.frustum.aspect();
    let mut maps = Vec::new();
    for (k, m) in built.maps.iter().enumerate() {
        let (n, f) = (m.near, m.far);
        let body = built.bodies.get(k)?;
        let full = |z: f64| {
            let wide = body
                .iter()
                .filter(|v| (-v.z - z).abs() <= 1e-9 * z)
                .map(|v| v.x.abs())
                .fold(0.0f64, f64::max);
            (wide - z * tan_x).abs() <= 1e-9 * z * tan_x
        };
        if !(full(n) && full(f)) {
            return None;
        }
        maps.push((n, f, m.reported.n_prime));
    }
    Some(Lloyd {
        maps,
        tan,
        near: view.frustum.near(),
    })
}

impl Lloyd {
    /// The relative difference of a ground pixel's rendered (m_x, m_z) at depth `z` in map `k`
    /// from Eq 7–8.
    #[allow(clippy::too_many_arguments)] // one pixel's values and the sizes
    pub(crate) fn pixel_diff(
        &self,
        k: usize,
        z: f64,
        mx: f64,
        mz: f64,
        width: u32,
        height: u32,
        res: u32,
    ) -> f64 {
        let (n, f, np) = self.maps[k];
        let r = f64::from(res);
        let ex = lloyd2006::m_x(z, n, f, np, f64::from(width), r);
        let ez = lloyd2006::m_z(z, n, f, np, self.tan, f64::from(height), r);
        (mx / ex - 1.0).abs().max((mz / ez - 1.0).abs())
    }

    /// The relative difference of the rendered maxima over the ground from Eq 9–10, for the maps
    /// whose near end is the camera's near plane (where the level set-up shows the ground): M_x
    /// (Eq 9, on the near plane) always, M_z where Eq 10's maximum lies on the near plane too
    /// (n′ ≥ n′_LSPSM, where m_z(n) ≥ m_z(f)). Below n′_LSPSM (PSM's n′ = n) M_z is m_z(f), on
    /// the far plane, where the ground reaches the horizon's rows and no pixel is compared.
    pub(crate) fn maxima_diff(
        &self,
        ground: &[(f64, f64)],
        width: u32,
        height: u32,
        res: u32,
    ) -> f64 {
        let mut d = 0.0f64;
        for (k, &(n, f, np)) in self.maps.iter().enumerate() {
            if (n - self.near).abs() > 1e-12 * n || ground[k].0 == 0.0 {
                continue;
            }
            let sizes = (f64::from(width), f64::from(height));
            let r = f64::from(res);
            let (ex, ez) = lloyd2006::maxima(n, f, np, self.tan, sizes, r);
            d = d.max((ground[k].0 / ex - 1.0).abs());
            let at = |z: f64| lloyd2006::m_z(z, n, f, np, self.tan, sizes.1, r);
            if at(n) >= at(f) * (1.0 - 1e-9) {
                d = d.max((ground[k].1 / ez - 1.0).abs());
            }
        }
        d
    }
}
