//! Spheres, optionally moving linearly over the shutter interval (motion blur).

use std::f64::consts::PI;

use super::UvMapping;
use super::{
    Intersection, SurfaceHit, derivatives_or_fallback, fallback_derivatives, normalize_or,
};
use super::{cambrian_sphere, cav_sphere, single_precision};
use crate::math::{Aabb, Point3, Ray, Vec3};

/// The rules of a sphere's ray test.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SphereTest {
    /// The robust quadratic, points re-projected onto the sphere, rays
    /// leaving off the surface.
    #[default]
    Robust,
    /// Cambrian's (see [`cambrian_sphere`]): inside by the origin's
    /// distance, no far root from outside, the normal inwards from inside
    /// (an [`Intersection`]'s `u` is 1 for such a hit), and rays leaving
    /// from the hit point itself.
    Cambrian,
    /// emily-jia's (`emily-jia/graphic_homework:include/sphere.hpp`): the
    /// near root from outside, the far one from inside, found as a distance
    /// along the ray and used as the ray's parameter (they differ under a
    /// transform that scales the direction), the normal from that point,
    /// inwards from inside (`u` is 1); rays leave it offset as usual.
    DistanceAsParameter,
    /// W-Solaris's, in single precision ([`single_precision::sphere`]):
    /// the near root from `t_min` on (0 itself included), else the far
    /// one; the point and normal as the robust test's.
    SinglePrecision,
    /// cav's (see [`cav_sphere`]): its single-precision arithmetic, hits
    /// from 1e-4, the normal inwards from inside (`u` is 1), and rays
    /// leaving from the hit point (moved 1e-5 along their direction by
    /// the test itself).
    Cav,
}

#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    pub center: Point3,
    pub radius: f64,
    /// Displacement of the centre over the shutter interval: `center + motion * time`.
    pub motion: Vec3,
    pub test: SphereTest,
}

impl Sphere {
    pub fn new(center: Point3, radius: f64, motion: Vec3) -> Self {
        Sphere {
            center,
            radius: radius.abs(),
            motion,
            test: SphereTest::Robust,
        }
    }

    #[inline]
    pub fn center_at(&self, time: f64) -> Point3 {
        self.center + self.motion * time
    }

