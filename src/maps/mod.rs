//! Renderer-facing shadow matrices.
//!
//! A renderer gives its camera (eye space: right-handed, looking down −Z, Y up) and a directional
//! light; the builders return [`ShadowMatrix`]: eye space → light clip space, with the warp
//! parameter used and the depth range covered, in both clip-depth conventions ([`ClipDepth`]).
//!
//! - [`light_space`]: the frame every map is built in (Lloyd 2006 §4).
//! - [`fit_warp`]: the core construction, a perspective warp along the light-space z axis with
//!   parameter n′ fitted around a point set (orthographic for n′ = ∞).
//! - [`warp()`] / [`n_prime_for`]: the single-map builders, n′ chosen by a [`WarpRule`] (η, PSM,
//!   LiSPSM and its 1/sin γ rule, Barroso & Celes, TSM's focus rule, the LiSPSM reference code,
//!   Filament, OGRE, and the crate's minimax).
//!
//! ```
//! use shadow_aliasing::maps::{warp, ClipDepth, WarpRule};
//! use shadow_aliasing::measure::frustum_max;
//! use shadow_aliasing::ViewFrustum;
//! use glam::DVec3;
//!
//! let view = ViewFrustum::new(0.5, 200.0, 35f64.to_radians())?;
//! let s = warp(&view, DVec3::new(0.3, -0.8, -0.4), WarpRule::default())?;
//! let gpu = s.to_mat4(ClipDepth::ZeroToOne); // for a Vulkan/wgpu shader
//! let err = frustum_max(&view, &s.shadow_map())?; // M_x, M_z, S̄ of what was built
//! assert!(err.storage_factor > 0.0 && gpu.is_finite());
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

pub mod atlas;
pub mod cascades;
pub mod faces;
pub mod fit;
pub mod lightspace;
pub mod matrix;
pub mod minimax;
pub mod tsm;
pub mod uniform;
pub mod warp;

pub use lightspace::{light_space, LightSpace};
pub use matrix::{ClipDepth, ShadowMatrix};
pub use tsm::{tsm, TsmMap, TsmOptions, TsmSearch};
pub use uniform::{uniform, with_casters, CasterDepth};
pub use warp::{fit_warp, n_prime_for, warp, Falloff, WarpRule};
