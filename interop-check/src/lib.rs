//! The frame API driven from other glam versions (docs/renderer.md, "Uploading"): the tests in
//! `tests/` build the same frame from glam 0.32, glam 0.33 and the crate's own glam, through
//! mint and through plain column arrays, and compare every upload value bit for bit.
