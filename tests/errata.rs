//! docs/errata.md's numbers, recomputed. Every entry with numbers is located by its section and
//! heading (its number, or the start of its bold title), the numbers it quotes are recomputed
//! from the crate's measurement of the built matrices (`measure::frustum_max`, `point_error`,
//! `mz_along_view_axis`, `aliasing_functions`), from the crate's closed forms where the entry
//! quotes them, or from the printed formula typed in as printed, formatted to the digits the
//! entry gives, and the entry's text must contain them. `independent_check_paragraph_counts`
//! checks that the paragraph "Independent check of these entries" states how many entries and
//! numbers this file checks.

mod common;
use common::faces::{faces_with_axis, side_face_with_axis};
use common::{adaptive_limit, close, top_line_crossing_x, tsm_80_percent_sbar, zhang_printed};
use glam::DVec3;
use shadow_aliasing::analytic::global::{zhang_ep, zhang_ep_local, zhang_eq, zhang_eq_local};
use shadow_aliasing::analytic::partition::{
    optimal_storage_factor, shadow_map_count, z_splits, Scheme, SchemeLight, SplitScheme,
};
use shadow_aliasing::analytic::subdivided::{
    allocate_texels, distribution_g, max_error, n_from_xi, subdivided_max_error,
};
use shadow_aliasing::analytic::tilted::{
    gamma_lim, generalized_n_prime, n_prime_1, n_prime_2, n_prime_axis_minimax, tilted_mz, Falloff,
};
use shadow_aliasing::analytic::tsm::tsm_projection;
use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
use shadow_aliasing::maps::minimax::minimax_mz_n_prime;
use shadow_aliasing::maps::{fit_warp, light_space, tsm, warp, TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::measure::tilted_twin::{
    aliasing_functions, mz_along_view_axis, tilted_warp, TiltSide, TiltedWarp,
};
use shadow_aliasing::measure::twin::{
    behind_map, measured_fp_zp_w_behind, overhead_cascade, overhead_map, TwinWarp,
};
use shadow_aliasing::measure::{frustum_max, point_error, FrustumError, PointError, ShadowMap};
use shadow_aliasing::scheme::sweep::light_dir_from_angles;
use shadow_aliasing::{LightAngle, NPrime, Resolutions, ViewFrustum};
use std::cell::Cell;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_6};

const ERRATA: &str = include_str!("../docs/errata.md");

// ---------------------------------------------------------------------------------------------
// Locating entries and formatting numbers.
// ---------------------------------------------------------------------------------------------

/// Collapses every run of whitespace (line breaks and indentation) to one space.
fn normalise(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The text of the section whose heading starts with `## {title}`, up to the next `## `.
fn section(title: &str) -> &'static str {
    let key = format!("\n## {title}");
    assert_eq!(ERRATA.matches(&key).count(), 1, "section {title:?}");
    let start = ERRATA.find(&key).unwrap() + 1;
    let rest = &ERRATA[start..];
    let end = rest[3..].find("\n## ").map_or(rest.len(), |e| e + 3);
    &rest[..end]
}

/// Whether `line` starts a numbered entry (`12. **`).
fn numbered_start(line: &str) -> Option<usize> {
    let digits: String = line.chars().take_while(char::is_ascii_digit).collect();
    if digits.is_empty() || !line[digits.len()..].starts_with(". **") {
        return None;
    }
    digits.parse().ok()
}

/// One entry of a section and the count of numbers checked in it.
struct Entry {
    name: String,
    text: String,
    checked: Cell<usize>,
}

impl Entry {
    /// Entry `i.` of the numbered list of section `title`.
    fn numbered(title: &str, i: usize) -> Entry {
        let sec = section(title);
        let mut out = Vec::new();
        let mut inside = false;
        for line in sec.lines() {
            if let Some(k) = numbered_start(line) {
                inside = k == i;
            } else if line.starts_with("## ") || line.starts_with("- **") {
                inside = false;
            }
            if inside {
                out.push(line);
            }
        }
        assert!(!out.is_empty(), "{title} entry {i} not found");
        Entry {
            name: format!("{title} {i}"),
            text: normalise(&out.join("\n")),
            checked: Cell::new(0),
        }
    }

    /// The bulleted entry of section `title` whose bold title starts with `head`.
    fn bullet(title: &str, head: &str) -> Entry {
        let sec = section(title);
        let key = format!("- **{head}");
        let starts: Vec<_> = sec.lines().filter(|l| l.starts_with(&key)).collect();
        assert_eq!(starts.len(), 1, "{title}: entry {head:?}");
        let mut out = Vec::new();
        let mut inside = false;
        for line in sec.lines() {
            if line.starts_with("- **") || line.starts_with("## ") {
                inside = line.starts_with(&key);
            }
            if inside {
                out.push(line);
            }
        }
        Entry {
            name: format!("{title}: {head}"),
            text: normalise(&out.join("\n")),
            checked: Cell::new(0),
        }
    }

    /// Asserts that the entry contains `s` (recomputed, formatted numbers in their context) and
    /// counts the numbers formatted for it.
    fn has(&self, s: impl AsRef<str>) {
        let s = normalise(s.as_ref());
        let n = FORMATTED.with(|c| c.replace(0));
        assert!(n > 0, "{}: {s:?} has no recomputed number", self.name);
        assert!(
            self.text.contains(&s),
            "{}: expected {:?} in\n{}",
            self.name,
            s,
            self.text
        );
        self.checked.set(self.checked.get() + n);
    }

    fn done(self) -> usize {
        assert!(self.checked.get() > 0, "{}: nothing checked", self.name);
        CHECKED.with(|c| c.borrow_mut().insert(self.name.clone()));
        self.checked.get()
    }
}

thread_local! {
    /// Recomputed values formatted since the last [`Entry::has`].
    static FORMATTED: Cell<usize> = const { Cell::new(0) };
    /// The entries checked on this thread (an entry may be checked by more than one function).
    static CHECKED: std::cell::RefCell<std::collections::BTreeSet<String>> =
        const { std::cell::RefCell::new(std::collections::BTreeSet::new()) };
}

fn formatted() {
    FORMATTED.with(|c| c.set(c.get() + 1));
}

/// `x` with `p` decimals, the minus sign as docs/errata.md writes it (U+2212).
fn d(x: f64, p: usize) -> String {
    formatted();
    let s = format!("{x:.p$}");
    match s.strip_prefix('-') {
        Some(r) => format!("−{r}"),
        None => s,
    }
}

/// `x` with `p` decimals and the integer part grouped by threes with spaces ("866 024.5").
fn grouped(x: f64, p: usize) -> String {
    formatted();
    let s = format!("{:.p$}", x.abs());
    let (int, frac) = s
        .split_once('.')
        .map_or((s.as_str(), None), |(a, b)| (a, Some(b)));
    let mut g = String::new();
    for (i, c) in int.chars().enumerate() {
        if i > 0 && (int.len() - i) % 3 == 0 {
            g.push(' ');
        }
        g.push(c);
    }
    if let Some(f) = frac {
        g.push('.');
        g.push_str(f);
    }
    if x < 0.0 {
        format!("−{g}")
    } else {
        g
    }
}

fn superscript(k: i32) -> String {
    let digits = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::new();
    if k < 0 {
        s.push('⁻');
    }
    for c in k.unsigned_abs().to_string().chars() {
        s.push(digits[c.to_digit(10).unwrap() as usize]);
    }
    s
}

/// `x` written as a power of ten ("10⁴"); `x` must be one to a relative 1e-9.
fn pow10(x: f64) -> String {
    formatted();
    let k = x.log10().round() as i32;
    assert!(
        (x / 10f64.powi(k) - 1.0).abs() < 1e-9,
        "{x} is not a power of ten"
    );
    format!("10{}", superscript(k))
}

/// `x` as `m·10ᵏ` with `p` decimals in m ("1.1·10⁻⁷").
fn sci(x: f64, p: usize) -> String {
    let k = x.abs().log10().floor() as i32;
    // d() counts the value.
    format!("{}·10{}", d(x / 10f64.powi(k), p), superscript(k))
}

/// Measured error at (x, y, −z) with unit resolutions.
fn at(view: &ViewFrustum, map: &ShadowMap, x: f64, y: f64, z: f64) -> PointError {
    point_error(view, map, DVec3::new(x, y, -z), Resolutions::default()).unwrap()
}

/// The overhead warp (light travelling −y) measured over the frustum.
fn overhead(view: &ViewFrustum, np: NPrime) -> FrustumError {
    frustum_max(view, &overhead_map(view, np).unwrap()).unwrap()
}

/// The map fitted with an explicit n′ on the view-axis light space, measured.
fn fitted(view: &ViewFrustum, l: DVec3, np: NPrime) -> FrustumError {
    let ls = light_space(l, DVec3::NEG_Z).unwrap();
    let m = fit_warp(&view.corners(), &ls, np).unwrap();
    frustum_max(view, &ShadowMap::new(m, l).unwrap()).unwrap()
}

fn tilted(view: &ViewFrustum, gamma: f64, side: TiltSide, np: NPrime) -> TiltedWarp {
    tilted_warp(view, LightAngle::new(gamma).unwrap(), side, np).unwrap()
}

