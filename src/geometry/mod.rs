//! Shapes and their ray intersection: a cheap `intersect` that finds the distance
//! and surface parameters, then `surface` that computes the local geometry of the
//! one hit that survives (point, normals, uv and the derivatives of the point
//! with respect to uv).

pub mod cambrian_rectangle;
pub mod cambrian_sphere;
pub mod cav_revolution;
pub mod cav_sphere;
pub mod curve;
pub mod disk;
pub mod jefflyy_revolution;
pub mod mesh;
pub mod plane;
pub mod profile_seeds;
pub mod rectangle;
pub mod revolution;
pub mod seeded_revolution;
pub mod shape;
mod shape_sampling;
pub mod single_precision;
pub mod sphere;
mod sphere_sampling;
pub mod surface_samples;
pub mod transform;
pub mod triangle;

use crate::math::{Point3, Vec3};

pub use cav_revolution::CavRevolution;
pub use curve::{Curve, CurveKind, Profile};
pub use disk::Disk;
pub use mesh::{Mesh, MeshData};
pub use plane::Plane;
pub use rectangle::Rectangle;
pub use revolution::{Revolution, RevolutionTest};
pub use seeded_revolution::SeededRevolution;
pub use shape::Shape;
pub use sphere::{Sphere, SphereTest};
pub use sphere_sampling::Cone;
pub use surface_samples::ShapeSample;
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
    /// Where the shape keeps that element, when it differs from `index`
    /// (a mesh's triangle in BVH leaf order); 0 otherwise.
    pub slot: u32,
}

impl Intersection {
    pub fn new(t: f64, u: f64, v: f64) -> Self {
        Intersection {
            t,
            u,
            v,
            index: 0,
            slot: 0,
        }
    }
}

/// How a hit's `uv` is meant to be read by a texture lookup.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UvMapping {
    /// `uv` in [0, 1]: clamped lookup.
    Unit,
    /// `uv` in texels of a tiled texture (planes: 10 texels per world unit).
    Tiled,
}

/// The local geometry at a hit, in the space of the shape that produced it.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceHit {
    pub point: Point3,
    /// Unit normal as modelled (outward for closed shapes), not flipped to the ray.
    pub geometric_normal: Vec3,
    /// Unit shading normal (interpolated for smooth meshes).
    pub shading_normal: Vec3,
    /// Partial derivatives of `point` with respect to `uv[0]` and `uv[1]`
    /// (not normalised; per texel where `uv` is in texels). Both are
    /// perpendicular to the geometric normal; where the parametrisation is
    /// singular (a sphere's poles, a disk's centre) they are finite fallbacks.
    pub dpdu: Vec3,
    pub dpdv: Vec3,
    pub uv: [f64; 2],
    pub uv_mapping: UvMapping,
}

/// Two unit vectors perpendicular to `normal` (and to each other), used as
/// surface derivatives where a shape's parametrisation has none.
pub(crate) fn fallback_derivatives(normal: &Vec3) -> (Vec3, Vec3) {
    crate::math::orthonormal_basis(normal)
}

/// `(dpdu, dpdv)`, with a zero or non-finite one replaced by a unit vector
/// perpendicular to `normal` (and to the other one, so that `dpdu x dpdv`
/// still points along `normal`).
pub(crate) fn derivatives_or_fallback(dpdu: Vec3, dpdv: Vec3, normal: &Vec3) -> (Vec3, Vec3) {
    let usable = |v: &Vec3| {
        let length = v.norm_squared();
        length > 0.0 && length.is_finite()
    };
    let (e1, e2) = match (usable(&dpdu), usable(&dpdv)) {
        (true, true) => return (dpdu, dpdv),
        (true, false) => (dpdu, normalize_or(normal.cross(&dpdu), Vec3::zeros())),
        (false, true) => (normalize_or(dpdv.cross(normal), Vec3::zeros()), dpdv),
        (false, false) => fallback_derivatives(normal),
    };
    if usable(&e1) && usable(&e2) {
        (e1, e2)
    } else {
        fallback_derivatives(normal)
    }
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
