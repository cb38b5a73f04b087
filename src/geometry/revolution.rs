//! Surfaces of revolution `S(u, theta) = (x(u) cos theta, y(u), -x(u) sin theta)`
//! of a profile curve about the y axis, intersected by Newton iteration.
//!
//! The 3D problem is reduced to the (r, y) half-plane: the ray gives
//! `r(t)^2 = (ox + t dx)^2 + (oz + t dz)^2` and `y(t) = oy + t dy`, and a hit solves
//! `g(t, u) = (x(u)^2 - r(t)^2, y(u) - y(t)) = 0`. Deterministic seeds come from the
//! ray against a cone-frustum tessellation of the profile (computed once), plus
//! near misses of those frusta within their chord deviation (silhouettes). Newton
//! then converges on the true curve; only roots with a small residual, `u` in
//! [0, 1] and `t` in range are accepted, and the nearest wins. `theta` follows from
//! the hit point.

use std::f64::consts::PI;

use super::curve::{Curve, Point2};
use super::{Intersection, SurfaceHit, fallback_tangent, normalize_or};
use crate::math::{Aabb, Point3, Ray, Vec3, inverse_direction};
use crate::scene::model::Profile;
use crate::world::UvMapping;

/// Frusta of the seeding tessellation.
pub const SEED_SEGMENTS: usize = 128;
/// At most this many seeds per ray are refined (further ones are dropped).
const MAX_SEEDS: usize = 48;
const MAX_ITERATIONS: usize = 32;

#[derive(Clone, Copy, Debug)]
struct Segment {
    u0: f64,
    u1: f64,
    start: Point2,
    end: Point2,
    /// Bound on the distance between the curve piece and its chord.
    deviation: f64,
    y_min: f64,
    y_max: f64,
    r_max: f64,
}

#[derive(Clone, Debug)]
pub struct Revolution {
    curve: Curve,
    bounds: Aabb,
    /// Size of the object, the unit of the tolerances.
    scale: f64,
    segments: Vec<Segment>,
}

