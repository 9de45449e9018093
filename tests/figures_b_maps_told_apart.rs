//! The z-partitions' maps told apart (the eleventh review, R11-barroso-fig5-1 and R11-X-1), read
//! back from the SVGs of barroso-fig5 and lloyd2006-fig11 in all three forms:
//! - each pair of barroso-fig5's four maps differs in CIE L* by at least 20 or in colour by a
//!   CIE76 ΔE of at least 25 (R11: maps 1 and 3, #582A92 and #674CA0, were 10.8 L* and 17.4 ΔE
//!   apart), and in dash pattern; every map stroke is at least 3 : 1 on white;
//! - map i has one colour and one dash kind in both figures (R11-X-1: fig11's map 1 was thick
//!   dark dashed, barroso-fig5's thin dashed; map 3 dash-dot in both but of other purples);
//! - in barroso-fig5's details (b), (d), (f) each map large enough is numbered, "1" to "4" in its
//!   map's colour (or that colour darkened to 4.5 : 1), at a corner of its own rectangle: the
//!   corner of a map's outline nearest the number is its own map's.
//!
//! Map i's colour is read from the key ("Maps, nearest first:", each sample before its number);
//! a dash kind from the outlines' straight pieces: each piece's length over the distance from
//! its start to the next collinear piece's start (its share of the period), clustered: dashes
//! 6 : 3 give 0.67, dots 4 : 3 give 0.57, dash-dot 12 : 3 : 2 : 3 gives 0.8 and 0.4, long dashes
//! 14 : 4 give 0.78 (the kinds are those ratios at any scale).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read as read;
use figures_style_read::{attr_str, forms, points, Font};
use shadow_aliasing::plot::{render_with, Format, Options};
use std::path::Path;

fn svg(name: &str, form: &str, opts: &Options) -> String {
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "figures-b-{name}-{form}-{}-{call}",
        std::process::id()
    ));
    let files = render_with(name, &dir, Format::Svg, opts).unwrap();
    let s = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    s
}

/// `#RRGGBB` as its channels.
fn rgb(hex: &str) -> [f64; 3] {
    let c = |i: usize| f64::from(u8::from_str_radix(&hex[i..i + 2], 16).unwrap());
    [c(1), c(3), c(5)]
}

/// sRGB to CIE L*a*b* (D65), and the relative luminance Y.
fn lab(hex: &str) -> ([f64; 3], f64) {
    let lin = |v: f64| {
        let v = v / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    let [r, g, b] = rgb(hex).map(lin);
    let x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
    let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
    let f = |t: f64| {
        if t > 216.0 / 24389.0 {
            t.cbrt()
        } else {
            (24389.0 / 27.0 * t + 16.0) / 116.0
        }
    };
    let (fx, fy, fz) = (f(x / 0.95047), f(y), f(z / 1.08883));
    ([116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)], y)
}

fn delta_e(a: &str, b: &str) -> f64 {
    let (p, _) = lab(a);
    let (q, _) = lab(b);
    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
}

/// WCAG 2's contrast against white.
fn contrast(hex: &str) -> f64 {
    1.05 / (lab(hex).1 + 0.05)
}

/// The maps' colours in the key's order (map 1 first): the stroke of the last sample drawn
/// before each number after "Maps, nearest first:".
fn key_colours(svg: &str) -> Vec<String> {
    let start = svg.find(">Maps, nearest first:").expect("the key");
    let mut out = Vec::new();
    let mut last: Option<String> = None;
    for l in svg[start..].lines() {
        if l.starts_with("<polyline") {
            last = attr_str(l, "stroke").map(str::to_uppercase);
        } else if l.starts_with("<text") {
            let content = &l[l.find('>').unwrap() + 1..l.rfind("</text>").unwrap_or(l.len())];
            if content == "frustum" {
                break;
            }
            if content.parse::<usize>() == Ok(out.len() + 1) {
                out.push(last.clone().expect("a sample before its number"));
            }
        }
    }
    out
}

