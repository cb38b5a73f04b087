//! yao-jz's surface of revolution: a hit found on a coarse tessellation and
//! then moved by plain Newton steps, without any of the checks that make
//! [`super::Revolution`] exact (`yao-jz/Computer-Graphics-THU:include/revsurface.hpp`,
//! `include/curve.hpp`, `include/triangle.hpp`).
//!
//! The facts it follows:
//! - The profile is sampled at `u = 0, 0.02, 0.04, ...` while `u < 1` (the
//!   steps summed in double precision) and each sample is turned about y to
//!   20 angles `a = 2 pi k / 20`, as `(x cos a, y, -x sin a)`; neighbouring
//!   samples make two triangles, the last angle joined to the first.
//! - A ray meets the nearest triangle; its barycentric weights mix the three
//!   vertices' `u` and angle into the start of the iteration (the wedge
//!   between the last angle and 0 mixes 2 pi 19/20 with 0).
//! - The iteration solves `origin + t direction = (x(u) cos th, y(u), x(u) sin th)`
//!   for `(t, u, th)`: 20 full Newton steps, whatever they do. That sweep
//!   turns the other way round from the tessellation's, so the start's angle
//!   is the mirror image of the hit's: from a hit on the near side the
//!   steps usually land on the far side of the surface, behind it on the
//!   ray, and from a hit near the silhouette or a rim they may land off the
//!   surface's range of `u`, where nothing is checked.
//! - The hit is `origin + t direction`, its normal `dS/du x dS/dth`
//!   normalised and turned to face the ray.
//!
//! Only a look that asks for it (`ShapeRules::revolution_test`) builds this
//! shape; the profile is the file's Bezier or B-spline curve as ours reads it.

use std::f64::consts::PI;
use std::sync::Arc;

use super::curve::Curve;
use super::{Intersection, Mesh, MeshData, Profile, SurfaceHit, UvMapping};
use super::{derivatives_or_fallback, normalize_or};
use crate::math::{Aabb, Point3, Ray, Vec3};

/// Profile samples are `SAMPLE_STEP` apart in `u`.
const SAMPLE_STEP: f64 = 1.0 / 50.0;
/// Angles around the axis.
const ANGLES: usize = 20;
/// Newton steps after the tessellation's hit.
const NEWTON_STEPS: usize = 20;

#[derive(Debug)]
pub struct SeededRevolution {
    curve: Curve,
    tessellation: Mesh,
    /// Profile parameter and angle of each tessellation vertex.
    vertex_u: Vec<f64>,
    vertex_angle: Vec<f64>,
}

impl SeededRevolution {
    /// `None` for a profile our curves cannot read or a tessellation without
    /// triangles.
    pub fn new(profile: &Profile) -> Option<SeededRevolution> {
        let curve = Curve::new(profile)?;
        let mut samples = Vec::new();
        let mut u = 0.0f64;
        while u < 1.0 {
            samples.push(u);
            u += SAMPLE_STEP;
        }
        let mut positions = Vec::with_capacity(samples.len() * ANGLES);
        let mut vertex_u = Vec::with_capacity(positions.capacity());
        let mut vertex_angle = Vec::with_capacity(positions.capacity());
        let mut triangles = Vec::new();
        for (row, &u) in samples.iter().enumerate() {
            let p = curve.evaluate(u).0;
            for k in 0..ANGLES {
                let angle = 2.0 * PI * k as f64 / ANGLES as f64;
                let (sin, cos) = angle.sin_cos();
                positions.push(Point3::new(p.x * cos, p.y, -p.x * sin));
                vertex_u.push(u);
                vertex_angle.push(angle);
                if row + 1 < samples.len() {
                    let next_k = (k + 1) % ANGLES;
                    let at = |r: usize, k: usize| (r * ANGLES + k) as u32;
                    triangles.push([at(row + 1, k), at(row, next_k), at(row, k)]);
                    triangles.push([at(row + 1, k), at(row + 1, next_k), at(row, next_k)]);
                }
            }
        }
        if triangles.is_empty() || !positions.iter().all(|p| p.iter().all(|c| c.is_finite())) {
            return None;
        }
        let data = MeshData {
            positions,
            normals: None,
            uvs: None,
            triangles,
            framework_reading: None,
        };
        Some(SeededRevolution {
            curve,
            tessellation: Mesh::new(Arc::new(data)),
            vertex_u,
            vertex_angle,
        })
    }

