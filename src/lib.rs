//! # shadow-aliasing
//!
//! The mathematics of perspective aliasing in shadow maps, from five papers, as one library.
#![forbid(unsafe_code)]

pub mod analytic;
pub mod build;
pub mod error;
#[cfg(feature = "cli")]
pub mod eval;
pub mod frustum;
pub mod measure;
#[cfg(feature = "plot")]
pub mod plot;
pub mod warp;

pub use error::{Error, Result};
pub use frustum::{LightAngle, NPrime, Resolutions, ViewFrustum};