/// The straight pieces (two points) of every polyline of `colour`, in the SVG's order.
fn pieces(svg: &str, colour: &str) -> Vec<[(f64, f64); 2]> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline"))
        .filter(|l| attr_str(l, "stroke").is_some_and(|c| c.eq_ignore_ascii_case(colour)))
        .map(points)
        .filter(|p| p.len() == 2 && p[0] != p[1])
        .map(|p| [p[0], p[1]])
        .collect()
}

/// Each dash's share of its period (see the module's notes): for each piece followed by a
/// collinear one further along its direction, the piece's length over the distance between the
/// two starts.
fn shares(pieces: &[[(f64, f64); 2]]) -> Vec<f64> {
    let mut out = Vec::new();
    for w in pieces.windows(2) {
        let ([a, b], [c, _]) = (w[0], w[1]);
        let len = (b.0 - a.0).hypot(b.1 - a.1);
        let dir = ((b.0 - a.0) / len, (b.1 - a.1) / len);
        let (ux, uy) = (c.0 - a.0, c.1 - a.1);
        let along = ux * dir.0 + uy * dir.1;
        let off = (ux * dir.1 - uy * dir.0).abs();
        if off <= 0.05 && along > len {
            out.push(len / along);
        }
    }
    out
}

/// A dash kind: the medians of the clusters of `shares` (sorted, split where two neighbours
/// are more than 0.08 apart), each cluster holding at least a sixth of them.
fn kind(shares: &[f64]) -> Vec<f64> {
    let mut s = shares.to_vec();
    s.sort_by(f64::total_cmp);
    let mut clusters: Vec<Vec<f64>> = Vec::new();
    for v in s {
        match clusters.last_mut() {
            Some(c) if v - c[c.len() - 1] <= 0.08 => c.push(v),
            _ => clusters.push(vec![v]),
        }
    }
    let n = shares.len();
    clusters
        .into_iter()
        .filter(|c| c.len() * 6 >= n && c.len() >= 2)
        .map(|c| c[c.len() / 2])
        .collect()
}

fn same_kind(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 0.05)
}

/// The kinds of `shares` by hand: 6 : 3 dashes are 2/3, a dash-dot 12 : 3 : 2 : 3 is 0.4 and
/// 0.8, and two kinds 0.1 apart differ.
/// The four sides of the axis-aligned box `r` (bottom and top, then left and right) as
/// (the side's fixed coordinate, its extent from, to, the pieces of `segs` lying on it as
/// intervals along it, sorted by their start).
#[allow(clippy::type_complexity)]
fn sides(segs: &[((f64, f64), (f64, f64))], r: &[f64; 4]) -> Vec<(f64, f64, f64, Vec<(f64, f64)>)> {
    [
        (true, r[1], r[0], r[2]),
        (true, r[3], r[0], r[2]),
        (false, r[0], r[1], r[3]),
        (false, r[2], r[1], r[3]),
    ]
    .into_iter()
    .map(|(horizontal, at, lo, hi)| {
        let on = |p: (f64, f64)| (if horizontal { p.1 } else { p.0 } - at).abs() <= 0.05;
        let along = |p: (f64, f64)| if horizontal { p.0 } else { p.1 };
        let mut iv: Vec<(f64, f64)> = segs
            .iter()
            .filter(|&&(p, q)| on(p) && on(q))
            .map(|&(p, q)| (along(p).min(along(q)), along(p).max(along(q))))
            .collect();
        iv.sort_by(|x, y| x.0.total_cmp(&y.0));
        (at, lo, hi, iv)
    })
    .collect()
}

