//! Inputs shared by the benches.

include!("points.rs");
