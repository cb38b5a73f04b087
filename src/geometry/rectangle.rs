//! Parallelograms `origin + s * edge_u + t * edge_v`, s and t in [0, 1].

use super::{Intersection, SurfaceHit};
use super::{UvMapping, cambrian_rectangle};
use crate::math::{Aabb, Point3, Ray, Vec3};

#[derive(Clone, Copy, Debug)]
pub struct Rectangle {
    pub origin: Point3,
    pub edge_u: Vec3,
    pub edge_v: Vec3,
    /// Unit normal `edge_u x edge_v`.
    normal: Vec3,
    /// `edge_v x n / |edge_u x edge_v|` and `n x edge_u / |...|`: dual basis giving (s, t).
    dual_u: Vec3,
    dual_v: Vec3,
    /// Whether rays meet it by Cambrian's test ([`cambrian_rectangle`]):
    /// a hit whose point does not round into the rectangle's box is lost.
    pub cambrian: bool,
}

impl Rectangle {
    /// `None` for a zero-area parallelogram.
    pub fn new(origin: Point3, edge_u: Vec3, edge_v: Vec3) -> Option<Rectangle> {
        let cross = edge_u.cross(&edge_v);
        let area_squared = cross.norm_squared();
        if !(area_squared > 0.0 && area_squared.is_finite()) {
            return None;
        }
        let normal = cross / area_squared.sqrt();
        Some(Rectangle {
            origin,
            edge_u,
            edge_v,
            normal,
            dual_u: edge_v.cross(&cross) / area_squared,
            dual_v: cross.cross(&edge_u) / area_squared,
            cambrian: false,
        })
    }

    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        if self.cambrian {
            let t = cambrian_rectangle::intersect(
                &self.origin,
                &self.edge_u,
                &self.edge_v,
                ray,
                t_min,
                t_max,
            )?;
            let local = ray.at(t) - self.origin;
            let s = self.dual_u.dot(&local).clamp(0.0, 1.0);
            let r = self.dual_v.dot(&local).clamp(0.0, 1.0);
            return Some(Intersection::new(t, s, r));
        }
        let denominator = self.normal.dot(&ray.direction);
        if denominator == 0.0 {
            return None;
        }
        let t = self.normal.dot(&(self.origin - ray.origin)) / denominator;
        if !(t > t_min && t < t_max) {
            return None;
        }
        let local = ray.at(t) - self.origin;
        let s = self.dual_u.dot(&local);
        let r = self.dual_v.dot(&local);
        ((0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&r)).then(|| Intersection::new(t, s, r))
    }

    pub fn surface(&self, _ray: &Ray, hit: &Intersection) -> SurfaceHit {
        SurfaceHit {
            point: self.origin + self.edge_u * hit.u + self.edge_v * hit.v,
            geometric_normal: self.normal,
            shading_normal: self.normal,
            dpdu: self.edge_u,
            dpdv: self.edge_v,
            uv: [hit.u, hit.v],
            uv_mapping: UvMapping::Unit,
        }
    }

    pub fn bounds(&self) -> Aabb {
        Aabb::from_point(self.origin)
            .include_point(self.origin + self.edge_u)
            .include_point(self.origin + self.edge_v)
            .include_point(self.origin + self.edge_u + self.edge_v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn skewed_parallelogram_coordinates() {
        let rect = Rectangle::new(
            Point3::zeros(),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
        )
        .unwrap();
        let ray = Ray::new(Point3::new(1.5, 0.5, 1.0), -Vec3::z(), 0.0);
        let hit = rect.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.u - 0.5).abs() < 1e-12 && (hit.v - 0.5).abs() < 1e-12);
        let outside = Ray::new(Point3::new(0.2, 0.9, 1.0), -Vec3::z(), 0.0);
        assert!(rect.intersect(&outside, 0.0, f64::INFINITY).is_none());
    }
}
