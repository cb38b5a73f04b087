//! Single triangles: Möller–Trumbore in f64; zero-area triangles are never hit.

use super::UvMapping;
use super::single_precision;
use super::{Intersection, SurfaceHit, derivatives_or_fallback, normalize_or};
use crate::math::{Aabb, Point3, Ray, Vec3};

/// Möller–Trumbore: `(t, b1, b2)` with the hit at `(1-b1-b2) p0 + b1 p1 + b2 p2`.
/// Degenerate triangles (parallel ray or zero area) give `None`.
#[inline]
pub fn intersect_vertices(
    p0: &Point3,
    p1: &Point3,
    p2: &Point3,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<(f64, f64, f64)> {
    intersect_edges(p0, &(p1 - p0), &(p2 - p0), ray, t_min, t_max)
}

/// [`intersect_vertices`] of the triangle with vertex `p0` and edges
/// `edge1 = p1 - p0`, `edge2 = p2 - p0`.
#[inline]
pub fn intersect_edges(
    p0: &Point3,
    edge1: &Vec3,
    edge2: &Vec3,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<(f64, f64, f64)> {
    let p = ray.direction.cross(edge2);
    let determinant = edge1.dot(&p);
    // Exactly zero for a degenerate triangle or a ray in its plane; the tests
    // below also reject NaN produced by huge or non-finite input.
    if determinant == 0.0 || !determinant.is_finite() {
        return None;
    }
    let inverse = 1.0 / determinant;
    let s = ray.origin - p0;
    let b1 = s.dot(&p) * inverse;
    if !(0.0..=1.0).contains(&b1) {
        return None;
    }
    let q = s.cross(edge1);
    let b2 = ray.direction.dot(&q) * inverse;
    if !(b2 >= 0.0 && b1 + b2 <= 1.0) {
        return None;
    }
    let t = edge2.dot(&q) * inverse;
    (t > t_min && t < t_max).then_some((t, b1, b2))
}

/// The surface of a triangle at barycentrics (b1, b2), uv = (b1, b2), so
/// that `dpdu = p1 - p0` and `dpdv = p2 - p0`.
pub fn surface_vertices(p0: &Point3, p1: &Point3, p2: &Point3, b1: f64, b2: f64) -> SurfaceHit {
    let edge1 = p1 - p0;
    let edge2 = p2 - p0;
    let normal = normalize_or(edge1.cross(&edge2), Vec3::z());
    let point = p0 * (1.0 - b1 - b2) + p1 * b1 + p2 * b2;
    let (dpdu, dpdv) = derivatives_or_fallback(edge1, edge2, &normal);
    SurfaceHit {
        point,
        geometric_normal: normal,
        shading_normal: normal,
        dpdu,
        dpdv,
        uv: [b1, b2],
        uv_mapping: UvMapping::Unit,
    }
}

#[derive(Clone, Copy, Debug)]
pub struct Triangle {
    pub vertices: [Point3; 3],
    /// Tested by W-Solaris's test in single precision
    /// ([`single_precision::triangle`]).
    pub single_precision: bool,
}

impl Triangle {
    pub fn new(vertices: [Point3; 3]) -> Self {
        Triangle {
            vertices,
            single_precision: false,
        }
    }

    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        let [p0, p1, p2] = &self.vertices;
        if self.single_precision {
            return single_precision::triangle(&self.vertices, ray, t_min, t_max)
                .map(|(t, b1, b2)| Intersection::new(t, b1, b2));
        }
        intersect_vertices(p0, p1, p2, ray, t_min, t_max)
            .map(|(t, b1, b2)| Intersection::new(t, b1, b2))
    }

    pub fn surface(&self, _ray: &Ray, hit: &Intersection) -> SurfaceHit {
        let [p0, p1, p2] = &self.vertices;
        surface_vertices(p0, p1, p2, hit.u, hit.v)
    }

    pub fn bounds(&self) -> Aabb {
        self.vertices
            .iter()
            .fold(Aabb::empty(), |b, p| b.include_point(*p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degenerate_triangle_is_never_hit() {
        let line = Triangle::new([
            Point3::zeros(),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(2.0, 2.0, 0.0),
        ]);
        for direction in [
            Vec3::z(),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(0.3, 0.1, 1.0),
        ] {
            let ray = Ray::new(Point3::new(1.0, 1.0, -1.0), direction, 0.0);
            assert!(line.intersect(&ray, 0.0, f64::INFINITY).is_none());
        }
    }

    #[test]
    fn hit_point_and_normal() {
        let triangle = Triangle::new([Point3::zeros(), Point3::x(), Point3::y()]);
        let ray = Ray::new(Point3::new(0.25, 0.25, 1.0), -Vec3::z(), 0.0);
        let hit = triangle.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        let s = triangle.surface(&ray, &hit);
        assert!((hit.t - 1.0).abs() < 1e-12);
        assert!((s.point - Point3::new(0.25, 0.25, 0.0)).norm() < 1e-12);
        assert_eq!(s.geometric_normal, Vec3::z());
    }
}