#[test]
fn dash_kinds_are_read_by_hand() {
    let dashes: Vec<[(f64, f64); 2]> = (0..5)
        .map(|k| {
            let x = 9.0 * f64::from(k);
            [(x, 1.0), (x + 6.0, 1.0)]
        })
        .collect();
    let k = kind(&shares(&dashes));
    assert_eq!(k.len(), 1);
    assert!((k[0] - 2.0 / 3.0).abs() < 1e-9, "{k:?}");
    let mut dash_dot = Vec::new();
    for p in 0..4 {
        let x = 20.0 * f64::from(p);
        dash_dot.push([(x, 0.0), (x + 12.0, 0.0)]);
        dash_dot.push([(x + 15.0, 0.0), (x + 17.0, 0.0)]);
    }
    let k = kind(&shares(&dash_dot));
    assert!(same_kind(&k, &[0.4, 0.8]), "{k:?}");
    assert!(!same_kind(&[0.67], &[0.78]) && !same_kind(&[0.8], &[0.4, 0.8]));
}

/// Each pair of barroso-fig5's maps: L* at least 20 apart or ΔE at least 25, and dash kinds
/// that differ; lloyd2006-fig11's three maps alike; every map at least 3 : 1 on white.
#[test]
fn each_pair_of_maps_differs_in_colour_and_dash() {
    // The old colours fail (R11: #582A92 against #674CA0).
    let (old1, old3) = ("#582A92", "#674CA0");
    assert!((lab(old1).0[0] - lab(old3).0[0]).abs() < 20.0 && delta_e(old1, old3) < 25.0);
    for (name, n) in [("barroso-fig5", 4), ("lloyd2006-fig11", 3)] {
        for (form, opts) in forms() {
            let s = svg(name, form, &opts);
            let colours = key_colours(&s);
            assert_eq!(colours.len(), n, "{name} {form}: {colours:?}");
            let kinds: Vec<Vec<f64>> = colours
                .iter()
                .map(|c| kind(&shares(&pieces(&s, c))))
                .collect();
            for (i, c) in colours.iter().enumerate() {
                assert!(contrast(c) >= 3.0, "{name} {form}: map {} {c}", i + 1);
                assert!(
                    !kinds[i].is_empty(),
                    "{name} {form}: map {} no dashes",
                    i + 1
                );
                for j in i + 1..n {
                    let d = &colours[j];
                    let dl = (lab(c).0[0] - lab(d).0[0]).abs();
                    let de = delta_e(c, d);
                    assert!(
                        dl >= 20.0 || de >= 25.0,
                        "{name} {form}: maps {} {c} and {} {d}: ΔL* {dl:.1}, ΔE {de:.1}",
                        i + 1,
                        j + 1
                    );
                    assert!(
                        !same_kind(&kinds[i], &kinds[j]),
                        "{name} {form}: maps {} and {} both dashed {:?}, {:?}",
                        i + 1,
                        j + 1,
                        kinds[i],
                        kinds[j]
                    );
                }
            }
        }
    }
}

/// Map i's colour and dash kind are the same in barroso-fig5 and lloyd2006-fig11 (R11-X-1), in
/// each form.
#[test]
fn map_i_looks_the_same_in_both_figures() {
    for (form, opts) in forms() {
        let b = svg("barroso-fig5", form, &opts);
        let f = svg("lloyd2006-fig11", form, &opts);
        let (cb, cf) = (key_colours(&b), key_colours(&f));
        assert_eq!(cf.len(), 3, "{form}");
        for (i, c) in cf.iter().enumerate() {
            assert_eq!(c, &cb[i], "{form}: map {}", i + 1);
            let (kb, kf) = (kind(&shares(&pieces(&b, c))), kind(&shares(&pieces(&f, c))));
            assert!(
                same_kind(&kb, &kf),
                "{form}: map {} dashed {kb:?} in barroso-fig5, {kf:?} in lloyd2006-fig11",
                i + 1
            );
        }
    }
}

