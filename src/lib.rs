//! # shadow-aliasing
//!
//! The mathematics of perspective aliasing in shadow maps, from five papers, as one tested
//! library: the closed-form error of warped and partitioned shadow maps, the matrices a renderer
//! builds from it every frame, and a numeric ground truth that checks both.
//!
//! # The model in one page
//!
//! A directional light's shadow map samples the scene with light beams, one per texel; the camera
//! samples it with image beams, one per pixel. Where a light beam is wider than the image beam it
//! meets, its texel shows as a jagged shadow edge. The *perspective aliasing error* is that ratio
//! of widths, in each shadow-map direction: `m_x` along s and `m_z` along t (Lloyd et al. 2006
//! Eq 7, 8; Zhang et al.'s `E_q`, `E_p` are the same ratios on a `[−1, 1]` screen, twice as large).
//! Its maximum over the view frustum, `M_x` and `M_z`, bounds the error for any scene, and the
//! product `S̄ = M_x M_z` is the *storage factor*: how many times more texels than pixels a map
//! needs to show no perspective aliasing anywhere (Lloyd 2006 Eq 12).
//!
//! The crate's layers, in the order data flows:
//!
//! 1. [`frustum`]: validated inputs ([`ViewFrustum`], [`NPrime`], [`Resolutions`],
//!    [`LightAngle`]); every constructor returns [`Result`] with an [`Error`] that names the
//!    argument.
//! 2. [`analytic`] (with [`analytic::eta`], the warp parameter n′ ↔ η): the closed forms of the five papers, in one notation
//!    (docs/notation.md), each citing its paper and equation, corrected where the paper is wrong
//!    (docs/errata.md).
//! 3. [`maps`]: the matrices a renderer needs (uniform, LiSPSM with every n′ rule, the crate's
//!    minimax, trapezoidal, cascades, stable cascades, face partitions, an atlas), eye space →
//!    light clip space, in both clip-depth conventions, without heap allocation.
//!    [`geom`] holds the plane geometry they share (homography, convex hull, polytopes).
//! 4. [`measure`]: the ground truth. The error of *any* shadow matrix at any point, from the exact
//!    derivatives of the projective map; its maximum over the frustum; the storage factor over the
//!    hemisphere of light directions. Every closed form has a numeric twin here, and the tests hold
//!    each closed form to its twin to a relative 1e-9.
//! 5. [`scheme`]: a scheme's partitions built and measured together, and the hemisphere sweep.
//! 6. [`frame`]: **the renderer's call, once per light per frame**, in world space: the camera,
//!    the light, the scene's receivers and casters in, every map's world → clip matrix, splits,
//!    blend bands, culling volumes, bias and measured error out, with the GPU record and the WGSL
//!    lookup module (docs/renderer.md). Start here to put the crate in a renderer:
//!    [`frame::frame`], [`frame::FrameInput`].
//! 7. [`plan`]: choices made from the measured error: the cheapest set-up for a target error, the
//!    least error for a texel budget, texel allocation, clipmap levels (docs/planning.md).
//! 8. `plot` (feature `plot`) and the `shadow-aliasing` command line (feature `cli`): the papers'
//!    figures, JSON evaluation for CI pipelines in any language, matrices, plans and sweeps.
//!
//! # Conventions
//!
//! Eye space is right-handed, the camera at the origin looking down −Z, Y up (glam's
//! `look_at_rh`); the depth of a point `p` is `z = −p.z`. Angles are in radians; `half_fov` is half
//! the vertical field of view. A light direction is the direction light travels, in eye space.
//! Shadow matrices map eye space to light clip space with x, y ∈ [−1, 1] over the map; depth in
//! [−1, 1] (OpenGL), [0, 1] (Vulkan, wgpu, D3D) or reversed [1, 0] (1 nearest the light) by
//! [`maps::ClipDepth`]. All analysis is `f64`;
//! [`maps::ShadowMatrix::to_mat4`] gives `f32` for the GPU.
//!
//! # Example
//!
//! ```
//! use glam::DVec3;
//! use shadow_aliasing::{analytic::overhead, maps, measure, NPrime, Resolutions, ViewFrustum};
//!
//! let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
//! // Closed form: LiSPSM's storage factor for the light overhead (Lloyd 2006 Eq 12).
//! let n_prime = NPrime::finite(view.n_prime_lispsm())?;
//! let predicted = overhead::storage_factor(&view, n_prime)?;
//! // The same map built as a matrix, and its error measured from exact derivatives.
//! let light = DVec3::new(0.0, -1.0, 0.0);
//! let map = maps::warp(&view, light, maps::WarpRule::Lispsm)?;
//! let measured = measure::frustum_max(&view, &map.shadow_map())?;
//! assert!((measured.storage_factor - predicted).abs() < 1e-9 * predicted);
//! # let _ = Resolutions::default();
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```
//!
//! # References
//!
//! - B. Lloyd, S.-E. Yoon, D. Tuft, D. Manocha. *Subdivided Shadow Maps*. UNC TR05-024, 2005.
//! - T. Martin, T.-S. Tan. *Anti-aliasing and Continuity with Trapezoidal Shadow Maps*. EGSR 2004.
//! - B. Lloyd, D. Tuft, S.-E. Yoon, D. Manocha. *Warping and Partitioning for Low Error Shadow
//!   Maps*. EGSR 2006.
//! - J. Barroso, W. Celes. *Improved Real-Time Shadow Mapping for CAD Models*. SIBGRAPI 2007.
//! - F. Zhang, C. Zhao, H. Sun. *An Aliasing Theory of Shadow Mapping*. 2009.
//!
//! Each paper has known errors; docs/errata.md lists every one the crate found, with numbers.
// No unsafe code; the one exception is the `bytemuck` feature's derived `Pod`/`Zeroable` impls
// of `frame::GpuShadowMap` (allowed in that module alone), so the lint is `deny` there.
#![cfg_attr(not(feature = "bytemuck"), forbid(unsafe_code))]
#![cfg_attr(feature = "bytemuck", deny(unsafe_code))]

pub mod analytic;
pub mod error;
#[cfg(feature = "cli")]
pub mod eval;
pub mod frame;
pub mod frustum;
pub mod geom;
pub mod maps;
pub mod measure;
pub mod numeric;
pub mod plan;
#[cfg(feature = "plot")]
pub mod plot;
pub mod scheme;

pub use error::{Error, Result};
pub use frustum::{LightAngle, LightDir, NPrime, Resolutions, ViewFrustum};

/// The glam the crate's API speaks (0.34), re-exported so a renderer on another glam version can
/// name these types without a second dependency line and convert at the boundary: through plain
/// arrays (`glam::DMat4::from_cols_array_2d(&m.to_cols_array_2d())`, and every upload value as
/// arrays, [`frame::FrameMap::world_to_clip_cols`]) or through the `mint` crate (feature `mint`).
pub use glam;

/// The mint version whose types the `mint` feature's conversions take and give (glam's own
/// `mint-05` conversions: `glam::DMat4: From<mint::ColumnMatrix4<f64>>`, and back).
#[cfg(feature = "mint")]
pub use mint;

/// The README's Rust example, compiled and run as a doc-test by `cargo test` in every feature
/// set, so that the README cannot drift from the API.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

/// docs/renderer.md's frame loop, compiled as a doc-test for the same reason.
#[doc = include_str!("../docs/renderer.md")]
#[cfg(doctest)]
pub struct RendererGuideDoctests;

/// docs/planning.md's examples (equal-error splits, texel allocation, the planner, the controller),
/// compiled as doc-tests.
#[doc = include_str!("../docs/planning.md")]
#[cfg(doctest)]
pub struct PlanningDoctests;