impl Revolution {
    /// `None` for an unusable profile (fewer than two finite control points, or
    /// a zero-size control polygon).
    pub fn new(profile: &Profile) -> Option<Revolution> {
        let curve = Curve::new(profile)?;
        // Bezier curves and B-splines lie in the convex hull of their controls.
        let controls = curve.controls();
        let radius = controls.iter().fold(0.0f64, |r, c| r.max(c.x.abs()));
        let y_min = controls.iter().fold(f64::INFINITY, |m, c| m.min(c.y));
        let y_max = controls.iter().fold(f64::NEG_INFINITY, |m, c| m.max(c.y));
        let scale = radius.max(y_max - y_min);
        if !(scale > 0.0 && scale.is_finite()) {
            return None;
        }
        let bounds = Aabb {
            min: Point3::new(-radius, y_min, -radius),
            max: Point3::new(radius, y_max, radius),
        };
        let segments = (0..SEED_SEGMENTS)
            .map(|i| {
                let u0 = i as f64 / SEED_SEGMENTS as f64;
                let u1 = (i + 1) as f64 / SEED_SEGMENTS as f64;
                let start = curve.evaluate(u0).0;
                let end = curve.evaluate(u1).0;
                let mut deviation: f64 = 0.0;
                let mut y_lo = start.y.min(end.y);
                let mut y_hi = start.y.max(end.y);
                let mut r_hi = start.x.abs().max(end.x.abs());
                for k in 1..8 {
                    let p = curve.evaluate(u0 + (u1 - u0) * k as f64 / 8.0).0;
                    deviation = deviation.max(distance_to_segment(&p, &start, &end));
                    y_lo = y_lo.min(p.y);
                    y_hi = y_hi.max(p.y);
                    r_hi = r_hi.max(p.x.abs());
                }
                let deviation = 2.0 * deviation + 1e-9 * scale;
                Segment {
                    u0,
                    u1,
                    start,
                    end,
                    deviation,
                    y_min: y_lo - deviation,
                    y_max: y_hi + deviation,
                    r_max: r_hi + deviation,
                }
            })
            .collect();
        Some(Revolution {
            curve,
            bounds,
            scale,
            segments,
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
        let (y_a, y_b) = (o.y + t0 * d.y, o.y + t1 * d.y);
        let (y_lo, y_hi) = (y_a.min(y_b), y_a.max(y_b));
        // r(t)^2 = a t^2 + 2 b t + c.
        let a = d.x * d.x + d.z * d.z;
        let b = o.x * d.x + o.z * d.z;
        let c = o.x * o.x + o.z * o.z;
        let t_closest = if a > 0.0 { (-b / a).clamp(t0, t1) } else { t0 };
        let r_min = (a * t_closest * t_closest + 2.0 * b * t_closest + c)
            .max(0.0)
            .sqrt();
        let slack = 1e-6 * (t1 - t0).abs() + 1e-12;
        let ray_2d = RadialRay { o, d, a, b, c };

        let mut seeds = [(0.0f64, 0.0f64); MAX_SEEDS];
        let mut count = 0usize;
        let mut push = |t: f64, u: f64| {
            if count < MAX_SEEDS && t >= t0 - slack && t <= t1 + slack {
                seeds[count] = (t, u);
                count += 1;
            }
        };
        for segment in &self.segments {
            if segment.y_max < y_lo || segment.y_min > y_hi || segment.r_max < r_min {
                continue;
            }
            segment_seeds(segment, &ray_2d, (t0 - slack, t1 + slack), &mut push);
        }

        let mut best: Option<Intersection> = None;
        for &(t, u) in &seeds[..count] {
            let limit = best.map_or(t_max, |h| h.t);
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
            let dt = (g1 * j22 - j12 * g2) / determinant;
            let mut du = (j11 * g2 - j21 * g1) / determinant;
            let mut dt = dt;
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

    /// Point, normal `dS/du x dS/dtheta` (normalised), tangent `dS/du`, uv = (theta/2pi, u).
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
        let m = Vec3::new(-dp.y * cos, dp.x, dp.y * sin) * sign;
        let radial = Vec3::new(cos, 0.0, -sin);
        let normal = normalize_or(m, radial * sign);
        let tangent = normalize_or(
            Vec3::new(dp.x * cos, dp.y, -dp.x * sin),
            fallback_tangent(&normal),
        );
        SurfaceHit {
            point,
            geometric_normal: normal,
            shading_normal: normal,
            tangent,
            uv: [theta / (2.0 * PI), u],
            uv_mapping: UvMapping::Unit,
        }
    }
}

/// The ray with its radial quadratic `r(t)^2 = a t^2 + 2 b t + c`.
struct RadialRay {
    o: Point3,
    d: Vec3,
    a: f64,
    b: f64,
    c: f64,
}

impl RadialRay {
    fn radius(&self, t: f64) -> f64 {
        (self.a * t * t + 2.0 * self.b * t + self.c).max(0.0).sqrt()
    }
}

/// Seeds (t, u) from the ray against one frustum: its exact crossings and its
/// point of closest approach, kept when the ray point lies within the segment's
/// chord deviation of the segment in the (r, y) half-plane. Steep segments are
/// solved for t (the segment parameter s is linear in y), flat ones for s (t is
/// linear in s), so neither divides by a tiny number.
fn segment_seeds(
    segment: &Segment,
    ray: &RadialRay,
    (t0, t1): (f64, f64),
    push: &mut impl FnMut(f64, f64),
) {
    let (x0, y0) = (segment.start.x, segment.start.y);
    let (dx, dy) = (segment.end.x - x0, segment.end.y - y0);
    let mut candidates = [f64::NAN; 3];
    if dy.abs() >= dx.abs() {
        // s = alpha + beta t and x = p + q t: solve r(t)^2 = x(t)^2 for t.
        let (alpha, beta) = ((ray.o.y - y0) / dy, ray.d.y / dy);
        let (p, q) = (x0 + dx * alpha, dx * beta);
        candidates = quadratic_candidates(ray.a - q * q, ray.b - p * q, ray.c - p * p);
        // Keep the extremum within the segment's t range.
        if beta != 0.0 {
            let (ta, tb) = (-alpha / beta, (1.0 - alpha) / beta);
            candidates[0] = candidates[0].clamp(ta.min(tb), ta.max(tb));
        }
    } else if ray.d.y != 0.0 {
        // t = alpha + beta s: solve r(t(s))^2 = x(s)^2 for s.
        let (alpha, beta) = ((y0 - ray.o.y) / ray.d.y, dy / ray.d.y);
        let (a, b, c) = (ray.a, ray.b, ray.c);
        let roots = quadratic_candidates(
            a * beta * beta - dx * dx,
            a * alpha * beta + b * beta - x0 * dx,
            a * alpha * alpha + 2.0 * b * alpha + c - x0 * x0,
        );
        candidates = roots.map(|s| alpha + beta * s);
        candidates[0] = alpha + beta * roots[0].clamp(0.0, 1.0);
    }
    let start = Point2::new(x0.abs(), y0);
    let end = Point2::new(segment.end.x.abs(), segment.end.y);
    for t in candidates {
        if !(t.is_finite() && t >= t0 && t <= t1) {
            continue;
        }
        let point = Point2::new(ray.radius(t), ray.o.y + t * ray.d.y);
        let (distance, s) = project_to_segment(&point, &start, &end);
        if distance <= segment.deviation {
            push(t, segment.u0 + s * (segment.u1 - segment.u0));
        }
    }
}

/// The extremum and the real roots of `qa x^2 + 2 qb x + qc` (NaN when absent).
fn quadratic_candidates(qa: f64, qb: f64, qc: f64) -> [f64; 3] {
    let mut out = [f64::NAN; 3];
    if qa == 0.0 {
        out[1] = -qc / (2.0 * qb);
        return out;
    }
    out[0] = -qb / qa;
    let discriminant = qb * qb - qa * qc;
    if discriminant >= 0.0 {
        let root = -(qb + discriminant.sqrt().copysign(qb));
        out[1] = root / qa;
        if root != 0.0 {
            out[2] = qc / root;
        }
    }
    out
}

/// Distance from `p` to the segment a-b and the parameter of the closest point.
fn project_to_segment(p: &Point2, a: &Point2, b: &Point2) -> (f64, f64) {
    let ab = b - a;
    let length_squared = ab.norm_squared();
    let s = if length_squared > 0.0 {
        ((p - a).dot(&ab) / length_squared).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((p - (a + ab * s)).norm(), s)
}

fn distance_to_segment(p: &Point2, a: &Point2, b: &Point2) -> f64 {
    project_to_segment(p, a, b).0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;
    use crate::scene::model::CurveKind;

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
                assert!((du.normalize() - s.tangent).norm() < 1e-5);
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
