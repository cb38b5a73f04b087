//! Affine transforms attached to primitives: rays go to object space with an
//! unnormalised direction (so `t` is shared by both spaces, also under non-uniform
//! scale); points and surface derivatives come back with the matrix (uv are
//! the same in both spaces), normals with the inverse transpose.

use nalgebra::Matrix3;

use super::SurfaceHit;
use crate::math::{Aabb, Matrix, Ray, transform_point, transform_vector};

#[derive(Clone, Debug)]
pub struct Transform {
    /// Object to world.
    pub matrix: Matrix,
    /// World to object.
    pub inverse: Matrix,
    /// Inverse transpose of the linear part (for normals).
    pub normal_matrix: Matrix3<f64>,
}

impl Transform {
    pub fn new(matrix: Matrix, inverse: Matrix) -> Self {
        let normal_matrix = inverse.fixed_view::<3, 3>(0, 0).transpose();
        Transform {
            matrix,
            inverse,
            normal_matrix,
        }
    }

    /// The transform `self` applied after `child` (`self.matrix * child.matrix`).
    pub fn compose(&self, child: &Transform) -> Transform {
        Transform::new(self.matrix * child.matrix, child.inverse * self.inverse)
    }

    pub fn is_identity(&self) -> bool {
        self.matrix == Matrix::identity()
    }

    /// The world ray in object space; `t` values are the same in both spaces.
    #[inline]
    pub fn ray_to_object(&self, ray: &Ray) -> Ray {
        Ray {
            origin: transform_point(&self.inverse, &ray.origin),
            direction: transform_vector(&self.inverse, &ray.direction),
            time: ray.time,
        }
    }

    /// An object-space surface hit moved to world space.
    pub fn surface_to_world(&self, hit: &SurfaceHit) -> SurfaceHit {
        let geometric_normal = super::normalize_or(
            self.normal_matrix * hit.geometric_normal,
            hit.geometric_normal,
        );
        let shading_normal =
            super::normalize_or(self.normal_matrix * hit.shading_normal, geometric_normal);
        let (dpdu, dpdv) = super::derivatives_or_fallback(
            transform_vector(&self.matrix, &hit.dpdu),
            transform_vector(&self.matrix, &hit.dpdv),
            &geometric_normal,
        );
        SurfaceHit {
            point: transform_point(&self.matrix, &hit.point),
            geometric_normal,
            shading_normal,
            dpdu,
            dpdv,
            uv: hit.uv,
            uv_mapping: hit.uv_mapping,
        }
    }

    pub fn bounds_to_world(&self, bounds: &Aabb) -> Aabb {
        bounds.transformed(&self.matrix)
    }
}
