//! Closed forms of the five papers, one file per geometry.

pub mod eta;
pub mod global;
pub mod overhead;
pub mod partition;
pub mod subdivided;
pub mod tilted;
pub mod tsm;
