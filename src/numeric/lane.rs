//! A lane type for code written once and run on one value or on four: `f64` for the scalar
//! builders and measurement, [`F4`] (four `f64`, one per light direction) for the hemisphere
//! sweep. Every operation is one IEEE operation per lane, in the order the code writes it (no
//! reassociation, no fused multiply-add), so a lane of [`F4`] is the `f64` code's value bit for
//! bit by construction (docs/performance.md, "Code-generation notes", for what the compiler makes
//! of it).

use glam::DVec3;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// One value per lane, with the arithmetic the shared code uses.
pub(crate) trait Lane:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// One flag per lane.
    type Mask: Copy;
    /// The same value in every lane.
    fn splat(v: f64) -> Self;
    /// `√x` per lane.
    fn sqrt(self) -> Self;
    /// `|x|` per lane.
    fn abs(self) -> Self;
    /// The crate's `fmin`, `if a < b { a } else { b }`.
    fn min(self, o: Self) -> Self;
    /// The crate's `fmax`, `if a > b { a } else { b }`.
    fn max(self, o: Self) -> Self;
    /// `a > b` per lane (false for NaN).
    fn gt(self, o: Self) -> Self::Mask;
    /// `a ≥ b` per lane (false for NaN).
    fn ge(self, o: Self) -> Self::Mask;
    /// `a < b` per lane (false for NaN).
    fn lt(self, o: Self) -> Self::Mask;
    /// `a ≤ b` per lane (false for NaN).
    fn le(self, o: Self) -> Self::Mask;
    /// Whether every lane is exactly 0 (so a caller may take the scalar code's shortcut for 0,
    /// whose values are the general path's).
    fn all_zero(self) -> bool;
    /// `x` finite per lane.
    fn finite(self) -> Self::Mask;
    /// The flag that is set in every lane.
    fn all_set() -> Self::Mask;
    /// Both flags per lane.
    fn and(a: Self::Mask, b: Self::Mask) -> Self::Mask;
    /// `if m { a } else { b }` per lane.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
}

impl Lane for f64 {
    type Mask = bool;
    #[inline(always)]
    fn splat(v: f64) -> Self {
        v
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        crate::numeric::fmin(self, o)
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        crate::numeric::fmax(self, o)
    }
    #[inline(always)]
    fn gt(self, o: Self) -> bool {
        self > o
    }
    #[inline(always)]
    fn ge(self, o: Self) -> bool {
        self >= o
    }
    #[inline(always)]
    fn lt(self, o: Self) -> bool {
        self < o
    }
    #[inline(always)]
    fn le(self, o: Self) -> bool {
        self <= o
    }
    #[inline(always)]
    fn all_zero(self) -> bool {
        self == 0.0
    }
    #[inline(always)]
    fn finite(self) -> bool {
        self.is_finite()
    }
    #[inline(always)]
    fn all_set() -> bool {
        true
    }
    #[inline(always)]
    fn and(a: bool, b: bool) -> bool {
        a && b
    }
    #[inline(always)]
    fn select(m: bool, a: Self, b: Self) -> Self {
        if m {
            a
        } else {
            b
        }
    }
}

/// Lanes per [`F4`].
pub(crate) const LANES: usize = 4;

/// Four `f64`, one per lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct F4(pub(crate) [f64; LANES]);

impl F4 {
    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> Self {
        F4(self.0.map(f))
    }
    #[inline(always)]
    fn zip(self, o: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        F4(std::array::from_fn(|i| f(self.0[i], o.0[i])))
    }
    #[inline(always)]
    fn test(self, f: impl Fn(f64) -> bool) -> M4 {
        let b = |i: usize| if f(self.0[i]) { !0u64 } else { 0 };
        M4([b(0), b(1), b(2), b(3)])
    }
    #[inline(always)]
    fn cmp(self, o: Self, f: impl Fn(f64, f64) -> bool) -> M4 {
        let b = |i: usize| if f(self.0[i], o.0[i]) { !0u64 } else { 0 };
        M4([b(0), b(1), b(2), b(3)])
    }
}

/// One flag per lane of [`F4`], all bits set or clear (so that `and` is one `andpd` per two
/// lanes, where `[bool; 4]` is packed and unpacked around every operation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct M4(pub(crate) [u64; LANES]);

impl M4 {
    /// The flags as booleans.
    #[inline(always)]
    pub(crate) fn to_bools(self) -> [bool; LANES] {
        [
            self.0[0] != 0,
            self.0[1] != 0,
            self.0[2] != 0,
            self.0[3] != 0,
        ]
    }
}

impl Lane for F4 {
    type Mask = M4;
    #[inline(always)]
    fn splat(v: f64) -> Self {
        F4([v; LANES])
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        self.map(f64::sqrt)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        self.map(f64::abs)
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        self.zip(o, <f64 as Lane>::min)
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        self.zip(o, <f64 as Lane>::max)
    }
    #[inline(always)]
    fn gt(self, o: Self) -> Self::Mask {
        self.cmp(o, |a, b| a > b)
    }
    #[inline(always)]
    fn ge(self, o: Self) -> Self::Mask {
        self.cmp(o, |a, b| a >= b)
    }
    #[inline(always)]
    fn lt(self, o: Self) -> Self::Mask {
        self.cmp(o, |a, b| a < b)
    }
    #[inline(always)]
    fn le(self, o: Self) -> Self::Mask {
        self.cmp(o, |a, b| a <= b)
    }
    #[inline(always)]
    fn all_zero(self) -> bool {
        self.0.iter().all(|&v| v == 0.0)
    }
    #[inline(always)]
    fn finite(self) -> Self::Mask {
        self.test(|x| x.abs() < f64::INFINITY)
    }
    #[inline(always)]
    fn all_set() -> Self::Mask {
        M4([!0; LANES])
    }
    #[inline(always)]
    fn and(a: Self::Mask, b: Self::Mask) -> Self::Mask {
        M4([
            a.0[0] & b.0[0],
            a.0[1] & b.0[1],
            a.0[2] & b.0[2],
            a.0[3] & b.0[3],
        ])
    }
    #[inline(always)]
    fn select(m: Self::Mask, a: Self, b: Self) -> Self {
        let s =
            |i: usize| f64::from_bits((a.0[i].to_bits() & m.0[i]) | (b.0[i].to_bits() & !m.0[i]));
        F4([s(0), s(1), s(2), s(3)])
    }
}

