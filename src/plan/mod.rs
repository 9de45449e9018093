//! Shadows planned by their error (issue 24): choices a renderer makes once per camera cut or per
//! frame, made from the measured error of the frame's maps rather than hard-coded.
//!
//! - [`allocate`]: each map's resolution for a texel budget or an atlas, the largest error least
//!   (Lloyd 2005 Eq 6 generalised), or the cheapest for a target error.
//! - [`planner`]: the cheapest scheme (single maps, TSM, cascades, stable cascades, face
//!   partitions, the clipmap) that meets a target error, or the least error within a texel budget, every
//!   candidate ([`candidates`]) measured over the scene's focus body.
//! - Error-equalising cascade splits live with the frame that measures them:
//!   [`CascadeSplits::EqualError`](crate::frame::CascadeSplits::EqualError).
//!
//! docs/planning.md describes them.

pub mod allocate;
pub mod candidates;
pub mod clipmap;
pub mod controller;
pub mod planner;

pub use controller::{Controller, ControllerOptions, Decision};
pub use planner::{plan, plan_among, Candidate, Goal, Measured, Plan};