/// Barroso's along-axis m_z at depth z (the twin).
fn along(view: &ViewFrustum, w: &TiltedWarp, z: f64) -> f64 {
    mz_along_view_axis(
        view,
        &w.shadow,
        DVec3::new(0.0, 0.0, -z),
        Resolutions::default(),
    )
    .unwrap()
}

fn view(n: f64, f: f64, half_fov: f64) -> ViewFrustum {
    ViewFrustum::new(n, f, half_fov).unwrap()
}

const L05: &str = "Lloyd et al. 2005";
const L06: &str = "Lloyd et al. 2006";
const MT: &str = "Martin & Tan 2004";
const BC: &str = "Barroso & Celes 2007";
const ZH: &str = "Zhang, Zhao & Sun 2009";

// ---------------------------------------------------------------------------------------------
// The checks, one per entry; each returns how many numbers it checked.
// ---------------------------------------------------------------------------------------------

mod checks {
    use super::*;

    // ----- Lloyd 2005 (near = 1, far = α) -----

    pub fn l05_1() -> usize {
        let e = Entry::numbered(L05, 1);
        let (n, f) = (1.0f64, 2.0f64);
        let printed = |z: f64| 0.5 + (f + n) / (2.0 * (f - n)) + f * n / (z * (f - n));
        let right = |z: f64| 0.5 + (f + n) / (2.0 * (f - n)) - f * n / (z * (f - n));
        e.has(format!(
            "planes to {} and {} (n = 1, f = 2) instead of {} and {}",
            d(printed(n), 0),
            d(printed(f), 0),
            d(right(n), 0),
            d(right(f), 0)
        ));
        e.done()
    }

    pub fn l05_2() -> usize {
        let e = Entry::numbered(L05, 2);
        let v = view(1.0, 100.0, 0.5);
        let map = overhead_map(&v, NPrime::finite(1.0).unwrap()).unwrap();
        let w = |z: f64| at(&v, &map, 0.0, 0.0, z).w_lt;
        e.has(format!(
            "w_lz(α)/w_lz(1) = {} (not {})",
            pow10(w(100.0) / w(1.0)),
            pow10(w(1.0) / w(100.0))
        ));
        e.has(format!("w_lz(10)/w_lz(1) = {}", d(w(10.0) / w(1.0), 0)));
        e.done()
    }

    pub fn l05_3() -> usize {
        let e = Entry::numbered(L05, 3);
        let th = FRAC_PI_4;
        let limit = subdivided_max_error(100.0, 1 << 24, 0.0, th, 1.0, 1.0).unwrap();
        assert!(close(limit, 100f64.ln() / (2.0 * th.tan()), 1e-9));
        e.has(format!("ln α / (2 tan θ) = {}", d(limit, 4)));
        // dz/ds = z for s = ln z: m = z/(2 z tan θ).
        e.has(format!("would claim {}", d(1.0 / (2.0 * th.tan()), 1)));
        e.done()
    }

    pub fn l05_5() -> usize {
        let e = Entry::numbered(L05, 5);
        let a = 100.0;
        let n = n_from_xi(a, -0.5).unwrap();
        let th = FRAC_PI_4;
        let v = view(1.0, a, th);
        let map = overhead_map(&v, n).unwrap();
        let scale = (a - 1.0) / (2.0 * th.tan());
        let (g1, ga) = (
            at(&v, &map, 0.0, 0.0, 1.0).mz / scale,
            at(&v, &map, 0.0, 0.0, a).mz / scale,
        );
        assert!(close(g1, distribution_g(a, n, 1.0).unwrap(), 1e-9));
        e.has(format!("(n = {})", d(n.value(), 0)));
        e.has(format!("g(1) = {}, g(α) = {}", d(g1, 2), d(ga, 4)));
        e.has(format!(
            "Eq 5 (which is right) gives {}",
            d(max_error(a, th, -0.5, 1.0, 1.0).unwrap() / scale, 2)
        ));
        e.done()
    }

    pub fn l05_6() -> usize {
        let e = Entry::numbered(L05, 6);
        let a = 100.0;
        let v = view(1.0, a, 0.5);
        let mx = |xi: f64| overhead(&v, n_from_xi(a, xi).unwrap()).max_mx;
        e.has(format!(
            "M_x = {} at ξ = +1 and {} at ξ = −1",
            d(mx(1.0), 0),
            d(mx(-1.0), 0)
        ));
        e.done()
    }

    pub fn l05_9() -> usize {
        let e = Entry::numbered(L05, 9);
        let a = 100.0;
        let (l, r) = (
            n_from_xi(a, -1e-9).unwrap().value(),
            n_from_xi(a, 1e-9).unwrap().value(),
        );
        let n0 = n_from_xi(a, 0.0).unwrap().value();
        e.has(format!("(−{}", d((l - r) / 2e-9, 0)));
        e.has(format!(
            "n(∓10⁻⁹) = {} ± {}",
            d(n0, 0),
            sci((l - r) / 2.0, 1)
        ));
        let th = FRAC_PI_4;
        let v = view(1.0, a, th);
        let m = overhead_map(&v, NPrime::finite(n0).unwrap()).unwrap();
        let (near, far) = (at(&v, &m, 0.0, 0.0, 1.0).mz, at(&v, &m, 0.0, 0.0, a).mz);
        assert!(close(near, far, 1e-9));
        assert!(close(near, max_error(a, th, 0.0, 1.0, 1.0).unwrap(), 1e-9));
        e.has(format!("m_max(0) = {} at", d(near, 2)));
        e.done()
    }

    pub fn l05_10() -> usize {
        let e = Entry::numbered(L05, 10);
        let th = FRAC_PI_4;
        // The measured maxima of the two subdivisions with all r_s texels (Eq 5 per subdivision).
        let m0 = overhead(&view(1.0, 100.0, th), n_from_xi(100.0, 0.0).unwrap()).max_mz;
        let m1 = overhead(&view(1.0, 50.0, th), n_from_xi(50.0, 1.0).unwrap()).max_mz;
        let mut out = [0.0; 2];
        allocate_texels(&[m0, m1], 1.0, &mut out).unwrap();
        assert!(close(out[1], m1 / (m0 + m1), 1e-12));
        e.has(format!(
            "{}/{} = {} % of the texels",
            d(m1, 1),
            d(m0 + m1, 2),
            d(100.0 * out[1], 0)
        ));
        e.done()
    }

    pub fn l05_11() -> usize {
        let e = Entry::numbered(L05, 11);
        let v = view(1.0, 1000.0, FRAC_PI_4);
        for l in [DVec3::NEG_Z, DVec3::Z] {
            let s = face_partitions(&v, l, FaceWarp::Lispsm, 1)
                .unwrap()
                .storage_factor();
            e.has(format!("Σ S̄ = {} from behind", d(s, 0)));
        }
        let far = frustum_max(&v, &behind_map(&v).unwrap())
            .unwrap()
            .storage_factor;
        e.has(format!("the far face {} = (f/n)²", pow10(far)));
        e.done()
    }

    // ----- Lloyd 2006 -----

    pub fn l06_1() -> usize {
        let e = Entry::numbered(L06, 1);
        let (n, f, th) = (2.0, 100.0, 30f64.to_radians());
        let v = view(n, f, th);
        let m = overhead(&v, NPrime::finite(v.n_prime_lispsm()).unwrap());
        // The transcribed width (2 tan θ/res_i)(z/n) is n times smaller at every z.
        let w_right = 2.0 * n * th.tan();
        let w_printed = 2.0 * th.tan() * n / n;
        e.has(format!(
            "m_x(n) = {}; the transcribed width gives {}",
            d(m.max_mx, 3),
            d(m.max_mx * w_right / w_printed, 3)
        ));
        e.done()
    }

    pub fn l06_2() -> usize {
        let e = Entry::numbered(L06, 2);
        let (n, f, np, th) = (1.0f64, 100.0f64, 11.0f64, FRAC_PI_4);
        let fp = np + f - n;
        let tan_printed = fp / f * th.tan();
        let s_far = f * th.tan() / (fp * tan_printed) + 0.5;
        e.has(format!("s = {} (outside [0, 1])", d(s_far, 3)));
        let s_near = |x: f64| x / (np * tan_printed) + 0.5;
        let h = 1e-6;
        let mx_printed = 2.0 * h / (s_near(h) - s_near(-h)) / (2.0 * n * th.tan());
        e.has(format!("m_x(n) = n′ f′/(2 n f) = {}", d(mx_printed, 2)));
        let m = overhead(&view(n, f, th), NPrime::finite(np).unwrap());
        e.has(format!("f n′/(n f′) = {}", d(m.max_mx, 0)));
        e.done()
    }

    pub fn l06_3() -> usize {
        let e = Entry::numbered(L06, 3);
        let (n, f, np) = (1.0f64, 100.0f64, 11.0f64);
        let fp = np + f - n;
        let printed = |zp: f64| (fp + np) / (2.0 * (fp - np)) + fp * np / (zp * (fp - np)) + 0.5;
        let right = |zp: f64| (fp + np) / (2.0 * (fp - np)) - fp * np / (zp * (fp - np)) + 0.5;
        e.has(format!(
            "printed t is {}/9 on the near plane and {}/9 on the far plane",
            d(9.0 * printed(np), 0),
            d(9.0 * printed(fp), 0)
        ));
        e.has(format!(
            "the right one is {} and {}",
            d(right(np).abs(), 0),
            d(right(fp), 0)
        ));
        e.done()
    }

