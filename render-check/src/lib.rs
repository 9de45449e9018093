//! render-check: shadow-aliasing's matrices drawn by a real rasterizer (wgpu on Vulkan; Debian's
//! lavapipe where there is no GPU), the error seen on screen compared with
//! `measure::surface_footprint`, and every shadow compared with an exact ray cast.
//! docs/rendered.md describes what is measured and the scene format.

pub mod analysis;
pub mod blend;
pub mod compute;
pub mod faults;
pub mod geometry;
pub mod gpu;
pub mod images;
pub mod lens;
pub mod lloyd_level;
pub mod options;
pub mod overlay;
pub mod paper_error;
pub mod papers;
pub mod paths;
pub mod perspective;
pub mod pool;
pub mod ratios;
pub mod run;
pub mod scene;
pub mod schemes;
pub mod self_test;
pub mod shadows;
pub mod snap;
pub mod targets;
pub mod volumes;
pub mod warpfit;
