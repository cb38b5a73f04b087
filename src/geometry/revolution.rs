//! Surfaces of revolution `S(u, theta) = (x(u) cos theta, y(u), -x(u) sin theta)`
//! of a profile curve about the y axis, intersected by Newton iteration.
//!
//! The 3D problem is reduced to the (r, y) half-plane: the ray gives
//! `r(t)^2 = (ox + t dx)^2 + (oz + t dz)^2` and `y(t) = oy + t dy`, and a hit solves
//! `g(t, u) = (x(u)^2 - r(t)^2, y(u) - y(t)) = 0`. Deterministic seeds come from the
//! ray against a cone-frustum tessellation of the profile (see `profile_seeds`). Newton
//! then converges on the true curve; only roots with a small residual, `u` in
//! [0, 1] and `t` in range are accepted, and the nearest wins. `theta` follows from
//! the hit point.

use std::f64::consts::PI;

use super::Profile;
use super::UvMapping;
use super::curve::Curve;
use super::jefflyy_revolution;
use super::profile_seeds::{RadialRay, SeedTessellation};
use super::{Intersection, SurfaceHit, derivatives_or_fallback, normalize_or};
use crate::math::{Aabb, Point3, Ray, Vec3, inverse_direction};

/// The rules of a surface of revolution's ray test.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RevolutionTest {
    /// Seeds from a tessellation refined by Newton on (t, u): every root
    /// the tolerance allows.
    #[default]
    Robust,
    /// jefflyy's (see [`jefflyy_revolution`]): Newton on the profile
    /// parameter alone from 1001 starts, its step scaled by the parameter,
    /// which misses roots near the profile's start and, by rounding, some
    /// elsewhere.
    Jefflyy,
    /// yao-jz's: Newton steps from the nearest triangle of a tessellation,
    /// unchecked, the normal facing the ray (a [`super::SeededRevolution`],
    /// built instead of a `Revolution`).
    TessellationSeeded,
    /// CaveSpiderLZJ's: the nearest triangle of a tessellation, moved a
    /// little by ten damped Newton steps that also pick the normal (a
    /// [`super::CavRevolution`], built instead of a `Revolution`).
    CavMesh,
}

/// At most this many seeds per ray are refined (further ones are dropped).
const MAX_SEEDS: usize = 48;
const MAX_ITERATIONS: usize = 32;
/// Seeds farther than this (times the object size) beyond the best root are skipped.
const SEED_MARGIN: f64 = 0.05;

#[derive(Clone, Debug)]
pub struct Revolution {
    curve: Curve,
    bounds: Aabb,
    /// Size of the object, the unit of the tolerances.
    scale: f64,
    seeds: SeedTessellation,
    /// How rays meet it (the look's rule).
    pub test: RevolutionTest,
    /// +1 or -1: makes `dS/du x dS/dtheta` point out of the solid that the
    /// profile bounds together with the axis, whichever way the profile runs.
    orientation: f64,
}

impl Revolution {
    /// `None` for an unusable profile: fewer than two finite control points, a
    /// control polygon of zero size, or one on the axis (a surface without
    /// area). Repeated controls are fine: the seeds and Newton steps of a
    /// piece that stays at one point are guarded against dividing by zero.
    pub fn new(profile: &Profile) -> Option<Revolution> {
        let curve = Curve::new(profile)?;
        // Bezier curves and B-splines lie in the convex hull of their controls.
        let controls = curve.controls();
        let radius = controls.iter().fold(0.0f64, |r, c| r.max(c.x.abs()));
        let y_min = controls.iter().fold(f64::INFINITY, |m, c| m.min(c.y));
        let y_max = controls.iter().fold(f64::NEG_INFINITY, |m, c| m.max(c.y));
        let first = controls[0];
        if controls.iter().all(|c| *c == first) {
            return None;
        }
        let scale = radius.max(y_max - y_min);
        if !(radius > 0.0 && scale.is_finite()) {
            return None;
        }
        let bounds = Aabb {
            min: Point3::new(-radius, y_min, -radius),
            max: Point3::new(radius, y_max, radius),
        };
        let seeds = SeedTessellation::new(&curve, scale);
        let orientation = outward_orientation(&curve);
        Some(Revolution {
            curve,
            bounds,
            scale,
            seeds,
            test: RevolutionTest::Robust,
            orientation,
        })
    }

    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    pub fn curve(&self) -> &Curve {
        &self.curve
    }

