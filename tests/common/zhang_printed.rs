//! Zhang, Zhao & Sun's Appendix forms exactly as printed (μ, tan φ_w, F_p, F_q, G, z_w), for the
//! tests that compare them with the crate's twin and for the errata that recompute them
//! (tests/zhang.rs, tests/errata.rs). Angles in radians: φ the half field of view, θ the light's
//! angle, λ the warp parameter; n, f the near and far depths.

pub fn tan_phi_w(n: f64, f: f64, phi: f64, lambda: f64, theta: f64) -> f64 {
    let mu = mu(n, f, phi, theta);
    if theta >= phi {
        f * phi.tan() / (mu + lambda)
    } else {
        f * phi.tan() / lambda
    }
}
pub fn mu(n: f64, f: f64, phi: f64, theta: f64) -> f64 {
    let (tp, tt) = (phi.tan(), theta.tan());
    if theta >= phi {
        (n * tp / tt + f - n + f * tp / tt) * theta.sin()
    } else {
        2.0 * f * tp * theta.cos()
    }
}
pub fn f_p(n: f64, f: f64, phi: f64, lambda: f64, theta: f64) -> f64 {
    let (tp, tt, s) = (phi.tan(), theta.tan(), theta.sin());
    if theta >= phi {
        let k = f - n + (f + n) * tp / tt;
        s * s * k / (tp * lambda * (lambda + k * s))
    } else {
        2.0 * f * s * s / (lambda * (lambda + 2.0 * f * tp * theta.cos()) * tp)
    }
}
pub fn f_q(n: f64, f: f64, phi: f64, lambda: f64, theta: f64) -> f64 {
    let (tp, tt, s) = (phi.tan(), theta.tan(), theta.sin());
    if theta >= phi {
        2.0 * f * s / (lambda + (f - n) * (1.0 - tp / tt) * s)
    } else {
        2.0 * f * s / lambda
    }
}
pub fn g(n: f64, f: f64, phi: f64, lambda: f64, theta: f64, y: f64) -> f64 {
    let (tp, tt, s) = (phi.tan(), theta.tan(), theta.sin());
    let r = if theta >= phi { n } else { f };
    lambda / s - r + (r * tp - y) / tt
}
pub fn z_w(n: f64, f: f64, phi: f64, lambda: f64, theta: f64, y: f64, z: f64) -> f64 {
    let (tp, tt) = (phi.tan(), theta.tan());
    if theta >= phi {
        (z - n + n * tp / tt - y / tt) * theta.sin() + lambda
    } else {
        (f * tp - (f - z) * tt - y) * theta.cos() + lambda
    }
}
