//! `replay --figure FILE.svg`: the measured error and the texels of each frame, the target drawn
//! across the error, the cuts marked: a plain SVG (no embedded font; text in DejaVu Sans or the
//! viewer's sans-serif).

use crate::output::sig;
use std::fmt::Write as _;

const W: f64 = 900.0;
const PANEL: f64 = 220.0;
const LEFT: f64 = 90.0;
const RIGHT: f64 = 20.0;
const TOP: f64 = 40.0;
const GAP: f64 = 60.0;

/// One frame as the figure draws it.
pub struct Point {
    /// The measured largest error, pixels.
    pub error: f64,
    /// The texels.
    pub texels: u64,
    /// The frame was a cut.
    pub cut: bool,
}

/// One panel: `values` against the frame index, from 0 to `top`, at `y0` (its top edge).
fn panel(s: &mut String, values: &[f64], top: f64, y0: f64, label: &str, colour: &str) {
    let n = values.len();
    let x = |i: usize| LEFT + (W - LEFT - RIGHT) * i as f64 / (n.max(2) - 1) as f64;
    let y = |v: f64| y0 + PANEL * (1.0 - v / top);
    let _ = writeln!(
        s,
        r##"<rect x="{LEFT}" y="{y0}" width="{}" height="{PANEL}" fill="none" stroke="#000"/>"##,
        W - LEFT - RIGHT
    );
    for f in [0.0, 0.5, 1.0] {
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{:.1}" text-anchor="end" font-size="12">{}</text>"#,
            LEFT - 6.0,
            y(f * top) + 4.0,
            sig(f * top)
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="20" y="{:.1}" font-size="13" transform="rotate(-90 20 {:.1})" text-anchor="middle">{label}</text>"#,
        y0 + PANEL / 2.0,
        y0 + PANEL / 2.0
    );
    let mut pts = String::new();
    for (i, v) in values.iter().enumerate() {
        let _ = write!(pts, "{:.2},{:.2} ", x(i), y(*v));
    }
    let _ = writeln!(
        s,
        r#"<polyline class="series" fill="none" stroke="{colour}" stroke-width="1.5" points="{}"/>"#,
        pts.trim_end()
    );
}

/// The figure for `points` (at least one) against `target` pixels and `budget` texels (each
/// drawn as a dashed line where given).
pub fn svg(points: &[Point], target: Option<f64>, budget: Option<u64>, title: &str) -> String {
    let n = points.len();
    let h = TOP + 2.0 * PANEL + GAP + 40.0;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{h}" viewBox="0 0 {W} {h}" font-family="DejaVu Sans, sans-serif">"#
    );
    let _ = writeln!(s, r##"<rect width="{W}" height="{h}" fill="#fff"/>"##);
    let _ = writeln!(
        s,
        r#"<text x="{}" y="24" text-anchor="middle" font-size="14">{}</text>"#,
        W / 2.0,
        escape(title)
    );
    let errors: Vec<f64> = points.iter().map(|p| p.error).collect();
    let texels: Vec<f64> = points.iter().map(|p| p.texels as f64 / 1e6).collect();
    let etop = 1.1 * errors.iter().copied().fold(target.unwrap_or(0.0), f64::max);
    let budget_m = budget.map(|b| b as f64 / 1e6);
    let ttop = 1.1
        * texels
            .iter()
            .copied()
            .fold(budget_m.unwrap_or(0.0), f64::max);
    let x = |i: usize| LEFT + (W - LEFT - RIGHT) * i as f64 / (n.max(2) - 1) as f64;
    // The cuts, across both panels.
    for (i, _) in points.iter().enumerate().filter(|(_, p)| p.cut) {
        let _ = writeln!(
            s,
            r##"<line class="cut" x1="{0:.2}" x2="{0:.2}" y1="{TOP}" y2="{1}" stroke="#bbb"/>"##,
            x(i),
            TOP + 2.0 * PANEL + GAP
        );
    }
    panel(&mut s, &errors, etop, TOP, "error (px)", "#0072b2");
    if let Some(target) = target {
        let ty = TOP + PANEL * (1.0 - target / etop);
        limit(&mut s, "target", ty, &format!("target {} px", sig(target)));
    }
    panel(
        &mut s,
        &texels,
        ttop,
        TOP + PANEL + GAP,
        "texels (M)",
        "#009e73",
    );
    if let Some(b) = budget_m {
        let by = TOP + PANEL + GAP + PANEL * (1.0 - b / ttop);
        limit(&mut s, "budget", by, &format!("budget {} M texels", sig(b)));
    }
    let base = TOP + 2.0 * PANEL + GAP;
    for (i, anchor) in [(0, "start"), (n - 1, "end")] {
        let _ = writeln!(
            s,
            r#"<text x="{:.2}" y="{}" text-anchor="{anchor}" font-size="12">{i}</text>"#,
            x(i),
            base + 16.0
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle" font-size="13">frame (grey lines: cuts)</text>"#,
        LEFT + (W - LEFT - RIGHT) / 2.0,
        base + 32.0
    );
    s.push_str("</svg>\n");
    s
}

/// A dashed limit line of class `class` across a panel at height `y`, labelled `label`.
fn limit(s: &mut String, class: &str, y: f64, label: &str) {
    let _ = writeln!(
        s,
        r##"<line class="{class}" x1="{LEFT}" x2="{}" y1="{y:.2}" y2="{y:.2}" stroke="#d55e00" stroke-dasharray="6 4"/>"##,
        W - RIGHT
    );
    let _ = writeln!(
        s,
        r##"<text x="{}" y="{:.1}" text-anchor="end" font-size="12" fill="#d55e00">{}</text>"##,
        W - RIGHT - 4.0,
        y - 4.0,
        escape(label)
    );
}

fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
