//! The renderable world: the scene's object tree flattened into primitives with
//! a BVH over the bounded ones. Answers the two ray queries of the integrators.

use crate::math::{Aabb, Point3, Ray, Vec3};
use crate::scene::model::Scene;

/// How a hit's `uv` is meant to be read by a texture lookup.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UvMapping {
    /// `uv` in [0, 1]: clamped lookup.
    Unit,
    /// `uv` in texels of a tiled texture (planes: 10 texels per world unit).
    Tiled,
}

/// A ray's nearest hit, in world space.
#[derive(Clone, Copy, Debug)]
pub struct WorldHit {
    pub t: f64,
    pub point: Point3,
    /// Unit normal of the surface as modelled (outward for closed shapes); not
    /// flipped towards the ray.
    pub geometric_normal: Vec3,
    /// Unit interpolated normal (meshes with normals), else the geometric one.
    pub shading_normal: Vec3,
    /// Unit tangent along increasing u (for normal maps).
    pub tangent: Vec3,
    pub uv: [f64; 2],
    pub uv_mapping: UvMapping,
    pub material: usize,
}

/// The flattened scene geometry.
pub struct World {}

impl World {
    pub fn build(_scene: &Scene) -> World {
        todo!("geometry helper")
    }

    /// The nearest hit with `t_min < t < t_max`.
    pub fn intersect(&self, _ray: &Ray, _t_min: f64, _t_max: f64) -> Option<WorldHit> {
        todo!("geometry helper")
    }

    /// Whether anything lies on the ray with `t_min < t < t_max`.
    pub fn occluded(&self, _ray: &Ray, _t_min: f64, _t_max: f64) -> bool {
        todo!("geometry helper")
    }

    /// Bounds of the bounded primitives (planes excluded).
    pub fn bounds(&self) -> Aabb {
        todo!("geometry helper")
    }
}
