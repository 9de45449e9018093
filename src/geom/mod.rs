//! Plane geometry and convex bodies the builders share: the four-point homography onto the unit
//! square, the convex hull of points in the plane, and convex polytopes bounded by planes. No
//! shadow-map knowledge lives here.

pub mod homography;
pub(crate) mod hull;
pub mod polytope;
