//! Cambrian's sphere test (`../shared/docs/looks.md`, cambrian-pathtracer;
//! its `include/sphere.hpp` and `src/main.cpp`), which the `cambrian` look
//! keeps because its glass balls depend on it:
//!
//! - the ray's origin is *inside* when its squared distance to the centre
//!   is below `r^2`; from inside, the hit is the far root and its normal
//!   points **inwards**; from outside, only the near root counts (a ray
//!   whose near root lies behind it misses the sphere);
//! - hits count beyond a distance of 1e-8, and a ray leaves a surface from
//!   the hit point itself, which lies a rounding error inside or outside.
//!
//! So a ray refracted into a glass ball from a point that rounds outside
//! finds no far root and crosses the ball unbent, and one from a point
//! that rounds inside meets the far side with an inward normal, which the
//! glass takes for an entry (it bends by 1/n where n is due). Half of the
//! paths through a ball take each way: Cambrian's glass looks frosted and
//! its caustics are broad rings. Rays that leave a diffuse or mirror ball
//! outwards meet it again only at distances far below 1e-8, so those
//! surfaces look as ours do. With this test `sample_rec`'s glass ball and
//! caustic match Cambrian's render (look-alike at 160 px and 256 spp: mean
//! 2.2, p95 6 against 4.0 / 19.0 with our exact sphere).
//!
//! The arithmetic is f64: the float version of the same formulas (rounding
//! errors of ~1e-5 at scene scale) traps rays in diffuse balls, which
//! Cambrian's renders do not show.

use crate::math::{Point3, Ray};

/// Cambrian's smallest accepted hit distance.
pub const MIN_DISTANCE: f64 = 1e-8;

/// Where a ray meets the sphere by Cambrian's test: the distance, and
/// whether the ray started inside (then the normal points inwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CambrianHit {
    pub t: f64,
    pub inside: bool,
}

/// The hit of `ray` with the sphere (`center`, `radius`) in
/// `(max(t_min, 1e-8), t_max)` by Cambrian's test.
#[inline]
pub fn intersect(
    center: &Point3,
    radius: f64,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<CambrianHit> {
    let to_center = center - ray.origin;
    let length = ray.direction.norm();
    if length == 0.0 || !length.is_finite() {
        return None;
    }
    let squared = to_center.norm_squared();
    let radius_squared = radius * radius;
    let inside = squared < radius_squared;
    if !inside && squared == radius_squared {
        return None;
    }
    let along = to_center.dot(&ray.direction) / length;
    if !inside && along < 0.0 {
        return None;
    }
    let off_axis = (squared - along * along).sqrt();
    if !inside && off_axis > radius {
        return None;
    }
    let half_chord = (radius_squared - off_axis * off_axis).sqrt();
    let t = if inside {
        (along + half_chord) / length
    } else {
        (along - half_chord) / length
    };
    // NaN (a negative square root from rounding) fails both tests.
    (t > t_min.max(MIN_DISTANCE) && t < t_max).then_some(CambrianHit { t, inside })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec3;
    use crate::rng::Rng;

    #[test]
    fn hits_from_outside_and_from_inside_with_the_side_it_started() {
        let center = Point3::new(0.5, -1.0, 2.0);
        let outside = Ray::new(Point3::new(0.5, -1.0, -8.0), Vec3::z() * 2.0, 0.0);
        let hit = intersect(&center, 2.0, &outside, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 4.0).abs() < 1e-12 && !hit.inside, "{hit:?}");
        let from_centre = Ray::new(center, Vec3::new(0.0, 0.6, 0.8), 0.0);
        let hit = intersect(&center, 2.0, &from_centre, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 2.0).abs() < 1e-12 && hit.inside, "{hit:?}");
        let away = Ray::new(Point3::new(0.5, -1.0, -8.0), -Vec3::z(), 0.0);
        assert_eq!(intersect(&center, 2.0, &away, 0.0, f64::INFINITY), None);
    }

    /// The rules the look is for, on rays refracted into the sphere at the
    /// point where they entered: from a point that rounds outside, the ray
    /// misses the sphere (no far root from outside); from one that rounds
    /// inside, it meets the far side with the inside flag. Both happen.
    #[test]
    fn a_ray_leaving_its_entry_point_inwards_crosses_unbent_or_meets_the_far_side_from_inside() {
        let center = Point3::new(27.0, 16.5, 47.0);
        let radius = 16.5;
        let camera = Point3::new(50.0, 52.0, 295.6);
        let mut rng = Rng::new(11, 5);
        let (mut missed, mut far) = (0, 0);
        for _ in 0..2000 {
            let jitter = Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64());
            let target = center + (jitter - Vec3::repeat(0.5)) * 20.0;
            let ray = Ray::new(camera, (target - camera).normalize(), 0.0);
            let Some(hit) = intersect(&center, radius, &ray, 0.0, f64::INFINITY) else {
                continue;
            };
            assert!(!hit.inside);
            let point = ray.at(hit.t);
            let inward = (center - point).normalize();
            let refracted = Ray::new(point, (inward + ray.direction).normalize(), 0.0);
            let rounds_inside = (center - point).norm_squared() < radius * radius;
            match intersect(&center, radius, &refracted, 0.0, f64::INFINITY) {
                None => {
                    assert!(!rounds_inside);
                    missed += 1;
                }
                Some(next) => {
                    assert!(rounds_inside && next.inside && next.t > 1.0, "{next:?}");
                    far += 1;
                }
            }
        }
        assert!(missed > 200 && far > 200, "missed {missed}, far side {far}");
    }

    /// Rays leaving a ball outwards from a point of its surface never meet
    /// it again: diffuse and mirror balls look as ours do.
    #[test]
    fn a_ray_leaving_a_surface_point_outwards_does_not_meet_the_sphere() {
        let center = Point3::new(73.0, 16.5, 78.0);
        let radius = 16.5;
        let mut rng = Rng::new(2, 9);
        for _ in 0..5000 {
            let normal = Vec3::new(
                rng.next_f64() - 0.5,
                rng.next_f64() - 0.5,
                rng.next_f64() - 0.5,
            )
            .normalize();
            let point = center + normal * radius;
            let out = (normal + Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 0.5)
                .normalize();
            if out.dot(&normal) <= 0.0 {
                continue;
            }
            let ray = Ray::new(point, out, 0.0);
            assert_eq!(intersect(&center, radius, &ray, 0.0, f64::INFINITY), None);
        }
    }
}
