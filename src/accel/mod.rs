//! Acceleration structures for ray queries.

pub mod bvh;
pub mod huge_pages;
pub mod triangles;

pub use bvh::Bvh;
pub use triangles::LeafTriangles;
