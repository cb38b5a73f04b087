//! Cambrian's rectangle test (`Cambrian-yzt/PathTracer:include/plane.hpp`,
//! class `Rectangle`, at the commit of its `focus_on_*` renders), which the
//! `cambrian` look keeps because its textured walls and floors depend on it:
//!
//! - the ray meets the rectangle's plane (two-sided) at
//!   `t = (n . point - n . o) / (n . d / |d|) / |d|`, with `n` the unit
//!   `x cross y`, beyond a distance of 1e-8;
//! - the hit point `o + d t` is kept only when each of its coordinates
//!   lies between those of `point` and `point + x + y`, both included.
//!
//! On an axis-aligned rectangle the box is flat along the normal, so a hit
//! counts only when the point's coordinate along the normal rounds exactly
//! onto the plane's. For the rays of Cambrian's `focus_on_earth` about one
//! in eight hits on the back wall and one in four on the floor do not (a
//! simulation of its camera rays with these formulas in f64): the ray goes
//! on through the wall as if it had a hole there. Its back wall, with
//! nothing behind it but the dark space between the side planes, looks
//! darker than a solid one.
//!
//! The arithmetic is f64, as Cambrian's sphere test's
//! ([`super::cambrian_sphere`]).

use crate::math::{Point3, Ray, Vec3};

/// Cambrian's smallest accepted hit distance.
pub const MIN_DISTANCE: f64 = 1e-8;

/// The distance at which `ray` meets the rectangle `point + s x + t y`
/// (s, t in [0, 1]) by Cambrian's test, in `(max(t_min, 1e-8), t_max)`.
#[inline]
pub fn intersect(
    point: &Point3,
    x: &Vec3,
    y: &Vec3,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<f64> {
    let cross = x.cross(y);
    let normal = cross / cross.norm();
    let length = ray.direction.norm();
    if ray.direction.dot(&normal) == 0.0 || length == 0.0 || !length.is_finite() {
        return None;
    }
    let unit = ray.direction / length;
    // Cambrian's plane keeps -(n . point) and adds n . o to it.
    let offset = -normal.dot(point);
    let t = -(offset + normal.dot(&ray.origin)) / normal.dot(&unit) / length;
    if !(t > t_min.max(MIN_DISTANCE) && t < t_max) {
        return None;
    }
    let hit = ray.origin + ray.direction * t;
    let far = point + x + y;
    let inside = (0..3).all(|axis| {
        let (low, high) = (point[axis].min(far[axis]), point[axis].max(far[axis]));
        hit[axis] >= low && hit[axis] <= high
    });
    inside.then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn back_wall() -> (Point3, Vec3, Vec3) {
        (
            Point3::new(1.0, 0.0, 0.0),
            Vec3::new(98.0, 0.0, 0.0),
            Vec3::new(0.0, 81.6, 0.0),
        )
    }

    #[test]
    fn a_ray_along_an_axis_meets_the_wall() {
        let (point, x, y) = back_wall();
        let ray = Ray::new(Point3::new(50.0, 40.0, 295.0), -Vec3::z(), 0.0);
        let t = intersect(&point, &x, &y, &ray, 0.0, f64::INFINITY).unwrap();
        assert_eq!(t, 295.0);
        let beside = Ray::new(Point3::new(100.0, 40.0, 295.0), -Vec3::z(), 0.0);
        assert!(intersect(&point, &x, &y, &beside, 0.0, f64::INFINITY).is_none());
    }

    #[test]
    fn oblique_rays_pass_through_a_flat_box_when_their_hit_rounds_off_the_plane() {
        // Rays from a camera 295 in front of the wall towards points spread
        // over it: each meets the wall by Cambrian's test exactly when its
        // hit point's z rounds to 0, which is neither always nor never.
        let (point, x, y) = back_wall();
        let origin = Point3::new(50.3, 52.7, 295.1);
        let (mut kept, mut total) = (0, 0);
        for i in 0..40 {
            for j in 0..40 {
                let target = Point3::new(2.0 + 2.4 * i as f64, 1.0 + 2.0 * j as f64, 0.0);
                let direction = (target - origin).normalize();
                let ray = Ray::new(origin, direction, 0.0);
                let hit = intersect(&point, &x, &y, &ray, 0.0, f64::INFINITY);
                let t = 295.1 / -direction.z;
                total += 1;
                match hit {
                    Some(found) => {
                        kept += 1;
                        assert!((found - t).abs() < 1e-9 * t);
                        assert_eq!(ray.at(found).z, 0.0);
                    }
                    // Lost only by rounding: the point lies within the
                    // wall's sides, a rounding error off its plane.
                    None => {
                        let p = ray.at(t);
                        assert!(p.x > 1.0 && p.x < 99.0 && p.y > 0.0 && p.y < 81.6);
                        assert!(p.z.abs() < 1e-12);
                    }
                }
            }
        }
        let share = kept as f64 / total as f64;
        assert!(share > 0.5 && share < 0.99, "{kept} of {total}");
    }
}