    /// Nearest hit; `u` is the profile parameter (`v` unused).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        if self.test == RevolutionTest::Jefflyy {
            return jefflyy_revolution::intersect(&self.curve, ray, t_min, t_max);
        }
        let (o, d) = (ray.origin, ray.direction);
        let (t0, t1) = self.bounds.expanded(1e-9 * self.scale).clip(
            &o,
            &inverse_direction(&d),
            t_min,
            t_max,
        )?;
        if !(t0.is_finite() && t1.is_finite()) {
            return None;
        }
        let slack = 1e-6 * (t1 - t0).abs() + 1e-12;
        let ray_2d = RadialRay::new(ray);

        let mut seeds = [(0.0f64, 0.0f64); MAX_SEEDS];
        let mut count = 0usize;
        let mut push = |t: f64, u: f64| {
            if count < MAX_SEEDS && t >= t0 - slack && t <= t1 + slack {
                seeds[count] = (t, u);
                count += 1;
            }
        };
        self.seeds
            .seeds(&ray_2d, (t0 - slack, t1 + slack), &mut push);

        // Nearest seeds first; Newton lands close to its seed, so once a root is
        // found, seeds well beyond it cannot give a nearer one.
        let seeds = &mut seeds[..count];
        seeds.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let margin = SEED_MARGIN * self.scale / ray.direction.norm();
        let mut best: Option<Intersection> = None;
        for &(t, u) in seeds.iter() {
            let limit = best.map_or(t_max, |h| h.t);
            if t > limit + margin {
                break;
            }
            if let Some((t, u)) = self.refine(&ray_2d, t, u)
                && t > t_min
                && t < limit
            {
                best = Some(Intersection::new(t, u, 0.0));
            }
        }
        best
    }

    /// Newton on g(t, u); the converged root if its residual is small and u in [0, 1].
    fn refine(&self, ray: &RadialRay, mut t: f64, mut u: f64) -> Option<(f64, f64)> {
        let d_norm = ray.d.norm();
        let tolerance = 1e-9 * self.scale;
        for _ in 0..MAX_ITERATIONS {
            let (p, dp) = self.curve.evaluate(u);
            let px = ray.o.x + t * ray.d.x;
            let pz = ray.o.z + t * ray.d.z;
            let py = ray.o.y + t * ray.d.y;
            let g1 = p.x * p.x - (px * px + pz * pz);
            let g2 = p.y - py;
            let j11 = -2.0 * (px * ray.d.x + pz * ray.d.z);
            let j12 = 2.0 * p.x * dp.x;
            let j21 = -ray.d.y;
            let j22 = dp.y;
            let determinant = j11 * j22 - j12 * j21;
            if determinant == 0.0 || !determinant.is_finite() {
                break;
            }
            let mut dt = (g1 * j22 - j12 * g2) / determinant;
            let mut du = (j11 * g2 - j21 * g1) / determinant;
            if !(dt.is_finite() && du.is_finite()) {
                break;
            }
            // Damp wild steps so the iteration stays near its seed.
            if du.abs() > 0.125 {
                let damping = 0.125 / du.abs();
                du *= damping;
                dt *= damping;
            }
            t -= dt;
            u = (u - du).clamp(-0.25, 1.25);
            if (dt * d_norm).abs() <= 1e-13 * self.scale && du.abs() <= 1e-13 {
                break;
            }
        }
        if !(-1e-9..=1.0 + 1e-9).contains(&u) || !t.is_finite() {
            return None;
        }
        let u = u.clamp(0.0, 1.0);
        let p = self.curve.evaluate(u).0;
        let hit = ray.o + ray.d * t;
        let r = (hit.x * hit.x + hit.z * hit.z).sqrt();
        ((p.y - hit.y).abs() <= tolerance && (p.x.abs() - r).abs() <= tolerance).then_some((t, u))
    }

    /// Point, normal `dS/du x dS/dtheta` (normalised), uv = (theta/2pi, u):
    /// `dpdu = 2pi dS/dtheta` (along the circle), `dpdv = dS/du` (along the
    /// profile).
    pub fn surface(&self, ray: &Ray, hit: &Intersection) -> SurfaceHit {
        let u = hit.u;
        let (p, mut dp) = self.curve.evaluate(u);
        let nudged = u + (0.5 - u) * 1e-4;
        let on_axis = p.x.abs() <= 1e-12 * self.scale;
        let sign = if on_axis {
            self.curve.evaluate(nudged).0.x.signum()
        } else {
            p.x.signum()
        };
        if dp.norm() <= 1e-12 * self.scale {
            // Stationary point of the profile (e.g. tripled B-spline controls).
            dp = self.curve.evaluate(nudged).1;
        }
        let raw = ray.at(hit.t);
        let theta = (-raw.z * sign).atan2(raw.x * sign).rem_euclid(2.0 * PI);
        let (sin, cos) = theta.sin_cos();
        let point = Point3::new(p.x * cos, p.y, -p.x * sin);
        // dS/du x dS/dtheta = x(u) * m with m the rotated profile normal (-y', x').
        let m = Vec3::new(-dp.y * cos, dp.x, dp.y * sin) * (sign * self.orientation);
        let radial = Vec3::new(cos, 0.0, -sin);
        let normal = normalize_or(m, radial * (sign * self.orientation));
        let dpdu = Vec3::new(-p.x * sin, 0.0, -p.x * cos) * (2.0 * PI);
        let dpdv = Vec3::new(dp.x * cos, dp.y, -dp.x * sin);
        let (dpdu, dpdv) = derivatives_or_fallback(dpdu, dpdv, &normal);
        SurfaceHit {
            point,
            geometric_normal: normal,
            shading_normal: normal,
            dpdu,
            dpdv,
            uv: [theta / (2.0 * PI), u],
            uv_mapping: UvMapping::Unit,
        }
    }
}

