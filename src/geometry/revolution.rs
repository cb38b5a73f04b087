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
            segment_seeds(segment, &ray_2d, (t0, t1), self.scale, &mut push);
        }

        let mut best: Option<Intersection> = None;
        for &(t, u) in &seeds[..count] {
            let limit = best.map_or(t_max, |h| h.t);
            if let Some((t, u)) = self.refine(&ray_2d, t, u) {
                if t > t_min && t < limit {
                    best = Some(Intersection::new(t, u, 0.0));
                }
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

/// Seeds (t, u) from the ray against one frustum: exact crossings, or the point of
/// closest approach when the ray passes within the segment's chord deviation.
fn segment_seeds(
    segment: &Segment,
    ray: &RadialRay,
    (t0, t1): (f64, f64),
    scale: f64,
    push: &mut impl FnMut(f64, f64),
) {
    let (x0, y0) = (segment.start.x, segment.start.y);
    let (dx, dy) = (segment.end.x - x0, segment.end.y - y0);
    let to_u = |s: f64| segment.u0 + s.clamp(0.0, 1.0) * (segment.u1 - segment.u0);
    if dy.abs() <= 1e-12 * scale {
        // An annulus in the plane y = y0.
        if ray.d.y == 0.0 {
            return;
        }
        let t = (y0 - ray.o.y) / ray.d.y;
        let r = ray.radius(t);
        let (lo, hi) = (x0.abs().min((x0 + dx).abs()), x0.abs().max((x0 + dx).abs()));
        if r >= lo - segment.deviation && r <= hi + segment.deviation {
            let s = if hi > lo { (r - lo) / (hi - lo) } else { 0.5 };
            let s = if x0.abs() <= (x0 + dx).abs() {
                s
            } else {
                1.0 - s
            };
            push(t, to_u(s));
        }
        return;
    }
    // Along the ray: s(t) = alpha + beta t, x(t) = x0 + dx s(t) = p + q t.
    let beta = ray.d.y / dy;
    let alpha = (ray.o.y - y0) / dy;
    let p = x0 + dx * alpha;
    let q = dx * beta;
    // r(t)^2 - x(t)^2 = qa t^2 + 2 qb t + qc.
    let qa = ray.a - q * q;
    let qb = ray.b - p * q;
    let qc = ray.c - p * p;
    let mut found = false;
    let accept = |t: f64, push: &mut dyn FnMut(f64, f64)| {
        let s = alpha + beta * t;
        if (-1e-6..=1.0 + 1e-6).contains(&s) {
            push(t, to_u(s));
            true
        } else {
            false
        }
    };
    if qa.abs() <= 1e-12 * (ray.a + q * q) {
        if qb != 0.0 {
            found |= accept(-qc / (2.0 * qb), push);
        }
    } else {
        let discriminant = qb * qb - qa * qc;
        if discriminant >= 0.0 {
            let root = -(qb + discriminant.sqrt().copysign(qb));
            if root != 0.0 {
                found |= accept(root / qa, push);
                found |= accept(qc / root, push);
            } else {
                found |= accept(0.0, push);
            }
        }
    }
    if found {
        return;
    }
    // Near miss: the extremum of r^2 - x^2 within the frustum's t range.
    let (ts0, ts1) = if beta != 0.0 {
        let (a, b) = ((0.0 - alpha) / beta, (1.0 - alpha) / beta);
        (a.min(b).max(t0), a.max(b).min(t1))
    } else if (0.0..=1.0).contains(&alpha) {
        (t0, t1)
    } else {
        return;
    };
    if ts0 > ts1 {
        return;
    }
    let t = if qa != 0.0 { -qb / qa } else { ts0 };
    let t = if t.is_finite() {
        t.clamp(ts0, ts1)
    } else {
        ts0
    };
    let x = (p + q * t).abs();
    if (ray.radius(t) - x).abs() <= segment.deviation {
        push(t, to_u(alpha + beta * t));
    }
}

fn distance_to_segment(p: &Point2, a: &Point2, b: &Point2) -> f64 {
    let ab = b - a;
    let length_squared = ab.norm_squared();
    let s = if length_squared > 0.0 {
        ((p - a).dot(&ab) / length_squared).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * s)).norm()
}
