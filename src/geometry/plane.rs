//! Infinite planes `normal . p = offset` with a tiled uv frame derived from the normal.

use super::UvMapping;
use super::single_precision;
use super::{Intersection, SurfaceHit};
use crate::math::{Point3, Ray, Vec3, orthonormal_basis};

/// Texels per world unit of the tiled plane mapping (the original's default).
pub const PLANE_TILING: f64 = 10.0;

#[derive(Clone, Copy, Debug)]
pub struct Plane {
    /// Unit normal.
    pub normal: Vec3,
    /// Signed distance of the plane from the origin along `normal`.
    pub offset: f64,
    /// Deterministic texture frame (e1, e2) from the normal.
    frame: (Vec3, Vec3),
    /// Hit only by rays that travel against the normal (W-Solaris's planes).
    pub one_sided: bool,
    /// Hit at the distance `t_min` itself too (W-Solaris's planes accept
    /// `t >= 0`: a ray that leaves from a point lying exactly on the plane
    /// finds it again at distance 0, and again, as long as it travels
    /// against the normal).
    pub accepts_zero: bool,
    /// Tested by W-Solaris's test in single precision
    /// ([`single_precision::plane`]: one-sided, and hit at `t_min` too,
    /// whatever `one_sided` and `accepts_zero` say).
    pub single_precision: bool,
    /// Tested by yangjunx21's test in single precision
    /// ([`single_precision::plane_two_sided`]: from either side).
    pub single_precision_two_sided: bool,
}

impl Plane {
    /// `None` when the normal is zero or not finite.
    pub fn new(normal: Vec3, offset: f64) -> Option<Plane> {
        let length = normal.norm();
        if !(length > 0.0 && length.is_finite() && offset.is_finite()) {
            return None;
        }
        let normal = normal / length;
        Some(Plane {
            normal,
            offset: offset / length,
            frame: orthonormal_basis(&normal),
            one_sided: false,
            accepts_zero: false,
            single_precision: false,
            single_precision_two_sided: false,
        })
    }

    /// The plane with cav's uv frame (`CaveSpiderLZJ/PathTracingFinal:include/plane.hpp`):
    /// `w1 = normalize(a x n)`, `a` the y axis when `n.x > 0.1` and the x
    /// axis otherwise, `w2 = n x w1`, and (u, v) = (p . w2, p . w1). A
    /// normal along -x, where cav's `w1` is not a number, keeps ours.
    pub fn with_cav_frame(mut self) -> Plane {
        let n = self.normal;
        let a = if n.x > 0.1 { Vec3::y() } else { Vec3::x() };
        if let Some(w1) = a.cross(&n).try_normalize(1e-12) {
            self.frame = (n.cross(&w1), w1);
        }
        self
    }

    /// The hit with `t_min < t < t_max`, or by W-Solaris's or yangjunx21's
    /// test in single precision when the plane has one.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        if self.single_precision {
            let t = single_precision::plane(&self.normal, self.offset, ray, t_min, t_max)?;
            return Some(Intersection::new(t, 0.0, 0.0));
        }
        if self.single_precision_two_sided {
            let t =
                single_precision::plane_two_sided(&self.normal, self.offset, ray, t_min, t_max)?;
            return Some(Intersection::new(t, 0.0, 0.0));
        }
        let denominator = self.normal.dot(&ray.direction);
        if denominator == 0.0 || (self.one_sided && denominator > 0.0) {
            return None;
        }
        let t = (self.offset - self.normal.dot(&ray.origin)) / denominator;
        let beyond_start = t > t_min || (self.accepts_zero && t == t_min);
        (beyond_start && t < t_max).then(|| Intersection::new(t, 0.0, 0.0))
    }

    pub fn surface(&self, ray: &Ray, hit: &Intersection) -> SurfaceHit {
        let raw: Point3 = ray.at(hit.t);
        // Project onto the plane so the point's error is relative to |point|.
        let point = raw - self.normal * (self.normal.dot(&raw) - self.offset);
        let (e1, e2) = self.frame;
        SurfaceHit {
            point,
            geometric_normal: self.normal,
            shading_normal: self.normal,
            // uv = PLANE_TILING * (p . e1, p . e2): per texel, p moves 1/PLANE_TILING.
            dpdu: e1 * (1.0 / PLANE_TILING),
            dpdv: e2 * (1.0 / PLANE_TILING),
            uv: [PLANE_TILING * point.dot(&e1), PLANE_TILING * point.dot(&e2)],
            uv_mapping: UvMapping::Tiled,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_and_offset_are_normalised_together() {
        let plane = Plane::new(Vec3::new(0.0, 2.0, 0.0), 4.0).unwrap();
        let ray = Ray::new(Point3::new(0.3, 10.0, 0.1), -Vec3::y(), 0.0);
        let hit = plane.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 8.0).abs() < 1e-12);
        assert!(Plane::new(Vec3::zeros(), 1.0).is_none());
    }

    #[test]
    fn a_plane_that_accepts_zero_is_met_again_from_a_point_on_it() {
        let mut plane = Plane::new(Vec3::y(), -4.0).unwrap();
        plane.one_sided = true;
        let down = Ray::new(Point3::new(0.3, -4.0, 1.7), Vec3::new(0.2, -1.0, 0.1), 0.0);
        assert!(plane.intersect(&down, 0.0, f64::INFINITY).is_none());
        plane.accepts_zero = true;
        let hit = plane.intersect(&down, 0.0, f64::INFINITY).unwrap();
        assert_eq!(hit.t, 0.0);
        // Leaving along the normal, a one-sided plane is not met at all.
        let up = Ray::new(down.origin, Vec3::y(), 0.0);
        assert!(plane.intersect(&up, 0.0, f64::INFINITY).is_none());
    }

    #[test]
    fn a_single_precision_plane_is_met_again_from_a_point_rounded_behind_it() {
        // yangjunx21's ceiling: y = 81.6 seen from below (normal 0 -1 0).
        let mut plane = Plane::new(-Vec3::y(), -81.6).unwrap();
        plane.single_precision_two_sided = true;
        let direction = Vec3::new(0.22425672220619774, 1.0, -0.1953505739617607);
        let up = Ray::new(Point3::new(50.0, 20.0, 290.6), direction.normalize(), 0.0);
        let hit = plane.intersect(&up, 0.0, f64::INFINITY).unwrap();
        let at = single_precision::point_at(&up, hit.t);
        // This ray's hit rounds to above the ceiling in single precision.
        assert!(at.y > f64::from(81.6f32), "{}", at.y);
        let down = Ray::new(at, Vec3::new(0.3, -1.0, 0.2).normalize(), 0.0);
        let again = plane.intersect(&down, 0.0, f64::INFINITY).unwrap();
        assert!(again.t > 0.0 && again.t < 1e-4, "{}", again.t);
    }

    #[test]
    fn parallel_ray_misses_without_nan() {
        let plane = Plane::new(Vec3::y(), 0.0).unwrap();
        let ray = Ray::new(Point3::new(0.0, 1.0, 0.0), Vec3::x(), 0.0);
        assert!(plane.intersect(&ray, 0.0, f64::INFINITY).is_none());
    }
}
