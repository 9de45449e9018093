//! # shadow-aliasing
//!
//! The mathematics of perspective aliasing in shadow maps, from five papers, as one library.
#![forbid(unsafe_code)]

pub mod error;
pub mod frustum;
pub mod measure;

pub use error::{Error, Result};
pub use frustum::{LightAngle, NPrime, Resolutions, ViewFrustum};
