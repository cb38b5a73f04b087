//! Geometric vocabulary shared by every stage: vectors, points, rays and boxes.

use nalgebra::{Matrix4, Vector3};

/// A direction or offset in 3D (f64: Newton iteration and ray offsets need it).
pub type Vec3 = Vector3<f64>;
/// A position in 3D. Kept as a vector type so that the arithmetic stays simple.
pub type Point3 = Vector3<f64>;
/// A homogeneous 4x4 transform.
pub type Matrix = Matrix4<f64>;

/// A ray `origin + t * direction` at a time within the shutter interval `[0, 1]`.
/// `direction` is not necessarily unit length (object-space rays are not).
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    pub origin: Point3,
    pub direction: Vec3,
    pub time: f64,
}

impl Ray {
    pub fn new(origin: Point3, direction: Vec3, time: f64) -> Self {
        Ray {
            origin,
            direction,
            time,
        }
    }

    pub fn at(&self, t: f64) -> Point3 {
        self.origin + self.direction * t
    }
}

/// An axis-aligned bounding box. The empty box has `min > max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Point3,
    pub max: Point3,
}

impl Aabb {
    pub fn empty() -> Self {
        Aabb {
            min: Vec3::repeat(f64::INFINITY),
            max: Vec3::repeat(f64::NEG_INFINITY),
        }
    }

    pub fn from_point(p: Point3) -> Self {
        Aabb { min: p, max: p }
    }

    pub fn include_point(&self, p: Point3) -> Self {
        Aabb {
            min: self.min.inf(&p),
            max: self.max.sup(&p),
        }
    }

    pub fn union(&self, other: &Aabb) -> Self {
        Aabb {
            min: self.min.inf(&other.min),
            max: self.max.sup(&other.max),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y || self.min.z > self.max.z
    }

    pub fn centroid(&self) -> Point3 {
        (self.min + self.max) * 0.5
    }

    pub fn extent(&self) -> Vec3 {
        self.max - self.min
    }

    pub fn surface_area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let e = self.extent();
        2.0 * (e.x * e.y + e.y * e.z + e.z * e.x)
    }

    /// The box that holds this box after an affine transform (all 8 corners).
    pub fn transformed(&self, matrix: &Matrix) -> Self {
        let mut out = Aabb::empty();
        for i in 0..8 {
            let corner = Vec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            );
            out = out.include_point(transform_point(matrix, &corner));
        }
        out
    }

    /// Slab test: the entry distance if the ray meets the box within `(t_min, t_max)`.
    /// `inverse_direction` is `1 / ray.direction` per component.
    #[inline]
    pub fn hit_distance(
        &self,
        origin: &Point3,
        inverse_direction: &Vec3,
        t_min: f64,
        t_max: f64,
    ) -> Option<f64> {
        self.clip(origin, inverse_direction, t_min, t_max)
            .map(|(near, _)| near)
    }

    /// Slab test returning the clipped parameter interval `(near, far)` of the ray
    /// inside the box, within `(t_min, t_max)`.
    #[inline]
    pub fn clip(
        &self,
        origin: &Point3,
        inverse_direction: &Vec3,
        t_min: f64,
        t_max: f64,
    ) -> Option<(f64, f64)> {
        let (near, far) = self.slabs(origin, inverse_direction, t_min, t_max);
        if near <= far { Some((near, far)) } else { None }
    }

    /// The ray's parameter interval inside the box's three slabs and
    /// `(t_min, t_max)`, empty when `near > far`. A ray parallel to an axis
    /// with its origin on one of the box's faces there (`0 * inf`, NaN)
    /// lies in that slab for every `t`.
    #[inline]
    pub fn slabs(
        &self,
        origin: &Point3,
        inverse_direction: &Vec3,
        t_min: f64,
        t_max: f64,
    ) -> (f64, f64) {
        let mut near = t_min;
        let mut far = t_max;
        for axis in 0..3 {
            let t0 = (self.min[axis] - origin[axis]) * inverse_direction[axis];
            let t1 = (self.max[axis] - origin[axis]) * inverse_direction[axis];
            if t0.is_nan() || t1.is_nan() {
                continue;
            }
            near = near.max(t0.min(t1));
            far = far.min(t0.max(t1));
        }
        (near, far)
    }

    /// The box grown by `margin` on every side.
    pub fn expanded(&self, margin: f64) -> Self {
        Aabb {
            min: self.min - Vec3::repeat(margin),
            max: self.max + Vec3::repeat(margin),
        }
    }

    /// Whether all coordinates are finite and `min <= max`.
    pub fn is_valid(&self) -> bool {
        self.min
            .iter()
            .chain(self.max.iter())
            .all(|c| c.is_finite())
            && !self.is_empty()
    }
}

