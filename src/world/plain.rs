//! The plain shapes of a world, tested inline in tight loops: untransformed
//! planes always, untransformed spheres when the world is small enough to go
//! without a BVH. The walls and balls of most course scenes are exactly these,
//! and a loop over a few of them costs less than the dispatch and box tests
//! of the general path.

use crate::geometry::{Intersection, Plane, Sphere, SphereTest};
use crate::math::Ray;

/// Shapes with the indices of their primitives in the world.
#[derive(Clone, Debug, Default)]
pub struct PlainShapes {
    planes: Vec<(Plane, u32)>,
    /// Spheres of the robust test, tested inline.
    spheres: Vec<(Sphere, u32)>,
    /// Spheres of another test (a look's), by their own `intersect`.
    other_spheres: Vec<(Sphere, u32)>,
}

impl PlainShapes {
    pub fn push_plane(&mut self, plane: Plane, primitive: usize) {
        self.planes.push((plane, primitive as u32));
    }

    pub fn push_sphere(&mut self, sphere: Sphere, primitive: usize) {
        if sphere.test == SphereTest::Robust {
            self.spheres.push((sphere, primitive as u32));
        } else {
            self.other_spheres.push((sphere, primitive as u32));
        }
    }

    /// Lowers `limit` to the nearest hit in `(t_min, limit)` and records it
    /// (primitive index, intersection) in `best`.
    #[inline]
    pub fn nearest(
        &self,
        ray: &Ray,
        t_min: f64,
        limit: &mut f64,
        best: &mut Option<(usize, Intersection)>,
    ) {
        for (plane, index) in &self.planes {
            if let Some(hit) = plane.intersect(ray, t_min, *limit) {
                *limit = hit.t;
                *best = Some((*index as usize, hit));
            }
        }
        for (sphere, index) in &self.other_spheres {
            if let Some(hit) = sphere.intersect(ray, t_min, *limit) {
                *limit = hit.t;
                *best = Some((*index as usize, hit));
            }
        }
        if self.spheres.is_empty() {
            return;
        }
        let ray = PreparedRay::new(ray);
        for (sphere, index) in &self.spheres {
            if let Some(t) = ray.sphere_distance(sphere, t_min, *limit) {
                *limit = t;
                *best = Some((*index as usize, Intersection::new(t, 0.0, 0.0)));
            }
        }
    }

    /// Whether any shape lies on the ray within `(t_min, t_max)`.
    #[inline]
    pub fn any(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.planes
            .iter()
            .any(|(plane, _)| plane.intersect(ray, t_min, t_max).is_some())
            || (!self.spheres.is_empty() && {
                let ray = PreparedRay::new(ray);
                self.spheres
                    .iter()
                    .any(|(sphere, _)| ray.sphere_distance(sphere, t_min, t_max).is_some())
            })
            || self
                .other_spheres
                .iter()
                .any(|(sphere, _)| sphere.intersect(ray, t_min, t_max).is_some())
    }
}

/// A ray with what every sphere test of it shares.
struct PreparedRay<'a> {
    ray: &'a Ray,
    /// `|direction|^2` and its inverse.
    a: f64,
    inverse_a: f64,
}

impl<'a> PreparedRay<'a> {
    #[inline]
    fn new(ray: &'a Ray) -> Self {
        let a = ray.direction.norm_squared();
        PreparedRay {
            ray,
            a,
            inverse_a: 1.0 / a,
        }
    }

    /// [`Sphere::intersect`]'s distance (the same robust quadratic), with an
    /// early exit for spheres behind the ray's origin.
    #[inline(always)]
    fn sphere_distance(&self, sphere: &Sphere, t_min: f64, t_max: f64) -> Option<f64> {
        let f = self.ray.origin - sphere.center_at(self.ray.time);
        let d = &self.ray.direction;
        let b = -f.dot(d);
        let radius2 = sphere.radius * sphere.radius;
        let c = f.norm_squared() - radius2;
        // Origin outside and moving away: both roots negative.
        if c > 0.0 && b <= 0.0 && t_min >= 0.0 {
            return None;
        }
        let perpendicular = f + d * (b * self.inverse_a);
        let discriminant = self.a * (radius2 - perpendicular.norm_squared());
        // NaN: a zero direction.
        if discriminant.is_nan() || discriminant < 0.0 {
            return None;
        }
        let q = b + discriminant.sqrt().copysign(b);
        let (mut t0, mut t1) = if q == 0.0 {
            (0.0, 0.0)
        } else {
            (c / q, q * self.inverse_a)
        };
        if t0 > t1 {
            std::mem::swap(&mut t0, &mut t1);
        }
        if t0 > t_min && t0 < t_max {
            Some(t0)
        } else if t1 > t_min && t1 < t_max {
            Some(t1)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Point3, Vec3};
    use crate::rng::Rng;

    #[test]
    fn prepared_sphere_test_equals_the_sphere_s_own() {
        let mut rng = Rng::new(3, 4);
        let mut hits = 0;
        for _ in 0..20_000 {
            let mut random = |scale: f64| {
                Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * scale
                    - Vec3::repeat(scale / 2.0)
            };
            let sphere = Sphere::new(random(4.0), 0.1 + random(2.0).x.abs(), random(1.0));
            let origin: Point3 = random(8.0);
            // Aimed near the sphere, so that about half the rays hit it.
            let direction = (sphere.center + random(3.0) - origin) * (0.5 + random(1.0).x.abs());
            let ray = Ray::new(origin, direction, 0.7);
            let t_min = if hits % 3 == 0 { 0.0 } else { -0.5 };
            let expected = sphere.intersect(&ray, t_min, 50.0).map(|hit| hit.t);
            let got = PreparedRay::new(&ray).sphere_distance(&sphere, t_min, 50.0);
            match (expected, got) {
                (Some(a), Some(b)) => {
                    assert!((a - b).abs() <= 1e-9 * a.abs().max(1.0), "{a} vs {b}");
                    hits += 1;
                }
                (None, None) => {}
                other => panic!("{other:?} for {ray:?} and {sphere:?}"),
            }
        }
        assert!(hits > 2_000, "{hits} hits");
    }
}
