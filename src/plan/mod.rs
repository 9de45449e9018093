//! Shadows planned by their error (issue 24): choices a renderer makes once per camera cut or per
//! frame, made from the measured error of the frame's maps rather than hard-coded.
//!
//! - [`allocate`]: each map's resolution for a texel budget or an atlas, the largest error least
//!   (Lloyd 2005 Eq 6 generalised).
//! - Error-equalising cascade splits live with the frame that measures them:
//!   [`CascadeSplits::EqualError`](crate::frame::CascadeSplits::EqualError).
//!
//! docs/planning.md describes both.

pub mod allocate;
