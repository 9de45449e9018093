//! The markers of line series: one shape per colour of the line palette and of the sweep, none
//! the mirror image or quarter turn of another.

use super::line::PALETTE;
use super::scheme::SWEEP;
use plotters::prelude::*;

/// The marker of a series, so that lines of different colours stay apart in greyscale: the
/// `i`-th colour of [`PALETTE`] has the `i`-th shape, the schemes' the shapes of the warps at
/// the same place in their set (no figure shows a warp beside a scheme). No shape is another's
/// mirror image or quarter turn (▲/▼, ▶/◀, a wide and a tall bar: the sixth figure review,
/// X-4, could not tell such pairs apart at print size).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Marker {
    Circle,
    Square,
    TriangleUp,
    Diamond,
    TallBar,
    Hexagon,
    /// The sweep's shapes ([`SWEEP`]), none of them a palette colour's.
    Star,
    Pentagon,
    Cross,
    /// A cross turned by 45° (×).
    Saltire,
    /// Two triangles meeting at a narrow waist, across (⋈).
    Bowtie,
}

impl Marker {
    /// The shapes of [`PALETTE`]'s colours, in its order.
    const ALL: [Marker; 9] = [
        Marker::Circle,
        Marker::Square,
        Marker::TriangleUp,
        Marker::Diamond,
        Marker::Circle,
        Marker::Square,
        Marker::TallBar,
        Marker::Hexagon,
        Marker::TriangleUp,
    ];

    /// The shapes of the sweep's colours, in [`SWEEP`]'s order.
    const SWEEP: [Marker; 5] = [
        Marker::Star,
        Marker::Pentagon,
        Marker::Cross,
        Marker::Saltire,
        Marker::Bowtie,
    ];

    /// The shape of a colour: the `i`-th of [`PALETTE`] gets the `i`-th shape, the `i`-th of
    /// [`SWEEP`] the `i`-th sweep shape, any other colour a circle.
    pub fn of(colour: RGBColor) -> Marker {
        if let Some(i) = SWEEP.iter().position(|&c| c == colour) {
            return Self::SWEEP[i];
        }
        PALETTE
            .iter()
            .position(|&c| c == colour)
            .map_or(Marker::Circle, |i| Self::ALL[i])
    }

    /// The marker's outline in pixels about its centre, for a radius `r`.
    pub fn outline(self, r: i32) -> Vec<(i32, i32)> {
        let ngon = |n: u32, phase: f64| -> Vec<(i32, i32)> {
            (0..n)
                .map(|k| {
                    let a = phase + f64::from(k) * std::f64::consts::TAU / f64::from(n);
                    (
                        (f64::from(r) * a.cos()).round() as i32,
                        (f64::from(r) * a.sin()).round() as i32,
                    )
                })
                .collect()
        };
        let h = r / 2;
        match self {
            Marker::Circle => ngon(12, 0.0),
            Marker::Square => vec![(-r, -r), (r, -r), (r, r), (-r, r)],
            Marker::TriangleUp => vec![(0, -r - 1), (r + 1, r), (-r - 1, r)],
            Marker::Diamond => vec![(0, -r - 1), (r + 1, 0), (0, r + 1), (-r - 1, 0)],
            Marker::TallBar => vec![(-h, -r - 1), (h, -r - 1), (h, r + 1), (-h, r + 1)],
            Marker::Hexagon => ngon(6, std::f64::consts::FRAC_PI_6),
            Marker::Pentagon => ngon(5, -std::f64::consts::FRAC_PI_2),
            Marker::Star => (0..10)
                .map(|k| {
                    let a =
                        -std::f64::consts::FRAC_PI_2 + f64::from(k) * std::f64::consts::PI / 5.0;
                    let rad = if k % 2 == 0 {
                        f64::from(r + 1)
                    } else {
                        0.45 * f64::from(r + 1)
                    };
                    (
                        (rad * a.cos()).round() as i32,
                        (rad * a.sin()).round() as i32,
                    )
                })
                .collect(),
            Marker::Cross => {
                let (o, t) = (r + 1, (r + 1) / 3 + 1);
                cross_corners(o, t).to_vec()
            }
            Marker::Saltire => {
                // The cross's arms along the diagonals: each corner of the cross turned by 45°.
                let (o, t) = (f64::from(r + 1), f64::from((r + 1) / 3 + 1));
                let turn = |x: f64, y: f64| {
                    let s = std::f64::consts::FRAC_1_SQRT_2;
                    (((x - y) * s).round() as i32, ((x + y) * s).round() as i32)
                };
                cross_corners(o, t)
                    .into_iter()
                    .map(|(x, y)| turn(x, y))
                    .collect()
            }
            Marker::Bowtie => {
                let (o, w) = (r + 1, (r + 1) / 3);
                vec![(-o, -o), (0, -w), (o, -o), (o, o), (0, w), (-o, o)]
            }
        }
    }
}

/// The twelve corners of a plus sign (+) with arms reaching `o` from its centre and `t` wide on
/// either side of their axis, in order round the outline.
fn cross_corners<T: Copy + std::ops::Neg<Output = T>>(o: T, t: T) -> [(T, T); 12] {
    [
        (-t, -o),
        (t, -o),
        (t, -t),
        (o, -t),
        (o, t),
        (t, t),
        (t, o),
        (-t, o),
        (-t, t),
        (-o, t),
        (-o, -t),
        (-t, -t),
    ]
}
