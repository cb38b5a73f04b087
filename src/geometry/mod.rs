//! Shapes and their ray intersection: a cheap `intersect` that finds the distance
//! and surface parameters, then `surface` that computes the local frame of the one
//! hit that survives.

pub mod curve;
pub mod disk;
pub mod mesh;
pub mod plane;
pub mod profile_seeds;
pub mod rectangle;
pub mod revolution;
pub mod shape;
pub mod sphere;
pub mod transform;
pub mod triangle;

use crate::math::{Point3, Vec3};
use crate::world::UvMapping;

pub use curve::Curve;
pub use disk::Disk;
pub use mesh::Mesh;
pub use plane::Plane;
pub use rectangle::Rectangle;
pub use revolution::Revolution;
pub use shape::Shape;
pub use sphere::Sphere;
pub use transform::Transform;
pub use triangle::Triangle;

/// The result of the cheap intersection phase: the ray distance and the shape's
/// own surface parameters (barycentrics, (u, theta), ...) plus an element index
/// (triangle of a mesh), enough for `surface` to finish the job.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Intersection {
    pub t: f64,
    pub u: f64,
    pub v: f64,
    pub index: u32,
}

impl Intersection {
    pub fn new(t: f64, u: f64, v: f64) -> Self {
        Intersection { t, u, v, index: 0 }
    }
}

/// The local geometry at a hit, in the space of the shape that produced it.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceHit {
    pub point: Point3,
    /// Unit normal as modelled (outward for closed shapes), not flipped to the ray.
    pub geometric_normal: Vec3,
    /// Unit shading normal (interpolated for smooth meshes).
    pub shading_normal: Vec3,
    /// Unit tangent along increasing u.
    pub tangent: Vec3,
    pub uv: [f64; 2],
    pub uv_mapping: UvMapping,
}

/// A unit vector perpendicular to `normal`, used when a shape has no natural tangent.
pub(crate) fn fallback_tangent(normal: &Vec3) -> Vec3 {
    crate::math::orthonormal_basis(normal).0
}

/// `v` normalised, or `fallback` when `v` is zero or not finite.
pub(crate) fn normalize_or(v: Vec3, fallback: Vec3) -> Vec3 {
    let length = v.norm();
    if length > 0.0 && length.is_finite() {
        v / length
    } else {
        fallback
    }
}