/// The distance from the box `r` to the point `c`.
fn distance(r: &[f64; 4], c: (f64, f64)) -> f64 {
    let dx = (r[0] - c.0).max(c.0 - r[2]).max(0.0);
    let dy = (r[1] - c.1).max(c.1 - r[3]).max(0.0);
    dx.hypot(dy)
}

/// Whether `ink` is `colour` or `colour` darkened (each channel scaled by one factor, within
/// rounding).
fn darkened(ink: &str, colour: &str) -> bool {
    let (a, b) = (rgb(ink), rgb(colour));
    let k = a.iter().sum::<f64>() / b.iter().sum::<f64>();
    k <= 1.0 + 1e-9 && a.iter().zip(&b).all(|(x, y)| (x - k * y).abs() <= 1.5)
}

/// In barroso-fig5's details each map whose rectangle the detail shows whole and large enough
/// for a digit is numbered: (b) (z ≤ 31.62) maps 2 and 3, (d) (z ≤ 10) maps 1 and 2, (f)
/// (z ≤ 40.81) maps 2 and 3 (map 1 is 3.7 × 2.2 light-space units in (b) and (f), a few units
/// on the page). Each number is in its map's colour or that darkened, at least 4.5 : 1 on
/// white, and sits by its own map's rectangle: within 25 units of one of its corners, and no
/// other map's corner nearer, or every other map's outline farther from its text box than
/// its own map's by half a unit or more (the digit's ink, which the code places, by two; read
/// by the nearest corner alone, no place in (d) was clear of the frustum's
/// diagonals: the number stood on a white box across one).
#[test]
fn numbers_sit_by_their_own_maps() {
    let font = Font::dejavu();
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let colours = key_colours(&s);
        for (from, to, want) in [
            ("(b)", Some("(c)"), [2, 3]),
            ("(d)", Some("(e)"), [1, 2]),
            // The last panel drawn (the key is drawn first).
            ("(f)", None, [2, 3]),
        ] {
            let a = read::title_at(&s, 0, from).unwrap();
            // Up to the next title's element.
            let b = to.map_or(s.len(), |to| {
                let b = read::title_at(&s, a + 1, to).unwrap();
                s[..b].rfind("<text").unwrap()
            });
            let part = &s[a..b];
            // Each map's rectangle in this panel: the bounding box of its outline.
            let rects: Vec<Option<[f64; 4]>> = colours
                .iter()
                .map(|c| {
                    let pts: Vec<(f64, f64)> = part
                        .lines()
                        .filter(|l| l.starts_with("<polyline"))
                        .filter(|l| {
                            attr_str(l, "stroke").is_some_and(|x| x.eq_ignore_ascii_case(c))
                        })
                        .flat_map(points)
                        .collect();
                    (!pts.is_empty()).then(|| read::bbox(&pts))
                })
                .collect();
            let corners = |r: &[f64; 4]| [(r[0], r[1]), (r[2], r[1]), (r[2], r[3]), (r[0], r[3])];
            let mut seen = Vec::new();
            for t in read::texts(&font, part) {
                let Ok(i) = t.content.parse::<usize>() else {
                    continue;
                };
                if !(1..=4).contains(&i) {
                    continue;
                }
                let ink = attr_str(&t.tag, "fill").unwrap().to_uppercase();
                let own = &colours[i - 1];
                assert!(
                    darkened(&ink, own) && contrast(&ink) >= 4.5,
                    "{form} {from}: \"{i}\" in {ink}, map {i} is {own}"
                );
                let rect =
                    rects[i - 1].unwrap_or_else(|| panic!("{form} {from}: map {i} not drawn"));
                let (near, d) = corners(&rect)
                    .into_iter()
                    .map(|c| (c, distance(&t.bbox, c)))
                    .min_by(|x, y| x.1.total_cmp(&y.1))
                    .unwrap();
                assert!(
                    d > 0.0 && d <= 25.0,
                    "{form} {from}: \"{i}\" {:?} is {d:.1} from map {i}'s corner {near:?}",
                    t.bbox
                );
                // The nearest outline is its own map's, every other at least 2 units farther.
                let outline = |r: &[f64; 4]| {
                    let sides = [
                        [r[0], r[1], r[2], r[1]],
                        [r[2], r[1], r[2], r[3]],
                        [r[0], r[3], r[2], r[3]],
                        [r[0], r[1], r[0], r[3]],
                    ];
                    sides
                        .iter()
                        .map(|e| {
                            let b = &t.bbox;
                            let dx = (e[0] - b[2]).max(b[0] - e[2]).max(0.0);
                            let dy = (e[1] - b[3]).max(b[1] - e[3]).max(0.0);
                            dx.hypot(dy)
                        })
                        .fold(f64::INFINITY, f64::min)
                };
                let mine = outline(&rect);
                let others = || {
                    rects
                        .iter()
                        .enumerate()
                        .filter(move |(j, _)| *j != i - 1)
                        .filter_map(|(j, r)| r.map(|r| (j, r)))
                };
                let by_corner = others()
                    .all(|(_, r)| corners(&r).into_iter().all(|c| distance(&t.bbox, c) >= d));
                for (j, r) in others() {
                    if !by_corner {
                        assert!(
                            outline(&r) >= mine + 0.5,
                            "{form} {from}: \"{i}\" {:.1} from map {}'s outline, {mine:.1} from \
                             its own",
                            outline(&r),
                            j + 1
                        );
                    }
                }
                // No black line (the frustum's) runs under the number (it stood on a white box
                // cutting a diagonal in (d)).
                for l in part.lines().filter(|l| {
                    l.starts_with("<polyline") && attr_str(l, "stroke") == Some("#000000")
                }) {
                    let pts = points(l);
                    for w in pts.windows(2) {
                        assert!(
                            !read::segment_enters(w[0], w[1], &t.bbox, 0.0),
                            "{form} {from}: \"{i}\" {:?} over a black line {:?}",
                            t.bbox,
                            (w[0], w[1])
                        );
                    }
                }
                seen.push(i);
            }
            for i in want {
                assert!(
                    seen.contains(&i),
                    "{form} {from}: map {i} not numbered ({seen:?})"
                );
            }
        }
    }
}