/// The sign that turns the profile's left normal `(-y', x')` outward: the
/// profile (in |x|) closed along the axis is a polygon; when it runs
/// counter-clockwise its left normal points into the solid, so flip it.
fn outward_orientation(curve: &Curve) -> f64 {
    const SAMPLES: usize = 256;
    let point = |i: usize| {
        let p = curve.evaluate(i as f64 / SAMPLES as f64).0;
        (p.x.abs(), p.y)
    };
    let (first, last) = (point(0), point(SAMPLES));
    let mut polygon: Vec<(f64, f64)> = (0..=SAMPLES).map(point).collect();
    polygon.push((0.0, last.1));
    polygon.push((0.0, first.1));
    let twice_area: f64 = polygon
        .iter()
        .zip(polygon.iter().cycle().skip(1))
        .map(|(a, b)| a.0 * b.1 - b.0 * a.1)
        .sum();
    if twice_area > 0.0 { -1.0 } else { 1.0 }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::CurveKind;
    use crate::rng::Rng;

    fn vase() -> Revolution {
        Revolution::new(&Profile {
            kind: CurveKind::Bezier,
            controls: vec![
                [0.0, 0.0],
                [2.2, 0.0],
                [3.0, 1.5],
                [1.2, 3.0],
                [0.8, 4.0],
                [1.6, 5.0],
                [2.0, 5.6],
            ],
        })
        .unwrap()
    }

    fn sweep(curve: &Curve, u: f64, theta: f64) -> Point3 {
        let p = curve.evaluate(u).0;
        Point3::new(p.x * theta.cos(), p.y, -p.x * theta.sin())
    }

    fn normal_at(surface: &Revolution, origin: Vec3, direction: Vec3) -> Vec3 {
        let ray = Ray::new(origin, direction, 0.0);
        let hit = surface.intersect(&ray, 0.0, f64::INFINITY).expect("hits");
        surface.surface(&ray, &hit).geometric_normal
    }

    #[test]
    fn normals_point_out_of_the_solid_whichever_way_the_profile_runs() {
        let forward = vase();
        let mut controls = forward
            .curve()
            .controls()
            .iter()
            .map(|c| [c.x, c.y])
            .collect::<Vec<_>>();
        controls.reverse();
        let backward = Revolution::new(&Profile {
            kind: CurveKind::Bezier,
            controls,
        })
        .unwrap();
        for surface in [&forward, &backward] {
            let side = normal_at(
                surface,
                Vec3::new(10.0, 1.5, 0.0),
                Vec3::new(-1.0, 0.0, 0.0),
            );
            assert!(side.x > 0.5, "side normal {side:?}");
            let bottom = normal_at(surface, Vec3::new(0.5, -5.0, 0.2), Vec3::new(0.0, 1.0, 0.0));
            assert!(bottom.y < -0.5, "bottom normal {bottom:?}");
        }
    }

    #[test]
    fn hits_lie_on_the_surface_with_the_swept_normal() {
        let surface = vase();
        let mut rng = Rng::new(8, 8);
        let mut hits = 0;
        for _ in 0..2000 {
            let origin = Point3::new(
                rng.next_f64() * 20.0 - 10.0,
                rng.next_f64() * 20.0 - 7.0,
                rng.next_f64() * 20.0 - 10.0,
            );
            let target = Point3::new(
                rng.next_f64() * 6.0 - 3.0,
                rng.next_f64() * 5.6,
                rng.next_f64() * 6.0 - 3.0,
            );
            let ray = Ray::new(origin, target - origin, 0.0);
            let Some(hit) = surface.intersect(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            hits += 1;
            let s = surface.surface(&ray, &hit);
            assert!((s.point - ray.at(hit.t)).norm() < 1e-7, "{:?}", s.point);
            let (u, theta) = (s.uv[1], s.uv[0] * 2.0 * PI);
            assert!((sweep(surface.curve(), u, theta) - s.point).norm() < 1e-9);
            // Normal = dS/du x dS/dtheta from finite differences.
            let h = 1e-6;
            let du = sweep(surface.curve(), u + h, theta) - sweep(surface.curve(), u - h, theta);
            let dtheta =
                sweep(surface.curve(), u, theta + h) - sweep(surface.curve(), u, theta - h);
            let expected = du.cross(&dtheta);
            if expected.norm() > 1e-9 {
                let error = (expected.normalize() - s.geometric_normal).norm();
                assert!(error < 1e-5, "normal off by {error} at u={u}");
                assert!((du / (2.0 * h) - s.dpdv).norm() < 1e-5 * du.norm() / h);
                let along = dtheta / (2.0 * h) * (2.0 * PI);
                assert!((along - s.dpdu).norm() < 1e-5 * along.norm().max(1.0));
            }
        }
        assert!(hits > 500, "{hits}");
    }

    #[test]
    fn ray_along_the_axis_hits_the_bottom_centre() {
        let surface = vase();
        let ray = Ray::new(Point3::new(0.0, -5.0, 0.0), Vec3::y(), 0.0);
        let hit = surface.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 5.0).abs() < 1e-6, "{}", hit.t);
        let s = surface.surface(&ray, &hit);
        assert!(s.geometric_normal.iter().all(|c| c.is_finite()));
        assert!(s.geometric_normal.y.abs() > 0.99);
    }
}