macro_rules! lane_op {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for F4 {
            type Output = F4;
            #[inline(always)]
            fn $f(self, o: F4) -> F4 {
                self.zip(o, |a, b| a $op b)
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl Neg for F4 {
    type Output = F4;
    #[inline(always)]
    fn neg(self) -> F4 {
        self.map(|a| -a)
    }
}

/// A 3-vector of lanes with glam's `DVec3` arithmetic in glam's order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct V3<T> {
    pub(crate) x: T,
    pub(crate) y: T,
    pub(crate) z: T,
}

impl<T: Lane> V3<T> {
    /// `(x, y, z)`.
    #[inline(always)]
    pub(crate) fn new(x: T, y: T, z: T) -> Self {
        Self { x, y, z }
    }
    /// The same vector in every lane.
    #[inline(always)]
    pub(crate) fn splat(v: DVec3) -> Self {
        Self::new(T::splat(v.x), T::splat(v.y), T::splat(v.z))
    }
    /// `(x·x + y·y) + z·z`, glam's `dot`.
    #[inline(always)]
    pub(crate) fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    /// glam's `cross`.
    #[inline(always)]
    pub(crate) fn cross(self, o: Self) -> Self {
        Self::new(
            self.y * o.z - o.y * self.z,
            self.z * o.x - o.z * self.x,
            self.x * o.y - o.x * self.y,
        )
    }
    /// `self − (self·l) l` (glam's `self - self.dot(l) * l`).
    #[inline(always)]
    pub(crate) fn perp(self, l: Self) -> Self {
        let s = self.dot(l);
        self - l.scale(s)
    }
    /// `self · s` per component (glam's `v * s`).
    #[inline(always)]
    pub(crate) fn scale(self, s: T) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
    /// `self / s` per component (glam's `v / s`).
    #[inline(always)]
    pub(crate) fn div(self, s: T) -> Self {
        Self::new(self.x / s, self.y / s, self.z / s)
    }
    /// `√(self·self)`, glam's `length`.
    #[inline(always)]
    pub(crate) fn length(self) -> T {
        self.dot(self).sqrt()
    }
}

impl<T: Lane> Add for V3<T> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<T: Lane> Sub for V3<T> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<T: Lane> Neg for V3<T> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl From<DVec3> for V3<f64> {
    #[inline(always)]
    fn from(v: DVec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<V3<f64>> for DVec3 {
    #[inline(always)]
    fn from(v: V3<f64>) -> Self {
        DVec3::new(v.x, v.y, v.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each lane of every `F4` operation is the `f64` operation's value bit for bit, NaN and
    /// signed zero included (min/max follow `fmin`/`fmax`: the second operand on ties and NaN).
    #[test]
    fn f4_lanes_are_the_f64_operations() {
        let vals = [
            1.5,
            -0.0,
            0.0,
            f64::NAN,
            f64::INFINITY,
            -3.25e-300,
            7e300,
            2.0,
        ];
        for a in vals.windows(4) {
            for b in vals.windows(4).rev() {
                let (x, y) = (F4([a[0], a[1], a[2], a[3]]), F4([b[0], b[1], b[2], b[3]]));
                type Op = fn(f64, f64) -> f64;
                let ops: [(F4, Op); 6] = [
                    (x + y, |a, b| a + b),
                    (x - y, |a, b| a - b),
                    (x * y, |a, b| a * b),
                    (x / y, |a, b| a / b),
                    (x.min(y), <f64 as Lane>::min),
                    (x.max(y), <f64 as Lane>::max),
                ];
                for (got, f) in ops {
                    for i in 0..LANES {
                        assert_eq!(got.0[i].to_bits(), f(x.0[i], y.0[i]).to_bits());
                    }
                }
                for i in 0..LANES {
                    assert_eq!(x.sqrt().0[i].to_bits(), x.0[i].sqrt().to_bits());
                    assert_eq!((-x).0[i].to_bits(), (-x.0[i]).to_bits());
                    assert_eq!(x.gt(y).to_bools()[i], x.0[i] > y.0[i]);
                    assert_eq!(x.ge(y).to_bools()[i], x.0[i] >= y.0[i]);
                    assert_eq!(x.lt(y).to_bools()[i], x.0[i] < y.0[i]);
                    assert_eq!(x.le(y).to_bools()[i], x.0[i] <= y.0[i]);
                    assert_eq!(x.finite().to_bools()[i], x.0[i].is_finite());
                }
            }
        }
        // glam's order for the vector operations.
        let (a, b) = (DVec3::new(0.3, -1.7, 2.9), DVec3::new(1e-3, 4.0, -0.25));
        let (va, vb) = (V3::from(a), V3::from(b));
        assert_eq!(DVec3::from(va.cross(vb)), a.cross(b));
        assert_eq!(va.dot(vb), a.dot(b));
        assert_eq!(DVec3::from(va.perp(vb)), a - a.dot(b) * b);
        assert_eq!(va.length(), a.length());
    }
}