    pub fn l06_4() -> usize {
        let e = Entry::numbered(L06, 4);
        let (n, f) = (2.0, 100.0);
        let v = view(n, f, 30f64.to_radians());
        let np = v.n_prime_lispsm();
        let m = overhead(&v, NPrime::finite(np).unwrap());
        let mx_printed = f * np / (np + f - n);
        let mz_printed = n * (f - n) / (2.0 * v.tan_half_fov()) * (np + f - n) / (np * f);
        e.has(format!(
            "transcribed M_x = {}, M_z = {}",
            d(mx_printed, 3),
            d(mz_printed, 3)
        ));
        e.has(format!(
            "measured {} and {}",
            d(m.max_mx, 3),
            d(m.max_mz, 3)
        ));
        e.done()
    }

    pub fn l06_5() -> usize {
        let e = Entry::numbered(L06, 5);
        let v = view(1.0, 100.0, FRAC_PI_4);
        let m = overhead(&v, NPrime::finite(11.0).unwrap());
        let s0 = 2048.0f64 * 2048.0;
        // Eq 13, 14 with res*_s/res*_t = M_x/M_z (measured, unit resolutions).
        let (rs, rt) = (
            (s0 * m.max_mx / m.max_mz).sqrt(),
            (s0 * m.max_mz / m.max_mx).sqrt(),
        );
        e.has(format!("res_s = {}, res_t = {}", d(rs, 1), d(rt, 1)));
        let (mx, mz) = (m.max_mx * 1024.0 / rs, m.max_mz * 1024.0 / rt);
        assert!(close(mx, mz, 1e-12));
        assert!(close(mx, 1024.0 * (m.storage_factor / s0).sqrt(), 1e-12));
        e.has(format!("M_x = M_z = res_i √(S̄/S₀) = {}", d(mx, 4)));
        e.done()
    }

    pub fn l06_7() -> usize {
        let e = Entry::numbered(L06, 7);
        let th = 30f64.to_radians();
        let own = 4.0 * 999.0 / (2.0 * th.tan()) + 1.0;
        e.has(format!("the own-θ reading gives {}", d(own, 2)));
        let sp = z_splits(1.0, 1000.0, 1, SplitScheme::SelfSimilar).unwrap();
        let mut all = Vec::new();
        for deg in [10.0f64, 30.0, 45.0, 70.0] {
            let v = view(1.0, 1000.0, deg.to_radians());
            all.push(measured_fp_zp_w_behind(&v, &sp, TwinWarp::Lispsm).unwrap());
        }
        assert!(all.iter().all(|&m| close(m, all[0], 1e-9)));
        e.has(format!(
            "give {} at θ = 10°, 30°, 45° and 70°",
            d(all[0], 0)
        ));
        e.done()
    }

    pub fn l06_8() -> usize {
        let e = Entry::numbered(L06, 8);
        let th = 30f64.to_radians();
        let v = view(1.0, 1e6, th);
        let j = 8usize;
        let zp = overhead_cascade(
            &v,
            &z_splits(1.0, 1e6, j, SplitScheme::SelfSimilar).unwrap(),
            TwinWarp::Unwarped,
        )
        .unwrap()
        .measured_storage_factor()
        .unwrap();
        let fp = overhead_cascade(
            &v,
            &z_splits(1.0, 1e6, j / 4, SplitScheme::SelfSimilar).unwrap(),
            TwinWarp::Lispsm,
        )
        .unwrap()
        .measured_storage_factor()
        .unwrap();
        let jf = j as f64;
        e.has(format!(
            "Eq 17 gives {} (printed {})",
            d(zp, 2),
            d(jf * 1e6f64.powf(2.0 / jf), 2)
        ));
        e.has(format!(
            "Eq 18 with k = 2 gives {} (printed {})",
            d(fp, 1),
            d(jf * 1e6f64.powf(4.0 / jf), 0)
        ));
        e.done()
    }

    pub fn l06_9() -> usize {
        let e = Entry::numbered(L06, 9);
        let v = view(1.0, 1000.0, 0.5);
        let r = Resolutions::new(1024.0, 1024.0, 1024.0).unwrap();
        let map = overhead_map(&v, NPrime::finite(1.0).unwrap()).unwrap();
        let mx = point_error(&v, &map, DVec3::new(0.0, 0.0, -30.0), r)
            .unwrap()
            .mx;
        e.has(format!(
            "measured m_x is res_i/res_s = {} at res_i = res_s = {} (printed: 1/{})",
            d(mx, 0),
            r.image(),
            r.s()
        ));
        e.done()
    }

    pub fn l06_11() -> usize {
        let e = Entry::numbered(L06, 11);
        // The 1/sin γ rule with explicit n′ = (n + √(f n))/sin γ against the unwarped map.
        let ratio = |v: &ViewFrustum, l: DVec3| {
            let sin = LightAngle::from_light_dir(l).unwrap().radians().sin();
            let np = NPrime::finite(v.n_prime_lispsm() / sin).unwrap();
            fitted(v, l, np).storage_factor / fitted(v, l, NPrime::UNWARPED).storage_factor
        };
        let v = view(1.0, 100.0, 30f64.to_radians());
        let r1 = ratio(&v, light_dir_from_angles(0.0, 350f64.to_radians()));
        e.has(format!("S̄ = {} × the uniform map's", d(r1, 3)));
        let v = view(1.0, 1000.0, 30f64.to_radians());
        let r2 = ratio(&v, light_dir_from_angles(12f64.to_radians(), 0.0));
        e.has(format!("behind, {} ×", d(r2, 2)));
        e.done()
    }

    pub fn l06_12() -> usize {
        let e = Entry::numbered(L06, 12);
        let v = view(1.0, 1000.0, FRAC_PI_4);
        let far = frustum_max(&v, &behind_map(&v).unwrap())
            .unwrap()
            .storage_factor;
        let ours = face_partitions(&v, DVec3::NEG_Z, FaceWarp::Lispsm, 1)
            .unwrap()
            .storage_factor();
        e.has(format!(
            "Σ S̄ = (f/n)² = {} instead of Eq 21's {}",
            pow10(far),
            d(ours, 0)
        ));
        e.done()
    }

    pub fn l06_13() -> usize {
        let e = Entry::numbered(L06, 13);
        let v = view(1.0, 100.0, 30f64.to_radians());
        let l = light_dir_from_angles(15f64.to_radians(), 165f64.to_radians());
        let unit = faces_with_axis(&v, l, true).unwrap();
        let built = face_partitions(&v, l, FaceWarp::Lispsm, 1)
            .unwrap()
            .storage_factor();
        e.has(format!("ê′₀ + ê′₁ gives {}", d(unit, 2)));
        e.has(format!("which gives {} here", d(built, 2)));
        e.done()
    }

    pub fn l06_14() -> usize {
        let e = Entry::numbered(L06, 14);
        let (n, f, th) = (1.0f64, 1000.0f64, 30f64.to_radians());
        let t = th.tan();
        let (dn, df) = (n * t, f * t);
        let nv = n + (f * n).sqrt();
        // Eq 12 for a side face (overhead, half field of view 45°, near d_n, far d_f).
        let own = (df / dn - 1.0) / 2.0;
        let with_view = own * nv * nv * df / (dn * (nv + df - dn).powi(2));
        let ours = face_partitions(&view(n, f, th), DVec3::NEG_Z, FaceWarp::Lispsm, 1)
            .unwrap()
            .storage_factor();
        e.has(format!(
            "each side face costs {} instead of {}, Σ S̄ = {} instead of {}",
            d(with_view, 1),
            d(own, 1),
            d(4.0 * with_view + 1.0, 0),
            d(ours, 0)
        ));
        e.done()
    }

    pub fn l06_15() -> usize {
        let e = Entry::numbered(L06, 15);
        let v = view(1.0, 100.0, FRAC_PI_4);
        let map = overhead_map(&v, NPrime::finite(11.0).unwrap()).unwrap();
        let mz = |z: f64| at(&v, &map, 0.0, 0.0, z).mz;
        e.has(format!(
            "m_z = {}, {}, {} at z = 1, 10, 100",
            d(mz(1.0), 2),
            d(mz(10.0), 3),
            d(mz(100.0), 2)
        ));
        e.done()
    }

    pub fn l06_16() -> usize {
        let e = Entry::numbered(L06, 16);
        let v = view(1.0, 100.0, 30f64.to_radians());
        e.has(format!(
            "S̄ is {} for n′ = ∞ and {} for n′_LSPSM = 11",
            d(overhead(&v, NPrime::UNWARPED).storage_factor, 2),
            d(
                overhead(&v, NPrime::finite(11.0).unwrap()).storage_factor,
                3
            )
        ));
        e.done()
    }