/// Relative size of the offset applied by [`offset_origin`] (2^-40, about 4000 ulps).
pub const OFFSET_SCALE: f64 = 1.0 / (1u64 << 40) as f64;

/// Where to start a ray spawned from a surface point so that it does not hit the
/// surface it leaves.
///
/// The point is moved along the geometric normal `normal` (unit, either side) to the
/// side that `direction` goes to, by `OFFSET_SCALE * (max |p_i| + 1e-3 * OFFSET_SCALE)`:
/// a distance relative to the magnitude of the coordinates, which bounds the
/// rounding error of a hit point reconstructed from surface parameters (and of
/// transforming it between object and world space). It is scale-free: objects of
/// size 1e-3 or placed at 1e5 behave alike. Rays spawned this way may use `t_min = 0`.
#[inline]
pub fn offset_origin(point: &Point3, normal: &Vec3, direction: &Vec3) -> Point3 {
    let magnitude = point.amax();
    let distance = OFFSET_SCALE * magnitude + 1e-3 * OFFSET_SCALE * OFFSET_SCALE;
    if normal.dot(direction) >= 0.0 {
        point + normal * distance
    } else {
        point - normal * distance
    }
}

/// How far a shadow ray from `origin` (spawned off its surface by
/// [`offset_origin`]) towards `point`, a point on another surface, may
/// reach without finding that surface: the distance from `origin` itself,
/// less `shortening` of it and [`OFFSET_SCALE`] of `point`'s magnitude (its
/// rounding). Measured from the shading point instead, the reach would
/// overshoot by the origin's offset, which far from the scene's origin
/// (1e7) outgrows a relative shortening: the shadow ray would find the
/// light it aims at.
#[inline]
pub fn shadow_reach(origin: &Point3, point: &Point3, shortening: f64) -> f64 {
    let distance = (point - origin).norm();
    distance * (1.0 - shortening) - OFFSET_SCALE * point.amax()
}

/// `1 / direction` per component (`±inf` for zero components, never NaN).
#[inline]
pub fn inverse_direction(direction: &Vec3) -> Vec3 {
    direction.map(|c| 1.0 / c)
}

/// Applies the affine part of `matrix` to a point.
#[inline]
pub fn transform_point(matrix: &Matrix, p: &Point3) -> Point3 {
    matrix.fixed_view::<3, 3>(0, 0) * p + matrix.fixed_view::<3, 1>(0, 3)
}

/// Applies the linear part of `matrix` to a direction.
#[inline]
pub fn transform_vector(matrix: &Matrix, v: &Vec3) -> Vec3 {
    matrix.fixed_view::<3, 3>(0, 0) * v
}

/// Two unit vectors completing `n` to a right-handed orthonormal frame
/// (Duff et al., "Building an Orthonormal Basis, Revisited", 2017).
#[inline]
pub fn orthonormal_basis(n: &Vec3) -> (Vec3, Vec3) {
    let sign = 1.0_f64.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        Vec3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ray_along_a_face_of_a_box_is_inside_that_slab() {
        let unit = Aabb {
            min: Point3::new(0.0, 0.0, 0.0),
            max: Point3::new(1.0, 1.0, 1.0),
        };
        // Along x, in the plane of the face y = 0: 0 * inf is NaN there.
        let origin = Point3::new(-1.0, 0.0, 0.5);
        let inverse = inverse_direction(&Vec3::new(1.0, 0.0, 0.0));
        assert_eq!(
            unit.clip(&origin, &inverse, 0.0, f64::INFINITY),
            Some((1.0, 2.0))
        );
        // Parallel to y but beside the box: outside for every t.
        let beside = Point3::new(2.0, -1.0, 0.5);
        let up = inverse_direction(&Vec3::new(0.0, 1.0, 0.0));
        assert_eq!(unit.clip(&beside, &up, 0.0, f64::INFINITY), None);
    }
}