    /// Robust quadratic of "Ray Tracing Gems" ch. 7: the discriminant from the
    /// squared distance of the centre to the ray line, and the stable root pair.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        let center = self.center_at(ray.time);
        if self.test == SphereTest::Cambrian {
            let hit = cambrian_sphere::intersect(&center, self.radius, ray, t_min, t_max)?;
            return Some(Intersection::new(
                hit.t,
                f64::from(u8::from(hit.inside)),
                0.0,
            ));
        }
        if self.test == SphereTest::DistanceAsParameter {
            return self.intersect_by_distance(&center, ray, t_min, t_max);
        }
        if self.test == SphereTest::SinglePrecision {
            let t = single_precision::sphere(&center, self.radius, ray, t_min, t_max)?;
            return Some(Intersection::new(t, 0.0, 0.0));
        }
        if self.test == SphereTest::Cav {
            let hit = cav_sphere::intersect(&center, self.radius, ray, t_min, t_max)?;
            return Some(Intersection::new(
                hit.t,
                f64::from(u8::from(hit.inside)),
                0.0,
            ));
        }
        let f = ray.origin - center;
        let d = ray.direction;
        let a = d.norm_squared();
        if a == 0.0 {
            return None;
        }
        let b = -f.dot(&d); // half of the usual -b
        let c = f.norm_squared() - self.radius * self.radius;
        let perpendicular = f + d * (b / a);
        let discriminant = a * (self.radius * self.radius - perpendicular.norm_squared());
        if discriminant < 0.0 {
            return None;
        }
        let q = b + discriminant.sqrt().copysign(b);
        let (mut t0, mut t1) = if q == 0.0 { (0.0, 0.0) } else { (c / q, q / a) };
        if t0 > t1 {
            std::mem::swap(&mut t0, &mut t1);
        }
        let t = if t0 > t_min && t0 < t_max {
            t0
        } else if t1 > t_min && t1 < t_max {
            t1
        } else {
            return None;
        };
        Some(Intersection::new(t, 0.0, 0.0))
    }

    /// [`SphereTest::DistanceAsParameter`]'s test.
    fn intersect_by_distance(
        &self,
        center: &Point3,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
    ) -> Option<Intersection> {
        let length = ray.direction.norm();
        if length == 0.0 {
            return None;
        }
        let to_center = center - ray.origin;
        let l_sq = to_center.norm_squared();
        let r_sq = self.radius * self.radius;
        let projected = to_center.dot(&ray.direction) / length;
        let distance_sq = l_sq - projected * projected;
        if (l_sq > r_sq && projected < 0.0) || distance_sq > r_sq {
            return None;
        }
        let half_chord = (r_sq - distance_sq).sqrt();
        let t = if l_sq == r_sq {
            0.0
        } else if l_sq > r_sq {
            projected - half_chord
        } else {
            projected + half_chord
        };
        if t < t_min || t > t_max {
            return None;
        }
        Some(Intersection::new(t, f64::from(u8::from(l_sq < r_sq)), 0.0))
    }

    pub fn surface(&self, ray: &Ray, hit: &Intersection) -> SurfaceHit {
        let center = self.center_at(ray.time);
        let w = normalize_or(ray.at(hit.t) - center, Vec3::y());
        // Re-project onto the sphere: the point's error is then relative to |point|.
        let point = center + w * self.radius;
        let (point, normal) = self.as_computed(ray, hit, point, w);
        let u = 0.5 - w.z.atan2(w.x) / (2.0 * PI);
        let v = 0.5 + w.y.clamp(-1.0, 1.0).asin() / PI;
        // w = (cos lat cos phi, sin lat, cos lat sin phi) with phi = 2pi (1/2 - u)
        // and lat = pi (v - 1/2): dp/du = -2pi r dw/dphi, dp/dv = pi r dw/dlat.
        let cos_latitude = (w.x * w.x + w.z * w.z).sqrt();
        let dpdu = Vec3::new(w.z, 0.0, -w.x) * (2.0 * PI * self.radius);
        let dpdv = Vec3::new(-w.y * w.x, cos_latitude * cos_latitude, -w.y * w.z)
            * (PI * self.radius / cos_latitude);
        let (dpdu, dpdv) = derivatives_or_fallback(dpdu, dpdv, &w);
        SurfaceHit {
            point,
            geometric_normal: normal,
            shading_normal: normal,
            dpdu,
            dpdv,
            uv: [u, v],
            uv_mapping: UvMapping::Unit,
        }
    }

    /// [`Sphere::surface`] without uv and derivatives (uv left zero, the
    /// derivatives an orthonormal pair around the normal).
    pub fn surface_without_uv(&self, ray: &Ray, hit: &Intersection) -> SurfaceHit {
        let center = self.center_at(ray.time);
        let w = normalize_or(ray.at(hit.t) - center, Vec3::y());
        let (dpdu, dpdv) = fallback_derivatives(&w);
        let (point, normal) = self.as_computed(ray, hit, center + w * self.radius, w);
        SurfaceHit {
            point,
            geometric_normal: normal,
            shading_normal: normal,
            dpdu,
            dpdv,
            uv: [0.0, 0.0],
            uv_mapping: UvMapping::Unit,
        }
    }

    /// The hit point and geometric normal by the sphere's test, from the
    /// robust ones (`point` on the sphere, outward unit `normal`).
    #[inline]
    fn as_computed(
        &self,
        ray: &Ray,
        hit: &Intersection,
        point: Point3,
        normal: Vec3,
    ) -> (Point3, Vec3) {
        match self.test {
            SphereTest::Robust | SphereTest::SinglePrecision => (point, normal),
            SphereTest::Cambrian | SphereTest::DistanceAsParameter | SphereTest::Cav => {
                let point = ray.at(hit.t);
                let inside = hit.u != 0.0;
                (point, if inside { -normal } else { normal })
            }
        }
    }

    pub fn bounds(&self) -> Aabb {
        let r = Vec3::repeat(self.radius);
        let start = Aabb {
            min: self.center - r,
            max: self.center + r,
        };
        let end_center = self.center + self.motion;
        start.union(&Aabb {
            min: end_center - r,
            max: end_center + r,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_front_then_back() {
        let sphere = Sphere::new(Point3::zeros(), 2.0, Vec3::zeros());
        let ray = Ray::new(Point3::new(0.0, 0.0, -10.0), Vec3::new(0.0, 0.0, 2.0), 0.0);
        let hit = sphere.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 4.0).abs() < 1e-12);
        let back = sphere.intersect(&ray, 4.5, f64::INFINITY).unwrap();
        assert!((back.t - 6.0).abs() < 1e-12);
        let s = sphere.surface(&ray, &hit);
        assert!((s.geometric_normal - Vec3::new(0.0, 0.0, -1.0)).norm() < 1e-12);
        let plain = sphere.surface_without_uv(&ray, &hit);
        assert_eq!(plain.point, s.point);
        assert_eq!(plain.geometric_normal, s.geometric_normal);
    }

    #[test]
    fn moving_sphere_follows_time() {
        let sphere = Sphere::new(Point3::zeros(), 1.0, Vec3::new(10.0, 0.0, 0.0));
        let ray = Ray::new(Point3::new(10.0, 0.0, -5.0), Vec3::z(), 1.0);
        assert!(sphere.intersect(&ray, 0.0, f64::INFINITY).is_some());
        let early = Ray { time: 0.0, ..ray };
        assert!(sphere.intersect(&early, 0.0, f64::INFINITY).is_none());
        assert!(sphere.bounds().max.x >= 11.0);
    }

    #[test]
    fn far_away_small_sphere_is_hit_precisely() {
        let sphere = Sphere::new(Point3::new(0.0, 0.0, 1e6), 1e-2, Vec3::zeros());
        let ray = Ray::new(Point3::zeros(), Vec3::z(), 0.0);
        let hit = sphere.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - (1e6 - 1e-2)).abs() < 1e-9, "{}", hit.t);
    }
}