    pub fn l06_18() -> usize {
        let e = Entry::numbered(L06, 18);
        let v = view(1.0, 100.0, 30f64.to_radians());
        let nps = [1.0, 6.0, 1.0 + 100f64.sqrt()];
        let up: Vec<f64> = nps
            .iter()
            .map(|&np| fitted(&v, DVec3::NEG_Y, NPrime::finite(np).unwrap()).storage_factor)
            .collect();
        assert!(up.iter().all(|&s| close(s, up[0], 1e-9)));
        e.has(format!(
            "n′ = {}, LiSPSM's n′ = n + √(f n) = {}",
            d(nps[1], 0),
            d(nps[2], 0)
        ));
        e.has(format!("Eq 12's {}", d(up[0], 3)));
        let l = light_dir_from_angles(45f64.to_radians(), 0.0);
        let s: Vec<f64> = nps
            .iter()
            .map(|&np| fitted(&v, l, NPrime::finite(np).unwrap()).storage_factor)
            .collect();
        e.has(format!(
            "S̄ = {}, {} and {}, PSM's {} times LiSPSM's",
            d(s[0], 2),
            d(s[1], 2),
            d(s[2], 2),
            d(s[0] / s[2], 2)
        ));
        e.done()
    }

    pub fn l06_19() -> usize {
        let e = Entry::numbered(L06, 19);
        let th = 30f64.to_radians();
        let v = view(1.0, 1e6, th);
        let meas = |k: usize| {
            overhead_cascade(
                &v,
                &z_splits(1.0, 1e6, k, SplitScheme::SelfSimilar).unwrap(),
                TwinWarp::Lispsm,
            )
            .unwrap()
            .measured_storage_factor()
            .unwrap()
        };
        let eq23 = |j: f64| j * 1e6f64.powf(4.0 / j) / (8.0 * th.tan());
        e.has(format!(
            "Eq 18 gives {} (k = 1) and {} (k = 2)",
            grouped(meas(1), 1),
            d(meas(2), 2)
        ));
        e.has(format!(
            "{} (j = 4) and {} (j = 8)",
            grouped(eq23(4.0), 1),
            d(eq23(8.0), 2)
        ));
        let nine = shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, 2).unwrap();
        e.has(format!("j = 6 gives {}", grouped(eq23(6.0), 1)));
        e.has(format!(
            "j = {nine}, the map count of k = 2, {}",
            d(eq23(nine as f64), 2)
        ));
        e.done()
    }

    pub fn l06_20() -> usize {
        let e = Entry::numbered(L06, 20);
        let (n, f, th, z) = (2.0f64, 200.0f64, 30f64.to_radians(), 20.0f64);
        let t = |z: f64| (z / n).ln() / (f / n).ln();
        let h = 1e-5 * z;
        let dz_dt = 2.0 * h / (t(z + h) - t(z - h));
        let mz = dz_dt / (2.0 * z * th.tan());
        assert!(close(
            mz,
            optimal_storage_factor(&view(n, f, th)).unwrap(),
            1e-8
        ));
        e.has(format!(
            "dz/dt = {} = z ln(f/n) and m_z = {}",
            d(dz_dt, 3),
            d(mz, 3)
        ));
        e.has(format!(
            "z/log(f/n) the line gives dz/dt = {}, and with a trailing /n (Eq 2's stray factor) {}",
            d(z / (f / n).ln(), 3),
            d(z * (f / n).ln() / n, 2)
        ));
        e.done()
    }

    /// #13's 30 × 72 grid (elevation 3i°, azimuth 5j°; f/n = 100, θ = 30°): every direction in
    /// exactly one category, the counts summing to the grid.
    pub fn l06_13_grid() -> usize {
        let e = Entry::numbered(L06, 13);
        let v = view(1.0, 100.0, 30f64.to_radians());
        let (mut fails, mut worse, mut ties, mut better) = (0usize, 0usize, 0usize, 0usize);
        let mut rounding = Vec::new();
        for i in 0..30 {
            for j in 0..72 {
                let (el, az) = (3.0 * f64::from(i), 5.0 * f64::from(j));
                let l = light_dir_from_angles(el.to_radians(), az.to_radians());
                let unit = faces_with_axis(&v, l, true).unwrap_or_else(|| panic!("({el}, {az})"));
                let Some(raw) = faces_with_axis(&v, l, false) else {
                    fails += 1;
                    continue;
                };
                if raw > unit * (1.0 + 1e-9) {
                    worse += 1;
                } else if raw > unit {
                    rounding.push((el, az, raw / unit - 1.0));
                } else if raw == unit {
                    ties += 1;
                } else {
                    better += 1;
                }
            }
        }
        assert_eq!(fails + worse + rounding.len() + ties + better, 30 * 72);
        let [(el, az, rel)] = rounding[..] else {
            panic!("{rounding:?}")
        };
        for _ in 0..6 {
            formatted();
        }
        e.has(format!(
            "the sum fails at {fails} directions and, of the other {}, is worse by more than \
             10⁻⁹ at {worse}, worse by a rounding difference (relative {}, at elevation {}°, \
             azimuth {}°) at {}, equal at {ties} and better at {better})",
            30 * 72 - fails,
            sci(rel, 1),
            d(el, 0),
            d(az, 0),
            rounding.len()
        ));
        e.done()
    }

    /// #17: Lloyd's unit-vector bisector alone (k = 1, f/n = 1000, θ = 30°) at azimuth 150° and
    /// elevation arctan ½ − δ, just below the frustum's +x+y side edge. Without the edge-on
    /// cut-off (the skipped face's map added back) Σ S̄ grows as δ^(−1/2); with it (the crate's
    /// `visible_faces`) it drops to its value on the edge once the face is skipped.
    pub fn l06_17_edge() -> usize {
        use shadow_aliasing::maps::faces::visible_faces;
        let e = Entry::numbered(L06, 17);
        let v = view(1.0, 1000.0, 30f64.to_radians());
        let at =
            |deg: f64| light_dir_from_angles(0.5f64.atan() - deg.to_radians(), 150f64.to_radians());
        let faces = |deg: f64| visible_faces(&v, at(deg)).unwrap().faces().to_vec();
        // The faces seen just below the edge, before any is skipped.
        let seen = faces(1e-3);
        let uncut = |deg: f64| {
            let kept = faces(deg);
            let skipped: f64 = seen
                .iter()
                .filter(|f| !kept.contains(f))
                .map(|&f| side_face_with_axis(&v, at(deg), f, true).unwrap())
                .sum();
            faces_with_axis(&v, at(deg), true).unwrap() + skipped
        };
        let s: Vec<f64> = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8].map(uncut).to_vec();
        // Unbounded: √10 per decade of δ towards the edge.
        for w in s[2..].windows(2) {
            let r = w[1] / w[0];
            assert!((r - 10f64.sqrt()).abs() < 0.1, "{s:?}");
        }
        // The ratios per decade rise towards √10 = 3.162 (δ^(−1/2) is only the limit): the
        // page quotes the first three, each below √10.
        let ratios: Vec<f64> = s.windows(2).map(|w| w[1] / w[0]).collect();
        assert!(ratios[..3].windows(2).all(|w| w[0] < w[1]), "{ratios:?}");
        assert!(ratios.iter().all(|r| *r < 10f64.sqrt()), "{ratios:?}");
        e.has(format!(
            "it is {} at δ = 10⁻⁴°, {} at 10⁻⁵°, {} at 10⁻⁶°, {} at 10⁻⁷° (ratios {}, {} and {} per \
             decade, rising towards √10 = 3.16, the limit of δ^(−1/2))",
            d(s[0], 0),
            d(s[1], 0),
            d(s[2], 0),
            d(s[3], 0),
            d(ratios[0], 2),
            d(ratios[1], 2),
            d(ratios[2], 2)
        ));
        // Where EDGE_ON skips the face: the largest δ at which one of `seen` is gone.
        let (mut lo, mut hi) = (1e-8f64, 1e-3f64);
        for _ in 0..200 {
            let m = (lo * hi).sqrt();
            if faces(m).len() < seen.len() {
                lo = m;
            } else {
                hi = m;
            }
        }
        let cut = faces_with_axis(&v, at(hi), true).unwrap();
        let on_edge = faces_with_axis(&v, at(0.0), true).unwrap();
        // Below the cut-off the crate's Σ S̄ is the on-edge value.
        assert!((faces_with_axis(&v, at(lo), true).unwrap() - on_edge).abs() < 1e-3 * on_edge);
        e.has(format!(
            "skips that face from δ = {}° on, where Σ S̄ = {},",
            sci(lo, 3),
            d(cut, 0)
        ));
        e.done()
    }

    pub fn l06_13_sum() -> usize {
        let e = Entry::numbered(L06, 13);
        let v = view(1.0, 100.0, 30f64.to_radians());
        let l = light_dir_from_angles(15f64.to_radians(), 165f64.to_radians());
        let raw = faces_with_axis(&v, l, false).unwrap();
        let unit = faces_with_axis(&v, l, true).unwrap();
        let built = face_partitions(&v, l, FaceWarp::Lispsm, 1)
            .unwrap()
            .storage_factor();
        // The crate's per-part choice is never above the unit-vector bisector alone.
        assert!(built <= unit * (1.0 + 1e-12));
        e.has(format!("the sum gives Σ S̄ = {} over", d(raw, 1)));
        e.done()
    }

    /// How many of the 46 × 72 hemisphere directions (elevation 0° to 90° in 2° steps, azimuth
    /// 0° to 355° in 5° steps) give `rule`'s map a larger measured S̄ than the uniform map.
    fn worse_than_uniform(
        view: &ViewFrustum,
        rule: impl Fn(DVec3) -> FrustumError,
    ) -> (usize, usize) {
        let mut worse = 0;
        let mut all = 0;
        for ie in 0..=45 {
            for ia in 0..72 {
                let l = light_dir_from_angles(
                    (ie as f64 * 2.0).to_radians(),
                    (ia as f64 * 5.0).to_radians(),
                );
                let su = fitted(view, l, NPrime::UNWARPED).storage_factor;
                if rule(l).storage_factor > su * (1.0 + 1e-12) {
                    worse += 1;
                }
                all += 1;
            }
        }
        (worse, all)
    }

    /// Checks entry `e`'s "({a} and {b} of {all} {directions})": `a` and `b` are
    /// [`worse_than_uniform`]'s counts at f/n = 100 and 1000 (n = 1, θ = 30°) for the map `rule`
    /// builds for a view, `all` the number of directions.
    fn has_worse_counts<R: Fn(DVec3) -> FrustumError>(
        e: Entry,
        directions: &str,
        rule: impl Fn(ViewFrustum) -> R,
    ) -> usize {
        let v1 = view(1.0, 100.0, 30f64.to_radians());
        let v2 = view(1.0, 1000.0, 30f64.to_radians());
        let (a, all) = worse_than_uniform(&v1, rule(v1));
        let (b, _) = worse_than_uniform(&v2, rule(v2));
        formatted();
        formatted();
        formatted();
        e.has(format!("({a} and {b} of {all} {directions})"));
        e.done()
    }

    pub fn l06_11_counts() -> usize {
        let e = Entry::numbered(L06, 11);
        let sin_rule = |v: ViewFrustum| {
            move |l: DVec3| {
                let sin = LightAngle::from_light_dir(l).unwrap().radians().sin();
                let np = if sin > 0.0 {
                    NPrime::finite(v.n_prime_lispsm() / sin).unwrap()
                } else {
                    NPrime::UNWARPED
                };
                fitted(&v, l, np)
            }
        };
        has_worse_counts(e, "grid directions", sin_rule)
    }

    // ----- Martin & Tan 2004 -----

    pub fn mt_domain() -> usize {
        let e = Entry::bullet(MT, "§6.2, domain of η");
        let (lambda, delta, xi) = (1.0, 0.85, -0.6);
        let printed = (lambda * delta + lambda * delta * xi) / (lambda - 2.0 * delta - lambda * xi);
        e.has(format!("printed η = {}", d(printed, 1)));
        e.done()
    }

    pub fn mt_vector() -> usize {
        let e = Entry::bullet(MT, "§6.2, the result vector");
        let (lambda, delta, eta) = (10.0, 3.0, 1.2);
        let m = tsm_projection(lambda, eta).unwrap();
        let x = delta + eta;
        let (xt, w) = (m[0][0] * x + m[0][1], m[1][0] * x + m[1][1]);
        e.has(format!(
            "the product is ({}, {}), and ξ = {}/{} = {}",
            d(xt, 2),
            d(w, 1),
            d(xt, 2),
            d(w, 1),
            d(xt / w, 1)
        ));
        e.done()
    }

    pub fn mt_top_line() -> usize {
        let e = Entry::bullet(MT, "§6.1, \"l_t transits smoothly");
        let v = view(1.0, 100.0, FRAC_PI_6);
        let (a, b) = (
            top_line_crossing_x(&v, 1e-3),
            top_line_crossing_x(&v, -1e-3),
        );
        e.has(format!("at x = +{}", d(a, 3)));
        e.has(format!("at x = {}", d(b, 3)));
        e.has(format!(
            "a jump of {} (nearly the far plane's width 2 f tan φ = {})",
            d(a - b, 2),
            d(200.0 * FRAC_PI_6.tan(), 2)
        ));
        e.done()
    }

    pub fn mt_square_fallback() -> usize {
        let e = Entry::bullet(MT, "§5, §6.1, §6.3, continuity");
        let v = view(1.0, 100.0, 30f64.to_radians());
        let sbar = |deg: f64| tsm_80_percent_sbar(&v, deg);
        let (off, boxed) = (sbar(0.1), sbar(0.05));
        e.has(format!(
            "the 80 % trapezoid has S̄ = {}, {} × the box's {}",
            grouped(off, 0),
            d(off / boxed, 2),
            grouped(boxed, 0)
        ));
        e.done()
    }

    pub fn mt_iterative() -> usize {
        let e = Entry::bullet(MT, "§6.2, the iterative variant's search");
        let near = 0.05;
        let v = ViewFrustum::with_aspect(
            near,
            near * 0.951378688432118f64.exp(),
            15.748389140270007f64.to_radians(),
            0.7934535693252515,
        )
        .unwrap();
        // On the horizon, 19° off behind (tests/tsm.rs's direction).
        let az = 5.9539707937975015f64;
        let l = DVec3::new(az.sin(), 0.0, -az.cos());
        let focus = 0.6613704857689824 * (v.far() - v.near());
        let area = |k: u32| {
            tsm(
                &v,
                l,
                TsmOptions {
                    focus,
                    search: TsmSearch::Line(1.0 - 2.0 * f64::from(k) / 32.0),
                },
            )
            .unwrap()
            .focus_area
        };
        let boxed: Vec<f64> = (1..=13).map(area).collect();
        assert!(boxed.iter().all(|&a| close(a, boxed[0], 1e-9)));
        // The 80 % line of 32: ξ = −0.6 rounds to line 26 (ξ = −0.625).
        e.has(format!(
            "it falls from {} (lines 1–13, the box) to {} (line 20) and rises to {} at the 80 % line",
            d(boxed[0], 4),
            d(area(20), 4),
            d(area(26), 4)
        ));
        // The fast search's miss (tests/tsm.rs, `fast_iterative_can_miss_a_narrow_peak`).
        let v = ViewFrustum::with_aspect(
            near,
            near * 0.98552f64.exp(),
            65.847f64.to_radians(),
            1.33108,
        )
        .unwrap();
        let (el, az) = (-1.25983f64, 3.05013f64);
        let l = DVec3::new(el.cos() * az.sin(), -el.sin(), -el.cos() * az.cos());
        let focus = 0.64775 * (v.far() - v.near());
        let run = |search| tsm(&v, l, TsmOptions { focus, search }).unwrap().focus_area;
        let fast = run(TsmSearch::Iterative { map_lines: 433 });
        let slow = run(TsmSearch::IterativeExhaustive { map_lines: 433 });
        e.has(format!(
            "{} % of focus area in the worst case seen",
            d(100.0 * (1.0 - fast / slow), 2)
        ));
        e.done()
    }

    pub fn bc_transition_counts() -> usize {
        let e = Entry::bullet(BC, "§3.1 after Eq 18, \"a smooth transition");
        let rule = |v: ViewFrustum| {
            move |l: DVec3| {
                let b = warp(&v, l, WarpRule::Barroso(Falloff::Barroso)).unwrap();
                frustum_max(&v, &b.shadow_map()).unwrap()
            }
        };
        has_worse_counts(e, "hemisphere directions", rule)
    }

    // ----- Barroso & Celes 2007 -----

    pub fn bc_s2_4() -> usize {
        let e = Entry::bullet(BC, "§2.4, \"the maximum aliasing error");
        let th = 30f64.to_radians();
        let m = |n: f64, f: f64, warped: bool| {
            let v = view(n, f, th);
            overhead(
                &v,
                if warped {
                    NPrime::finite(v.n_prime_lispsm()).unwrap()
                } else {
                    NPrime::UNWARPED
                },
            )
        };
        let (a, b) = (m(1.0, 4.0, true), m(1.0, 16.0, true));
        assert!(close(a.max_mz, m(10.0, 40.0, true).max_mz, 1e-9));
        e.has(format!(
            "LiSPSM M_z {} → {} (× {}",
            d(a.max_mz, 3),
            d(b.max_mz, 3),
            d(b.max_mz / a.max_mz, 1)
        ));
        e.has(format!(
            "M_x {} → {} (√(f/n)), S̄ {} → {} (× {}",
            d(a.max_mx, 0),
            d(b.max_mx, 0),
            d(a.storage_factor, 3),
            d(b.storage_factor, 2),
            d(b.storage_factor / a.storage_factor, 0)
        ));
        let (a, b) = (m(1.0, 4.0, false), m(1.0, 16.0, false));
        e.has(format!(
            "unwarped M_z {} → {} (× {}), M_x {} → {} (× {})",
            d(a.max_mz, 3),
            d(b.max_mz, 2),
            d(b.max_mz / a.max_mz, 0),
            d(a.max_mx, 0),
            d(b.max_mx, 0),
            d(b.max_mx / a.max_mx, 0)
        ));
        e.done()
    }

    pub fn bc_eq13_below_n() -> usize {
        let e = Entry::bullet(BC, "Eq 13, n′ below n");
        let v = view(1.0, 100.0, 1f64.to_radians());
        let g = 2f64.to_radians();
        let n1 = n_prime_1(&v, LightAngle::new(g).unwrap());
        let gen = generalized_n_prime(&v, LightAngle::new(g).unwrap(), Falloff::Barroso);
        assert_eq!(gen, NPrime::finite(n1).unwrap());
        let mx = |np: f64| {
            let w = tilted(&v, g, TiltSide::Behind, NPrime::finite(np).unwrap());
            along(&v, &w, 1.0).max(along(&v, &w, 100.0))
        };
        e.has(format!(
            "n′₁ = {} (Eq 16 uses it, γ_lim = {}°), along-axis maximum {} against {} at n′ = n",
            d(n1, 4),
            d(gamma_lim(&v).to_degrees(), 3),
            d(mx(n1), 2),
            d(mx(1.0), 2)
        ));
        let v = view(1.0, 2.0, 30f64.to_radians());
        let g = 35f64.to_radians();
        let n1 = n_prime_1(&v, LightAngle::new(g).unwrap());
        let mx = |np: f64| {
            let w = tilted(&v, g, TiltSide::Behind, NPrime::finite(np).unwrap());
            along(&v, &w, 1.0).max(along(&v, &w, 2.0))
        };
        e.has(format!(
            "n′₁ = {}, {} against {} at n′ = n",
            d(n1, 4),
            d(mx(n1), 4),
            d(mx(1.0), 4)
        ));
        e.done()
    }

    pub fn bc_eq6_eq12() -> usize {
        let e = Entry::bullet(BC, "Eq 6 and Eq 12, which width");
        let v = view(1.0, 100.0, FRAC_PI_6);
        let g = 45f64.to_radians();
        let np = n_prime_1(&v, LightAngle::new(g).unwrap());
        let w = tilted(&v, g, TiltSide::Behind, NPrime::finite(np).unwrap());
        let eq12 = tilted_mz(
            &v,
            NPrime::finite(np).unwrap(),
            LightAngle::new(g).unwrap(),
            1.0,
            Resolutions::default(),
        )
        .unwrap();
        let perp = at(&v, &w.shadow, 0.0, 0.0, 1.0).mz;
        e.has(format!(
            "n′ = n′₁ = {}, z = n: Eq 12 gives {} (along-axis measurement {}), the perpendicular measurement {}",
            d(np, 3),
            d(eq12, 3),
            d(along(&v, &w, 1.0), 3),
            d(perp, 3)
        ));
        e.done()
    }

    pub fn bc_eq13_minimax() -> usize {
        let e = Entry::bullet(BC, "§3.1 after Eq 12 / Eq 13");
        let v = view(1.0, 100.0, FRAC_PI_6);
        let max_at = |g: f64, np: NPrime| {
            let w = tilted(&v, g, TiltSide::Behind, np);
            along(&v, &w, 1.0).max(along(&v, &w, 100.0))
        };
        let g = 28f64.to_radians();
        let n2 = n_prime_2(&v, LightAngle::new(g).unwrap()).unwrap();
        let opt = n_prime_axis_minimax(&v, LightAngle::new(g).unwrap());
        e.has(format!(
            "n′₂ = {} gives the along-axis maximum {}, n′ = {} gives {}",
            d(n2, 4),
            d(max_at(g, NPrime::finite(n2).unwrap()), 2),
            d(opt.value(), 3),
            d(max_at(g, opt), 2)
        ));
        let g = 20f64.to_radians();
        assert!(n_prime_2(&v, LightAngle::new(g).unwrap()).unwrap() < 0.0);
        let opt = n_prime_axis_minimax(&v, LightAngle::new(g).unwrap());
        e.has(format!(
            "n′ = {} gives {}, unwarped {}",
            d(opt.value(), 2),
            d(max_at(g, opt), 2),
            d(max_at(g, NPrime::UNWARPED), 2)
        ));
        let wide = view(1.0, 2.0, 1.2);
        let g = 1.25;
        let m = |np: NPrime| {
            let w = tilted(&wide, g, TiltSide::Behind, np);
            along(&wide, &w, 1.0).max(along(&wide, &w, 2.0))
        };
        let n1 = n_prime_1(&wide, LightAngle::new(g).unwrap());
        let opt = n_prime_axis_minimax(&wide, LightAngle::new(g).unwrap());
        e.has(format!(
            "along-axis maximum {} at n′₁ = {}, {} at n′* = {}",
            d(m(NPrime::finite(n1).unwrap()), 5),
            d(n1, 3),
            d(m(opt), 5),
            d(opt.value(), 3)
        ));
        e.done()
    }

    pub fn bc_scope() -> usize {
        let e = Entry::bullet(BC, "§3.1, Eq 13 \"keeps the maximum error");
        let v = view(1.0, 100.0, FRAC_PI_6);
        let g = 60f64.to_radians();
        let mz = |np: f64| {
            frustum_max(
                &v,
                &tilted(&v, g, TiltSide::Behind, NPrime::finite(np).unwrap()).shadow,
            )
            .unwrap()
            .max_mz
        };
        let n1 = n_prime_1(&v, LightAngle::new(g).unwrap());
        e.has(format!(
            "n′₁ = {} gives the measured maximum over the eight vertices (perpendicular m_z) M_z = {}, n′ = 12.11 gives {}",
            d(n1, 3),
            d(mz(n1), 2),
            d(mz(12.11), 2)
        ));
        e.done()
    }

    pub fn bc_eq14_eq16() -> usize {
        let e = Entry::bullet(BC, "Eq 14 and Eq 16, \"n′₂\"");
        let v = view(1.0, 100.0, FRAC_PI_6);
        let g = LightAngle::new(20f64.to_radians()).unwrap();
        let gl = gamma_lim(&v);
        e.has(format!(
            "Eq 13's n′₂ = {}, Eq 16's \"n′₂\" = {} (Eq 17) or {} (Eq 18), with γ_lim = {}° and n′₁(γ_lim) = {}",
            d(n_prime_2(&v, g).unwrap(), 2),
            d(generalized_n_prime(&v, g, Falloff::Zhang).value(), 3),
            d(generalized_n_prime(&v, g, Falloff::Barroso).value(), 2),
            d(gl.to_degrees(), 2),
            d(n_prime_1(&v, LightAngle::new(gl).unwrap()), 3)
        ));
        e.done()
    }

    fn list(p: &[f64], digits: &[usize]) -> String {
        p.iter()
            .zip(digits)
            .map(|(&x, &k)| d(x, k))
            .collect::<Vec<_>>()
            .join(", ")
    }

    pub fn bc_eq19_alpha() -> usize {
        let e = Entry::bullet(BC, "Eq 19, \"α_i\"");
        let s = adaptive_limit(4);
        let p = s.planes();
        let r: Vec<f64> = p.windows(2).map(|w| w[1] / w[0]).collect();
        e.has(format!(
            "planes {} (ratios {})",
            list(p, &[0; 5]),
            list(&r, &[0; 4])
        ));
        // Read as α^i: at γ = 0, n_i = f_i/α^i from the far plane down.
        let mut q = vec![1000.0f64];
        for i in (2..=4).rev() {
            let next = *q.last().unwrap() / 2f64.powi(i);
            q.push(next);
        }
        q.push(1.0);
        q.reverse();
        let rq: Vec<f64> = q.windows(2).map(|w| w[1] / w[0]).collect();
        e.has(format!(
            "with α^i they would be {} (ratios {})",
            list(&q, &[0, 3, 4, 1, 0]),
            list(&rq, &[2, 0, 0, 0])
        ));
        e.done()
    }

    pub fn bc_f1_f2() -> usize {
        let e = Entry::bullet(BC, "§3.2 after Eq 19, \"f_1 = f_2\"");
        let s = adaptive_limit(4);
        let (a, b) = s.range(0);
        let (_, f2) = s.range(1);
        e.has(format!(
            "the first partition is [{}, {}], not [{}, {}]",
            d(a, 0),
            d(b, 0),
            d(a, 0),
            d(f2, 0)
        ));
        e.done()
    }

    /// Barroso's Eq 19 as printed (one α), in units of n: plane 1 u_1 from u_k = f/n by
    /// u_{i−1} = λ u_i^{(i−1)/i} + (1 − λ) u_i/α, λ = γ/(π/2); all k + 1 planes, near to far.
    fn eq19_by_hand(ratio: f64, k: usize, gamma: f64, alpha: f64) -> Vec<f64> {
        let l = gamma / FRAC_PI_2;
        let mut p = vec![ratio];
        for i in (2..=k).rev() {
            let u = *p.last().unwrap();
            let e = (i - 1) as f64 / i as f64;
            p.push(l * u.powf(e) + (1.0 - l) * u / alpha);
        }
        p.push(1.0);
        p.reverse();
        p
    }

    /// The f/n at which Eq 19's plane 1 reaches n (bisection; plane 1 increases with f/n).
    fn eq19_threshold(k: usize, gamma: f64, alpha: f64) -> f64 {
        let (mut lo, mut hi) = (1.0f64, 1e6f64);
        for _ in 0..200 {
            let m = (lo * hi).sqrt();
            if eq19_by_hand(m, k, gamma, alpha)[1] <= 1.0 {
                lo = m;
            } else {
                hi = m;
            }
        }
        0.5 * (lo + hi)
    }

    pub fn bc_eq19_no_planes() -> usize {
        use shadow_aliasing::Error;
        let e = Entry::bullet(BC, "Eq 19, planes at or below n");
        let adaptive = |f: f64, k: usize, g: f64| {
            z_splits(
                1.0,
                f,
                k,
                SplitScheme::Adaptive {
                    light_angle: g,
                    ratio: 2.0,
                },
            )
        };
        let p = eq19_by_hand(10.0, 5, 0.0, 2.0);
        e.has(format!(
            "γ = 0 gives the planes {}, plane 1 below n",
            list(&p[1..], &[3, 2, 1, 0, 0])
        ));
        match adaptive(10.0, 5, 0.0) {
            Err(Error::NoSolution(m)) => {
                assert!(m.contains(&format!("plane 1 at {}", p[1])), "{m}")
            }
            other => panic!("{other:?}"),
        }
        // The γ below which f/n = 10, k = 5 has no planes.
        let (mut lo, mut hi) = (0.0f64, FRAC_PI_2);
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if eq19_by_hand(10.0, 5, m, 2.0)[1] <= 1.0 {
                lo = m;
            } else {
                hi = m;
            }
        }
        assert!(matches!(
            adaptive(10.0, 5, lo * 0.999),
            Err(Error::NoSolution(_))
        ));
        assert!(adaptive(10.0, 5, hi * 1.001).is_ok());
        e.has(format!(
            "no planes for every γ below {}°",
            d(lo.to_degrees(), 2)
        ));
        for k in [2, 3, 4, 5, 8] {
            let mut row = format!("| {k} |");
            for (j, deg) in [0.0f64, 15.0, 30.0, 45.0, 60.0, 75.0]
                .into_iter()
                .enumerate()
            {
                let g = deg.to_radians();
                let t = eq19_threshold(k, g, 2.0);
                if j == 0 {
                    assert!((t - 2f64.powi(k as i32 - 1)).abs() < 1e-9 * t);
                }
                assert!(
                    matches!(adaptive(t / 1.01, k, g), Err(Error::NoSolution(_))),
                    "k {k}, γ {deg}°, f/n {}",
                    t / 1.01
                );
                let ok = adaptive(1.01 * t, k, g).unwrap();
                for (a, b) in ok.planes().iter().zip(eq19_by_hand(1.01 * t, k, g, 2.0)) {
                    assert!((a - b).abs() < 1e-12 * b, "k {k}, γ {deg}°: {a} vs {b}");
                }
                row += &format!(" {} |", d(t, if j == 0 { 0 } else { 2 }));
            }
            e.has(row);
        }
        let four: Vec<f64> = [2, 3, 4, 5, 8]
            .map(|k| eq19_threshold(k, 0.0, 4.0))
            .to_vec();
        e.has(format!(
            "T at γ = 0 is {} for these k",
            list(&four, &[0; 5])
        ));
        e.done()
    }

    pub fn bc_plane_by_plane() -> usize {
        let e = Entry::bullet(BC, "§3.2, Eq 19 \"linearly interpolating");
        let adaptive = |g: f64| {
            z_splits(
                1.0,
                1000.0,
                3,
                SplitScheme::Adaptive {
                    light_angle: g,
                    ratio: 2.0,
                },
            )
            .unwrap()
        };
        let s = adaptive(FRAC_PI_4);
        e.has(format!(
            "Eq 19 gives the planes {}",
            list(s.planes(), &[0, 3, 0, 0])
        ));
        let opt = z_splits(1.0, 1000.0, 3, SplitScheme::SelfSimilar).unwrap();
        let lim = adaptive(0.0);
        let blend: Vec<f64> = opt
            .planes()
            .iter()
            .zip(lim.planes())
            .map(|(a, b)| 0.5 * (a + b))
            .collect();
        e.has(format!(
            "the optimal {} and the limit {} is {}",
            list(opt.planes(), &[0; 4]),
            list(lim.planes(), &[0; 4]),
            list(&blend, &[0; 4])
        ));
        e.done()
    }

    pub fn bc_transition() -> usize {
        let e = Entry::bullet(BC, "§3.1 after Eq 18, \"a smooth transition");
        let ratio = |v: &ViewFrustum, l: DVec3| {
            let b = warp(v, l, WarpRule::Barroso(Falloff::Barroso)).unwrap();
            frustum_max(v, &b.shadow_map()).unwrap().storage_factor
                / fitted(v, l, NPrime::UNWARPED).storage_factor
        };
        let v = view(1.0, 100.0, 30f64.to_radians());
        e.has(format!(
            "straight behind, is {} × the uniform map's",
            d(ratio(&v, light_dir_from_angles(18f64.to_radians(), 0.0)), 2)
        ));
        let v = view(1.0, 1000.0, 30f64.to_radians());
        e.has(format!(
            "10° off behind, {} ×",
            d(
                ratio(
                    &v,
                    light_dir_from_angles(24f64.to_radians(), 10f64.to_radians())
                ),
                2
            )
        ));
        let v = view(1.0, 100.0, 30f64.to_radians());
        let g = 60f64.to_radians();
        let l = DVec3::new(0.0, -g.sin(), -g.cos());
        let o = minimax_mz_n_prime(&v, l).unwrap();
        let n1 = n_prime_1(&v, LightAngle::new(g).unwrap());
        e.has(format!(
            "n′ = {} with M_z = {}, against {} at n′₁ = {}",
            d(o.n_prime.value(), 3),
            d(fitted(&v, l, o.n_prime).max_mz, 3),
            d(fitted(&v, l, NPrime::finite(n1).unwrap()).max_mz, 2),
            d(n1, 3)
        ));
        e.done()
    }

    // ----- Zhang, Zhao & Sun 2009 (his light above and in front: TiltSide::InFront) -----

    fn zt(v: &ViewFrustum, theta: f64, lambda: f64) -> TiltedWarp {
        tilted(v, theta, TiltSide::InFront, NPrime::finite(lambda).unwrap())
    }

    pub fn zh_eq8_eq9() -> usize {
        let e = Entry::bullet(ZH, "§2.1, Eq 8 \"≈\"");
        let v = view(1.0, 100.0, FRAC_PI_6);
        let w = zt(&v, FRAC_PI_2, 11.0);
        let axis = DVec3::new(0.0, 0.0, -10.0);
        let full = aliasing_functions(&v, &w.shadow, axis, DVec3::new(0.3, 2.0, -1.0)).unwrap();
        let eq8 = zhang_eq_local(&v, NPrime::finite(11.0).unwrap(), 10.0).unwrap();
        let eq9 = zhang_ep_local(&v, NPrime::finite(11.0).unwrap(), 10.0).unwrap();
        assert!(close(full.e_q, eq8, 1e-9));
        e.has(format!("Eq 8 = {} = the full E_q", d(full.e_q, 3)));
        e.has(format!(
            "Eq 9 = {} while the full E_p is {} for k_y = 2",
            d(eq9, 3),
            d(full.e_p, 3)
        ));
        let off = aliasing_functions(
            &v,
            &w.shadow,
            DVec3::new(3.0, 0.0, -10.0),
            DVec3::new(1.0, 0.0, -1.0),
        )
        .unwrap();
        e.has(format!("full E_q = {})", d(off.e_q, 3)));
        e.done()
    }

    pub fn zh_tan_phi_w() -> usize {
        let e = Entry::bullet(ZH, "Appendix, tan φ_w");
        let (n, f, phi, theta, lambda) = (1.0, 100.0, FRAC_PI_6, 60f64.to_radians(), 11.0);
        let v = view(n, f, phi);
        let w = zt(&v, theta, lambda);
        let pr = zhang_printed::tan_phi_w(n, f, phi, lambda, theta);
        e.has(format!(
            "printed {}, fitted (twin) {}",
            d(pr, 4),
            d(w.half_extent_x, 4)
        ));
        let b = f * phi.tan();
        let zw = zhang_printed::z_w(n, f, phi, lambda, theta, b, f);
        e.has(format!(
            "the far-top corner has s = {}",
            d(0.5 * b / (zw * pr) + 0.5, 3)
        ));
        e.done()
    }

    pub fn zh_f_p() -> usize {
        let e = Entry::bullet(ZH, "Appendix, F_p");
        let (n, f, phi, lambda, z) = (1.0, 100.0, FRAC_PI_6, 11.0, 10.0);
        let v = view(n, f, phi);
        for (deg, digits) in [(60.0f64, 3usize), (20.0, 2)] {
            let th = deg.to_radians();
            let g = zhang_printed::g(n, f, phi, lambda, th, 0.0);
            let pr = zhang_printed::f_p(n, f, phi, lambda, th) * (z + g).powi(2) / z;
            let m = 2.0 * at(&v, &zt(&v, th, lambda).shadow, 0.0, 0.0, z).mz;
            if deg == 60.0 {
                e.has(format!(
                    "θ = 60°, printed F_p(z + G)²/z = {}, measured 2 m_z = {}",
                    d(pr, digits),
                    d(m, digits)
                ));
            } else {
                e.has(format!(
                    "θ = 20°, printed {}, measured {}",
                    d(pr, digits),
                    d(m, digits)
                ));
            }
        }
        e.done()
    }

    pub fn zh_f_q() -> usize {
        let e = Entry::bullet(ZH, "Appendix F_q and Eq 8");
        let (n, f, phi) = (1.0, 100.0, FRAC_PI_6);
        let v = view(n, f, phi);
        let eq8 = 2.0 * f / (f - n + 0.5) * (1.0 - n + 0.5) / 1.0;
        let m = 2.0 * at(&v, &zt(&v, FRAC_PI_2, 0.5).shadow, 0.0, 0.0, 1.0).mx;
        e.has(format!(
            "λ = 0.5, z = 1: Eq 8 gives {}, measured {}",
            d(eq8, 3),
            d(m, 3)
        ));
        let th = 60f64.to_radians();
        let g = zhang_printed::g(n, f, phi, 0.2, th, 0.0);
        let pr = zhang_printed::f_q(n, f, phi, 0.2, th) * (1.0 + g);
        let m = 2.0 * at(&v, &zt(&v, th, 0.2).shadow, 0.0, 0.0, 1.0).mx;
        e.has(format!(
            "printed F_q(z + G)/z = {}, measured {}",
            d(pr, 3),
            d(m, 3)
        ));
        e.done()
    }

    pub fn zh_s2_4_eq() -> usize {
        let e = Entry::bullet(ZH, "§2.4, E_q^pers");
        let (n, f, phi, lambda, z) = (1.0f64, 100.0f64, FRAC_PI_6, 11.0f64, 10.0f64);
        let v = view(n, f, phi);
        let tan_w = f * phi.tan() / (f - n + lambda);
        let printed = 2.0 * tan_w * (z - n + lambda) / phi.tan();
        let m = 2.0 * at(&v, &zt(&v, FRAC_PI_2, lambda).shadow, 0.0, 0.0, z).mx;
        e.has(format!(
            "z = 10: printed {}, measured 2 m_x = {}",
            d(printed, 2),
            d(m, 3)
        ));
        e.done()
    }

    pub fn zh_s2_1_maps() -> usize {
        let e = Entry::bullet(ZH, "§2.1, t(x, z) and s(z)");
        let (n, f, phi, lambda, z) = (1.0f64, 100.0f64, FRAC_PI_6, 11.0f64, 10.0f64);
        let v = view(n, f, phi);
        let mu = f - n;
        let s = |z: f64| (lambda + mu) / mu * (1.0 - lambda / z);
        let h = 1e-6;
        let ds_dz = (s(z + h) - s(z - h)) / (2.0 * h);
        let ep = 1.0 / (phi.tan() * z) / ds_dz;
        let m = 2.0 * at(&v, &zt(&v, FRAC_PI_2, lambda).shadow, 0.0, 0.0, z).mz;
        e.has(format!(
            "(ds/dz)⁻¹ = {}, measured (and Eq 9) {}",
            d(ep, 3),
            d(m, 3)
        ));
        e.done()
    }

    pub fn zh_argmin() -> usize {
        let e = Entry::bullet(ZH, "§3.1, \"arg min E");
        let (f, phi) = (100.0, FRAC_PI_6);
        let v = view(1.0, f, phi);
        let w = zt(&v, FRAC_PI_2, 11.0);
        let p = |z: f64| at(&v, &w.shadow, 0.0, z * phi.tan(), z);
        e.has(format!(
            "E_p = {} at z = √(fn) = 10 against {} at z = f",
            d(2.0 * p(10.0).mz, 3),
            d(2.0 * p(f).mz, 2)
        ));
        let pq = |z: f64| 4.0 * p(z).mx * p(z).mz;
        e.has(format!(
            "E_p×q = {} at z = 2√(fn) = 20 against {} at z = f",
            d(pq(20.0), 2),
            d(pq(f), 2)
        ));
        e.done()
    }

    pub fn zh_max_e_q() -> usize {
        let e = Entry::bullet(ZH, "§3.1, \"the maximum … of E_q");
        let (n, f, phi) = (1.0, 100.0, FRAC_PI_6);
        let v = view(n, f, phi);
        let w = zt(&v, 60f64.to_radians(), 0.2);
        e.has(format!(
            "measured E_q = {} at (z, y) = (n, −n tan φ), {} at (f, −f tan φ)",
            d(2.0 * at(&v, &w.shadow, 0.0, -n * phi.tan(), n).mx, 3),
            d(2.0 * at(&v, &w.shadow, 0.0, -f * phi.tan(), f).mx, 2)
        ));
        e.done()
    }

    pub fn zh_e_q_along_z() -> usize {
        let e = Entry::bullet(ZH, "§3.1, \"E_q increases as z decreases\"");
        let (n, f, phi, th) = (1.0f64, 100.0f64, FRAC_PI_6, 60f64.to_radians());
        let v = view(n, f, phi);
        e.has(format!(
            "(f − n) tan φ cos θ, {} at",
            d(n * th.sin() + (f - n) * phi.tan() * th.cos(), 2)
        ));
        let n1 = n_prime_1(&v, LightAngle::new(th).unwrap());
        e.has(format!("Barroso's n′₁ = {}", d(n1, 3)));
        let (y, z_top) = (40.0, 40.0 / phi.tan());
        let eq = |lambda: f64, z: f64| 2.0 * at(&v, &zt(&v, th, lambda).shadow, 0.0, y, z).mx;
        e.has(format!(
            "λ = 11 gives E_q = {} at z = {} (the top plane) and {} at z = f; λ = {}, {} and {}",
            d(eq(11.0, z_top), 4),
            d(z_top, 3),
            d(eq(11.0, f), 4),
            d(n1, 3),
            d(eq(n1, z_top), 4),
            d(eq(n1, f), 4)
        ));
        e.done()
    }

    pub fn zh_behind() -> usize {
        let e = Entry::bullet(ZH, "§2.4, \"θ can be replaced");
        let v = view(1.0, 100.0, FRAC_PI_6);
        let th = LightAngle::new(60f64.to_radians()).unwrap();
        let w = tilted_warp(&v, th, TiltSide::Behind, NPrime::finite(11.0).unwrap()).unwrap();
        let m = 2.0 * at(&v, &w.shadow, 0.0, 5.0, 10.0).mz;
        let l = NPrime::finite(11.0).unwrap();
        e.has(format!("measured E_p = {}", d(m, 3)));
        e.has(format!(
            "Eq 14 at θ = 60° gives {} with y = 5 and {} with y = −5",
            d(zhang_ep(&v, l, th, 5.0, 10.0).unwrap(), 3),
            d(zhang_ep(&v, l, th, -5.0, 10.0).unwrap(), 3)
        ));
        e.done()
    }

    pub fn zh_theta_zero() -> usize {
        let e = Entry::bullet(ZH, "Eq 13, 14 at θ = 0");
        let v = view(1.0, 100.0, FRAC_PI_6);
        let m = 2.0 * at(&v, &zt(&v, 0.0, 3.0).shadow, 0.0, 1.0, 7.0).mx;
        let eq = zhang_eq(
            &v,
            NPrime::finite(3.0).unwrap(),
            LightAngle::new(0.0).unwrap(),
            1.0,
            7.0,
        )
        .unwrap();
        assert!(close(eq, m, 1e-9));
        e.has(format!("E_q = 2(f/λ) z_w/z = {}", d(m, 2)));
        e.done()
    }
}

