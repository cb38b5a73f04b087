//! Acceleration structures for ray queries.

pub mod bvh;

pub use bvh::Bvh;
