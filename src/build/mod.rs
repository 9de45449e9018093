//! Renderer-facing shadow matrices.

pub mod atlas;
pub mod cascades;
pub mod faces;
