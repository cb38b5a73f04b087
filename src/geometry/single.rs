//! Single-precision arithmetic, as the renderers whose vectors are `float`
//! (the framework's `Vector3f`) compute: yangjunx21's planes and the points
//! its rays leave from. Rounding there decides whether a ray that leaves a
//! wall from the hit itself meets the wall again (see `Plane::intersect`).

use crate::math::{Point3, Ray, Vec3};

/// `v` rounded to single precision.
#[inline]
pub fn single(v: &Vec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

/// `a . b` in single precision, summed from x to z (as `Vector3f::dot`).
#[inline]
pub fn dot(a: &[f32; 3], b: &[f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The point at `t` on `ray`, `origin + t direction` computed in single
/// precision from the ray's values rounded to it.
#[inline]
pub fn point_at(ray: &Ray, t: f64) -> Point3 {
    let origin = single(&ray.origin);
    let direction = single(&ray.direction);
    let t = t as f32;
    let [x, y, z]: [f32; 3] = std::array::from_fn(|i| origin[i] + t * direction[i]);
    Point3::new(f64::from(x), f64::from(y), f64::from(z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_is_rounded_to_single_precision_at_every_step() {
        let ray = Ray::new(
            Point3::new(50.0, 52.0, 290.6),
            Vec3::new(0.0, 1.0, 0.0),
            0.0,
        );
        let p = point_at(&ray, 29.6);
        assert_eq!(p.y, f64::from(52.0f32 + 29.6f32));
        assert_ne!(p.y, 52.0 + 29.6, "not the double-precision sum");
        assert_eq!(p.z, f64::from(290.6f32));
    }
}