    /// The tessellation's bounds (the Newton steps may leave them).
    pub fn bounds(&self) -> Option<Aabb> {
        self.tessellation.bounds()
    }

    /// The point on the sweep that the iteration solves for, and its
    /// derivatives in `u` and `th`.
    fn sweep(&self, u: f64, theta: f64) -> (Point3, Vec3, Vec3) {
        let (p, dp) = self.curve.evaluate(u);
        let (sin, cos) = theta.sin_cos();
        (
            Point3::new(p.x * cos, p.y, p.x * sin),
            Vec3::new(dp.x * cos, dp.y, dp.x * sin),
            Vec3::new(-p.x * sin, 0.0, p.x * cos),
        )
    }

    /// The tessellation's nearest hit within `(t_min, t_max)`, moved by the
    /// Newton steps; `u` and `v` of the result are the profile parameter and
    /// the angle. `None` when the tessellation is missed or the steps end on a
    /// distance that is not finite or not within `(t_min, t_max)`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        let seed = self.tessellation.intersect(ray, t_min, t_max)?;
        let triangle = self.tessellation.data.triangles[seed.index as usize];
        let weights = [1.0 - seed.u - seed.v, seed.u, seed.v];
        let mix = |values: &[f64]| -> f64 {
            triangle
                .iter()
                .zip(weights)
                .map(|(&i, w)| values[i as usize] * w)
                .sum()
        };
        let (mut t, mut u, mut theta) = (seed.t, mix(&self.vertex_u), mix(&self.vertex_angle));
        for _ in 0..NEWTON_STEPS {
            let (s, s_u, s_theta) = self.sweep(u, theta);
            let f = ray.at(t) - s;
            // The Jacobian's columns: direction, -dS/du, -dS/dth.
            let jacobian = nalgebra::Matrix3::from_columns(&[ray.direction, -s_u, -s_theta]);
            let Some(inverse) = jacobian.try_inverse() else {
                break;
            };
            let step = inverse * f;
            t -= step.x;
            u -= step.y;
            theta -= step.z;
        }
        let finite = t.is_finite() && u.is_finite() && theta.is_finite();
        (finite && t < t_max).then(|| Intersection::new(t, u, theta))
    }

    /// The hit `origin + t direction`, with the sweep's normal turned to face
    /// the ray; uv = (angle / 2 pi, u).
    pub fn surface(&self, ray: &Ray, hit: &Intersection) -> SurfaceHit {
        let (_, s_u, s_theta) = self.sweep(hit.u, hit.v);
        let radial = Vec3::new(hit.v.cos(), 0.0, hit.v.sin());
        let mut normal = normalize_or(s_u.cross(&s_theta), radial);
        if ray.direction.dot(&normal) > 0.0 {
            normal = -normal;
        }
        let (dpdu, dpdv) = derivatives_or_fallback(s_theta * (2.0 * PI), s_u, &normal);
        SurfaceHit {
            point: ray.at(hit.t),
            geometric_normal: normal,
            shading_normal: normal,
            dpdu,
            dpdv,
            uv: [(hit.v / (2.0 * PI)).rem_euclid(1.0), hit.u],
            uv_mapping: UvMapping::Unit,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{CurveKind, Revolution};

    /// yao-jz's scene09_norm vase: a cubic Bezier profile with x < 0.
    fn vase() -> SeededRevolution {
        SeededRevolution::new(&Profile {
            kind: CurveKind::Bezier,
            controls: vec![[-2.0, 2.0], [-4.0, 0.0], [0.0, 0.0], [-2.0, -2.0]],
        })
        .unwrap()
    }

    fn towards(target: [f64; 3]) -> Ray {
        let origin = Point3::new(0.0, 0.0, 10.0);
        Ray::new(origin, (Point3::from(target) - origin).normalize(), 0.0)
    }

    /// Whether `point` lies on the swept profile (any angle) at `u`.
    fn on_sweep(surface: &SeededRevolution, point: &Point3, u: f64) -> bool {
        let p = surface.curve.evaluate(u).0;
        let radius = (point.x * point.x + point.z * point.z).sqrt();
        (radius - p.x.abs()).abs() < 1e-9 && (point.y - p.y).abs() < 1e-9
    }

    #[test]
    fn a_ray_that_meets_the_near_side_ends_on_the_far_side() {
        // The vase's waist (u = 0.5) has radius 2: the ray down the axis
        // of view meets it at z = 2 (t = 8) and leaves it at z = -2.
        let surface = vase();
        let exact = Revolution::new(&Profile {
            kind: CurveKind::Bezier,
            controls: vec![[-2.0, 2.0], [-4.0, 0.0], [0.0, 0.0], [-2.0, -2.0]],
        })
        .unwrap();
        let ray = towards([0.0, 0.0, 0.0]);
        let near = exact.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((near.t - 8.0).abs() < 1e-9, "{}", near.t);
        let hit = surface.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 12.0).abs() < 1e-9, "{}", hit.t);
        // Off the axis of view too: on the surface, behind the near hit.
        let ray = towards([0.8, 0.5, 0.0]);
        let near = exact.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        let hit = surface.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!(hit.t > near.t + 2.0, "{} vs {}", hit.t, near.t);
        assert!(on_sweep(&surface, &ray.at(hit.t), hit.u));
    }

    #[test]
    fn the_normal_faces_the_ray() {
        let surface = vase();
        for target in [
            [0.0, 0.0, 0.0],
            [0.8, 0.5, 0.0],
            [1.6, 0.0, 0.0],
            [0.4, 1.5, 0.0],
        ] {
            for ray in [
                towards(target),
                Ray::new(Point3::from(target), Vec3::z(), 0.0),
            ] {
                let Some(hit) = surface.intersect(&ray, 0.0, f64::INFINITY) else {
                    continue;
                };
                let at = surface.surface(&ray, &hit);
                assert!(at.geometric_normal.dot(&ray.direction) <= 0.0, "{target:?}");
                assert!((at.point - ray.at(hit.t)).norm() < 1e-12);
            }
        }
    }

    #[test]
    fn the_steps_are_not_held_to_the_profile() {
        // Near the bottom the steps end beyond u = 1, on the profile's
        // polynomial extended, and the hit is kept.
        let surface = vase();
        let ray = towards([0.8, -1.5, 2.0]);
        let hit = surface.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!(hit.u > 1.0, "{}", hit.u);
        assert!(on_sweep(&surface, &ray.at(hit.t), hit.u));
    }

    #[test]
    fn the_tessellation_stops_short_of_the_profiles_end() {
        // Samples at u = 0, 0.02, ..., 0.98: 50 rings, the last at y(0.98),
        // so a ray between that ring and the bottom rim (y = -2) misses.
        let surface = vase();
        assert_eq!(surface.vertex_u.len(), 50 * ANGLES);
        let last = surface.curve.evaluate(0.98).0;
        let end = surface.curve.evaluate(1.0).0;
        let y = 0.5 * (last.y + end.y);
        let side = Ray::new(Point3::new(10.0, y, 0.0), -Vec3::x(), 0.0);
        assert!(surface.intersect(&side, 0.0, f64::INFINITY).is_none());
        let above = Ray::new(Point3::new(10.0, last.y + 0.05, 0.0), -Vec3::x(), 0.0);
        assert!(surface.intersect(&above, 0.0, f64::INFINITY).is_some());
    }
}