/// Each dash's share of its dash and the gap after it, by map (nearest first), by hand from
/// the key's patterns: dashes 6 : 3, dots 4 : 3, dash-dot 12 : 3 : 2 : 3, long dashes 14 : 4.
const SHARES: [&[f64]; 4] = [&[6.0 / 9.0], &[4.0 / 7.0], &[0.8, 0.4], &[14.0 / 18.0]];

/// Map i's shortest period of its kind that prints and its first dash, in pt: each dash at
/// least 1 pt and each gap 0.8 pt, in the shares of [`SHARES`]; by hand: dashes 1.6 + 0.8,
/// dots 16/15 + 0.8, dash-dot 3.2 + 0.8 + 1 + 1.5, long dashes 2.8 + 0.8.
const LEAST_PERIOD_PT: [(f64, f64); 4] = [
    (2.4, 1.6),
    (28.0 / 15.0, 16.0 / 15.0),
    (6.5, 3.2),
    (3.6, 2.8),
];

/// The thirteenth review, R13-barroso-fig5-1: in the overviews (a), (c), (e) map 3's outline was
/// solid while the key gives it dash-dot. In every form, each side of each map's outline in the
/// overviews, read from the SVG (the pieces of the map's colour lying on the side of their
/// bounding box, corner pieces included), is dashed in its map's kind wherever one period of
/// the kind at its shortest that prints fits ([`LEAST_PERIOD_PT`]): every dash's share of its
/// period as [`SHARES`] gives it (within 0.05), whole periods (a side starts and ends on a
/// dash), at least 4 of them or as many as fit at the shortest, every dash at least 1 pt and
/// every gap 0.8 pt long printed; and map 3 shows dash-dot in each overview.
#[test]
fn overview_outlines_show_their_keyed_dash_kinds() {
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let pt = read::points_per_unit(&s);
        let colours = key_colours(&s);
        assert_eq!(colours.len(), 4, "{form}");
        for (from, to) in [("(a)", "(b)"), ("(c)", "(d)"), ("(e)", "(f)")] {
            let a = read::title_at(&s, 0, from).unwrap();
            let b = read::title_at(&s, a + 1, to).unwrap();
            let part = &s[a..s[..b].rfind("<text").unwrap()];
            let mut dash_dot_sides = 0;
            for (m, c) in colours.iter().enumerate() {
                let segs: Vec<((f64, f64), (f64, f64))> = part
                    .lines()
                    .filter(|l| l.starts_with("<polyline"))
                    .filter(|l| attr_str(l, "stroke").is_some_and(|x| x.eq_ignore_ascii_case(c)))
                    .flat_map(|l| {
                        let p = points(l);
                        p.windows(2).map(|w| (w[0], w[1])).collect::<Vec<_>>()
                    })
                    .filter(|(p, q)| p != q)
                    .collect();
                if segs.is_empty() {
                    continue;
                }
                let all: Vec<(f64, f64)> = segs.iter().flat_map(|&(p, q)| [p, q]).collect();
                let r = read::bbox(&all);
                // Bottom and top (along x), left and right (along y): the line's fixed
                // coordinate, the side's extent.
                for (at, lo, hi, iv) in sides(&segs, &r) {
                    if iv.is_empty() {
                        continue; // a side outside the plot, not drawn
                    }
                    let len = hi - lo;
                    let (period, first) = LEAST_PERIOD_PT[m];
                    let fit = ((len * pt - first) / period + 1e-6).floor();
                    let what = format!(
                        "{form} {from}: map {} side {len:.1} units at {at:.1}",
                        m + 1
                    );
                    assert!(
                        (iv[0].0 - lo).abs() <= 0.05 && (iv[iv.len() - 1].1 - hi).abs() <= 0.05,
                        "{what}: {iv:?}"
                    );
                    if fit < 1.0 {
                        continue;
                    }
                    let kind = SHARES[m];
                    let periods = (iv.len() - 1) as f64 / kind.len() as f64;
                    assert!(
                        iv.len() > 1 && periods.fract() == 0.0 && periods >= fit.min(4.0),
                        "{what}: {} dashes, {fit} periods fit: {iv:?}",
                        iv.len()
                    );
                    // The side runs either way round the outline: its dashes read from one end.
                    let reads = |iv: &[(f64, f64)]| {
                        iv.windows(2).enumerate().all(|(j, w)| {
                            let (dash, gap) = (w[0].1 - w[0].0, w[1].0 - w[0].1);
                            (dash / (dash + gap) - kind[j % kind.len()]).abs() <= 0.05
                        })
                    };
                    let back: Vec<(f64, f64)> = iv.iter().rev().map(|&(x, y)| (-y, -x)).collect();
                    assert!(reads(&iv) || reads(&back), "{what}: not {kind:?}: {iv:?}");
                    for w in iv.windows(2) {
                        let (dash, gap) = (w[0].1 - w[0].0, w[1].0 - w[0].1);
                        assert!(
                            dash * pt >= 1.0 - 0.01 && gap * pt >= 0.8 - 0.01,
                            "{what}: dash {dash:.2} gap {gap:.2}: {iv:?}"
                        );
                    }
                    let last = iv[iv.len() - 1];
                    assert!((last.1 - last.0) * pt >= 1.0 - 0.01, "{what}: {iv:?}");
                    if m == 2 {
                        dash_dot_sides += 1;
                    }
                }
            }
            assert!(
                dash_dot_sides > 0,
                "{form} {from}: map 3 not dash-dot on any side"
            );
        }
    }
}

