//! Flat disks given by centre, normal and radius.

use std::f64::consts::PI;

use super::UvMapping;
use super::{Intersection, SurfaceHit, derivatives_or_fallback};
use crate::math::{Aabb, Point3, Ray, Vec3, orthonormal_basis};

#[derive(Clone, Copy, Debug)]
pub struct Disk {
    pub center: Point3,
    /// Unit normal.
    pub normal: Vec3,
    pub radius: f64,
    frame: (Vec3, Vec3),
}

impl Disk {
    /// `None` for a zero normal or a non-positive radius.
    pub fn new(center: Point3, normal: Vec3, radius: f64) -> Option<Disk> {
        let length = normal.norm();
        if !(length > 0.0 && length.is_finite() && radius > 0.0) {
            return None;
        }
        let normal = normal / length;
        Some(Disk {
            center,
            normal,
            radius,
            frame: orthonormal_basis(&normal),
        })
    }

    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        let denominator = self.normal.dot(&ray.direction);
        if denominator == 0.0 {
            return None;
        }
        let t = self.normal.dot(&(self.center - ray.origin)) / denominator;
        if !(t > t_min && t < t_max) {
            return None;
        }
        let local = ray.at(t) - self.center;
        let x = local.dot(&self.frame.0);
        let y = local.dot(&self.frame.1);
        (x * x + y * y <= self.radius * self.radius).then(|| Intersection::new(t, x, y))
    }

    /// uv = (angle / 2pi, r / radius): `dpdu` runs along the circle
    /// (2pi r long), `dpdv` outwards (radius long); at the centre, where the
    /// angle has no derivative, they are a fallback pair.
    pub fn surface(&self, _ray: &Ray, hit: &Intersection) -> SurfaceHit {
        let (e1, e2) = self.frame;
        let (x, y) = (hit.u, hit.v);
        let angle = y.atan2(x).rem_euclid(2.0 * PI);
        let r = (x * x + y * y).sqrt();
        let (sin, cos) = angle.sin_cos();
        let dpdu = (e2 * cos - e1 * sin) * (2.0 * PI * r);
        let dpdv = (e1 * cos + e2 * sin) * self.radius;
        let (dpdu, dpdv) = derivatives_or_fallback(dpdu, dpdv, &self.normal);
        SurfaceHit {
            point: self.center + e1 * x + e2 * y,
            geometric_normal: self.normal,
            shading_normal: self.normal,
            dpdu,
            dpdv,
            uv: [angle / (2.0 * PI), r / self.radius],
            uv_mapping: UvMapping::Unit,
        }
    }

    pub fn bounds(&self) -> Aabb {
        // Extent along axis i is radius * sqrt(1 - n_i^2).
        let n = self.normal;
        let extent = Vec3::new(
            (1.0 - n.x * n.x).max(0.0).sqrt(),
            (1.0 - n.y * n.y).max(0.0).sqrt(),
            (1.0 - n.z * n.z).max(0.0).sqrt(),
        ) * self.radius;
        Aabb {
            min: self.center - extent,
            max: self.center + extent,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inside_and_outside_radius() {
        let disk = Disk::new(Point3::zeros(), Vec3::new(0.0, 0.0, 3.0), 1.0).unwrap();
        let inside = Ray::new(Point3::new(0.5, 0.5, 1.0), -Vec3::z(), 0.0);
        let outside = Ray::new(Point3::new(0.8, 0.8, 1.0), -Vec3::z(), 0.0);
        assert!(disk.intersect(&inside, 0.0, f64::INFINITY).is_some());
        assert!(disk.intersect(&outside, 0.0, f64::INFINITY).is_none());
        assert!(disk.bounds().max.z.abs() < 1e-12);
    }
}
