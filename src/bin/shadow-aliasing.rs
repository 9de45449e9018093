//! The `shadow-aliasing` command line (being written).
fn main() {}
