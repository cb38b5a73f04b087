//! Seeds for the Newton intersection of surfaces of revolution: the profile cut
//! into cone frusta once at build time, and the ray's crossings and near misses of
//! those frusta (within their chord deviation, so silhouettes are not lost).

use super::curve::{Curve, Point2};
use crate::math::{Point3, Ray, Vec3};

/// Frusta of the seeding tessellation.
pub const SEED_SEGMENTS: usize = 128;

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

/// The profile cut into frusta, with per-frustum bounds for culling.
#[derive(Clone, Debug)]
pub struct SeedTessellation {
    segments: Vec<Segment>,
}

impl SeedTessellation {
    /// `scale` is the size of the surface (the unit of the tolerances).
    pub fn new(curve: &Curve, scale: f64) -> SeedTessellation {
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
        SeedTessellation { segments }
    }

    /// Calls `push(t, u)` for every seed with `t` in `[t0, t1]`.
    pub fn seeds(&self, ray: &RadialRay, (t0, t1): (f64, f64), push: &mut impl FnMut(f64, f64)) {
        let (y_a, y_b) = (ray.o.y + t0 * ray.d.y, ray.o.y + t1 * ray.d.y);
        let (y_lo, y_hi) = (y_a.min(y_b), y_a.max(y_b));
        let t_closest = if ray.a > 0.0 {
            within(-ray.b / ray.a, t0, t1)
        } else {
            t0
        };
        let r_min = ray.radius(t_closest);
        for segment in &self.segments {
            if segment.y_max < y_lo || segment.y_min > y_hi || segment.r_max < r_min {
                continue;
            }
            segment_seeds(segment, ray, (t0, t1), push);
        }
    }
}

/// The ray with its radial quadratic `r(t)^2 = a t^2 + 2 b t + c`.
pub struct RadialRay {
    pub o: Point3,
    pub d: Vec3,
    pub a: f64,
    pub b: f64,
    pub c: f64,
}

impl RadialRay {
    pub fn new(ray: &Ray) -> Self {
        let (o, d) = (ray.origin, ray.direction);
        RadialRay {
            o,
            d,
            a: d.x * d.x + d.z * d.z,
            b: o.x * d.x + o.z * d.z,
            c: o.x * o.x + o.z * o.z,
        }
    }

    pub fn radius(&self, t: f64) -> f64 {
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
    if dx == 0.0 && dy == 0.0 {
        // A piece of the profile that stays at one point (equal controls): its
        // chord is that point, reached where the ray passes its height or
        // comes closest to the axis.
        if ray.d.y != 0.0 {
            candidates[0] = (y0 - ray.o.y) / ray.d.y;
        }
        if ray.a > 0.0 {
            candidates[1] = -ray.b / ray.a;
        }
    } else if dy.abs() >= dx.abs() || (ray.d.y == 0.0 && dy != 0.0) {
        // s = alpha + beta t and x = p + q t: solve r(t)^2 = x(t)^2 for t.
        // (A horizontal ray meets a flat segment at one height too: the
        // other branch would divide by its zero `d.y`.)
        let (alpha, beta) = ((ray.o.y - y0) / dy, ray.d.y / dy);
        let (p, q) = (x0 + dx * alpha, dx * beta);
        candidates = quadratic_candidates(ray.a - q * q, ray.b - p * q, ray.c - p * p);
        // Keep the extremum within the segment's t range.
        if beta != 0.0 {
            let (ta, tb) = (-alpha / beta, (1.0 - alpha) / beta);
            candidates[0] = within(candidates[0], ta.min(tb), ta.max(tb));
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
        candidates[0] = alpha + beta * within(roots[0], 0.0, 1.0);
    }
    for t in candidates {
        if !(t.is_finite() && t >= t0 && t <= t1) {
            continue;
        }
        let point = Point2::new(ray.radius(t), ray.o.y + t * ray.d.y);
        let (distance, s) = project_to_folded_segment(&point, &segment.start, &segment.end);
        if distance <= segment.deviation {
            push(t, segment.u0 + s * (segment.u1 - segment.u0));
        }
    }
}

/// `x` limited to `[lo, hi]`; unlike `f64::clamp` it never panics: NaN bounds
/// are ignored and `lo > hi` gives `hi` (a NaN `x` stays NaN, and callers
/// drop non-finite candidates).
fn within(x: f64, lo: f64, hi: f64) -> f64 {
    if x.is_nan() { x } else { x.max(lo).min(hi) }
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

/// Distance from `p` (in the (r, y) half-plane) to the segment a-b of the (x, y)
/// plane folded onto it by r = |x|, and the parameter of the closest point. A
/// segment crossing the axis folds into two pieces.
fn project_to_folded_segment(p: &Point2, a: &Point2, b: &Point2) -> (f64, f64) {
    let fold = |q: &Point2| Point2::new(q.x.abs(), q.y);
    if a.x * b.x >= 0.0 {
        return project_to_segment(p, &fold(a), &fold(b));
    }
    let split = a.x / (a.x - b.x);
    let axis = Point2::new(0.0, a.y + split * (b.y - a.y));
    let (d0, s0) = project_to_segment(p, &fold(a), &axis);
    let (d1, s1) = project_to_segment(p, &axis, &fold(b));
    if d0 <= d1 {
        (d0, s0 * split)
    } else {
        (d1, split + s1 * (1.0 - split))
    }
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