/// The eighteenth review, R18-barroso-fig5-1: in one column (d)'s map 1, a square 15.6 units on
/// a side, was one solid polyline (its pattern, 5 : 2.5, fits one period on a side, fewer than a
/// detail's two), while two columns dashed the same square (18.8 units) and the key dashes the
/// map. In every form, each map-1 outline in the details (b), (d), (f) at least 12 units on a
/// side (read as the bounding box of its pieces; (d)'s in every form, (b)'s and (f)'s are a few
/// units and skipped) is drawn as dashes: at least four pieces, and along each side at least two
/// dashes, starting and ending at its corners, each dash's share of its period map 1's 2/3
/// (within 0.05), every dash at least 1 pt and every gap 0.8 pt long.
#[test]
fn detail_map_1_squares_are_dashed() {
    const LEAST_SIDE: f64 = 12.0;
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let pt = read::points_per_unit(&s);
        let colours = key_colours(&s);
        let c = &colours[0];
        let mut checked = Vec::new();
        for (from, to) in [("(b)", Some("(c)")), ("(d)", Some("(e)")), ("(f)", None)] {
            let a = read::title_at(&s, 0, from).unwrap();
            let b = to.map_or(s.len(), |to| {
                let b = read::title_at(&s, a + 1, to).unwrap();
                s[..b].rfind("<text").unwrap()
            });
            let lines: Vec<Vec<(f64, f64)>> = s[a..b]
                .lines()
                .filter(|l| l.starts_with("<polyline"))
                .filter(|l| attr_str(l, "stroke").is_some_and(|x| x.eq_ignore_ascii_case(c)))
                .map(points)
                .collect();
            let all: Vec<(f64, f64)> = lines.iter().flatten().copied().collect();
            if all.is_empty() {
                continue;
            }
            let r = read::bbox(&all);
            let (w, h) = (r[2] - r[0], r[3] - r[1]);
            if w.min(h) < LEAST_SIDE {
                continue;
            }
            let what = format!("{form} {from}: map 1, {w:.1} × {h:.1} units");
            assert!(lines.len() >= 4, "{what}: {} polylines", lines.len());
            let segs: Vec<((f64, f64), (f64, f64))> = lines
                .iter()
                .flat_map(|p| p.windows(2).map(|w| (w[0], w[1])).collect::<Vec<_>>())
                .filter(|(p, q)| p != q)
                .collect();
            for (at, lo, hi, iv) in sides(&segs, &r) {
                // Pieces that meet (a polyline's points along one side) are one dash.
                let mut dashes: Vec<(f64, f64)> = Vec::new();
                for (x, y) in iv {
                    match dashes.last_mut() {
                        Some(d) if x <= d.1 + 0.05 => d.1 = d.1.max(y),
                        _ => dashes.push((x, y)),
                    }
                }
                let side = format!("{what}, side at {at:.1}");
                assert!(dashes.len() >= 2, "{side}: solid: {dashes:?}");
                assert!(
                    (dashes[0].0 - lo).abs() <= 0.05
                        && (dashes[dashes.len() - 1].1 - hi).abs() <= 0.05,
                    "{side}: {dashes:?}"
                );
                for w in dashes.windows(2) {
                    let (dash, gap) = (w[0].1 - w[0].0, w[1].0 - w[0].1);
                    assert!(
                        (dash / (dash + gap) - SHARES[0][0]).abs() <= 0.05,
                        "{side}: dash {dash:.2} gap {gap:.2}: {dashes:?}"
                    );
                    assert!(
                        dash * pt >= 1.0 - 0.01 && gap * pt >= 0.8 - 0.01,
                        "{side}: dash {dash:.2} gap {gap:.2}: {dashes:?}"
                    );
                }
            }
            checked.push(from);
        }
        assert!(checked.contains(&"(d)"), "{form}: (d)'s map 1 not read");
    }
}