// ---------------------------------------------------------------------------------------------
// One test per entry, and the paragraph's counts.
// ---------------------------------------------------------------------------------------------

macro_rules! entries {
    ($($name:ident),* $(,)?) => {
        $(#[test] fn $name() { checks::$name(); })*
        const ALL: &[fn() -> usize] = &[$(checks::$name),*];
    };
}

entries!(
    l05_1,
    l05_2,
    l05_3,
    l05_5,
    l05_6,
    l05_9,
    l05_10,
    l05_11,
    l06_1,
    l06_2,
    l06_3,
    l06_4,
    l06_5,
    l06_7,
    l06_8,
    l06_9,
    l06_11,
    l06_11_counts,
    l06_12,
    l06_13,
    l06_13_sum,
    l06_13_grid,
    l06_14,
    l06_15,
    l06_16,
    l06_17_edge,
    l06_18,
    l06_19,
    l06_20,
    mt_domain,
    mt_vector,
    mt_top_line,
    mt_square_fallback,
    mt_iterative,
    bc_s2_4,
    bc_eq13_below_n,
    bc_eq6_eq12,
    bc_eq13_minimax,
    bc_scope,
    bc_eq14_eq16,
    bc_eq19_alpha,
    bc_f1_f2,
    bc_eq19_no_planes,
    bc_plane_by_plane,
    bc_transition,
    bc_transition_counts,
    zh_eq8_eq9,
    zh_tan_phi_w,
    zh_f_p,
    zh_f_q,
    zh_s2_4_eq,
    zh_s2_1_maps,
    zh_argmin,
    zh_max_e_q,
    zh_e_q_along_z,
    zh_behind,
    zh_theta_zero,
);

/// The paragraph "Independent check of these entries" states how many entries and numbers this
/// file checks.
#[test]
fn independent_check_paragraph_counts() {
    CHECKED.with(|c| c.borrow_mut().clear());
    let numbers: usize = ALL.iter().map(|f| f()).sum();
    let entries = CHECKED.with(|c| c.borrow().len());
    let para = normalise(section("Independent check"));
    assert!(
        para.contains(&format!("The numbers of {entries} entries")),
        "expected {entries} entries in: {para}"
    );
    assert!(
        para.contains(&format!("All {numbers} numbers agree")),
        "expected {numbers} numbers in: {para}"
    );
}
