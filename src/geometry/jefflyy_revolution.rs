//! jefflyy's ray test of a surface of revolution
//! (`jefflyy/CG_2022spring:include/revsurface.hpp`, facts in
//! `../shared/docs/looks.md`), in single precision as theirs.
//!
//! The unknown is the profile's own parameter `s` alone: at the height
//! `y(s)` the ray lies on the circle of radius `|x(s)|` when
//! `f(s) = a^2 + b^2 - c^2 = 0`, with `a`, `b` the ray's radial offsets at
//! that height and `c` the radius, all times the ray's axial direction.
//! Newton starts from 1001 parameters spread evenly over the curve's range
//! (ends included) and runs at most 100 steps, each `s - s f / f'`: the
//! Newton step **times `s`**, so that near `s = 0` it crawls (the root is
//! approached at the rate `1 - s` per step) and a start ends as a root only
//! once `|f|` falls below 1e-6, about the rounding of `f` in single
//! precision. Roots near the start of the profile are therefore missed, and
//! elsewhere a root is found or not by the rounding of each ray: surfaces
//! come out speckled, and shadow rays pass through what they miss. A start
//! that leaves the parameter range, or meets `f' = 0`, ends without a
//! root. The nearest root in front of the ray wins.
//!
//! The profile turns about y here (the look turns it about z by a
//! transform), so their axis z is our y and their x, y our x, z. The curve
//! is evaluated in double precision and rounded (theirs is single
//! throughout); a B-spline's parameter runs over their knots' range
//! `[3 / (n + 3), n / (n + 3)]` for `n` controls (a Bezier curve's over
//! [0, 1]), which matters since the step is scaled by the parameter itself.

use super::Intersection;
use super::curve::{Curve, CurveKind};
use crate::math::Ray;

/// Newton starts: `STARTS + 1` parameters, both ends of the range included.
const STARTS: u16 = 1000;
/// Newton steps per start.
const STEPS: u16 = 100;
/// `|f|` below which an iterate is a root.
const ROOT_TOLERANCE: f32 = 1e-6;
/// Roots nearer than this distance along the ray are not hits: jefflyy's
/// rays that leave a surface ignore hits closer than 1e-4 (its `rt_eps`),
/// and a single-precision root of the surface a ray leaves lies about 1e-6
/// from it, far beyond our offset of the ray's origin. (Its camera rays
/// accept any distance above 0; no surface lies that close to a camera.)
const LEAVING_DISTANCE: f64 = 1e-4;
/// Below this axial direction component the hit's distance comes from the
/// circle in the radial plane instead of the height.
const FLAT: f32 = 1e-2;

/// A ray in the surface's frame, single precision: `x`, `z` radial, `y`
/// along the axis.
#[derive(Clone, Copy)]
struct SingleRay {
    o: [f32; 3],
    d: [f32; 3],
}

/// The nearest root of jefflyy's test within `(t_min, t_max)`; `u` is our
/// curve parameter of the root (in [0, 1]).
pub fn intersect(curve: &Curve, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
    let single = SingleRay {
        o: ray.origin.map(|c| c as f32).into(),
        d: ray.direction.map(|c| c as f32).into(),
    };
    let (s_min, s_max) = parameter_range(curve);
    let t_min = t_min.max(LEAVING_DISTANCE / ray.direction.norm());
    let mut best: Option<(f32, f32)> = None;
    for i in 0..=STARTS {
        let f = f32::from(i) / f32::from(STARTS);
        let start = (1.0 - f) * s_min + f * s_max;
        let Some((t, s)) = newton(curve, &single, start, (s_min, s_max)) else {
            continue;
        };
        let t_wide = f64::from(t);
        let nearer = best.is_none_or(|(best_t, _)| t < best_t);
        if t_wide > t_min && t_wide < t_max && nearer {
            best = Some((t, s));
        }
    }
    let (t, s) = best?;
    let u = (f64::from(s) - f64::from(s_min)) / (f64::from(s_max) - f64::from(s_min));
    Some(Intersection::new(f64::from(t), u.clamp(0.0, 1.0), 0.0))
}

/// jefflyy's parameter range of `curve`: a Bezier curve's [0, 1], a cubic
/// B-spline's `[3, n] / (n + 3)` over its uniform knots `i / (n + 3)`.
fn parameter_range(curve: &Curve) -> (f32, f32) {
    match curve.kind() {
        CurveKind::Bezier => (0.0, 1.0),
        CurveKind::Bspline => {
            let n = curve.controls().len() as f32;
            (3.0 / (n + 3.0), n / (n + 3.0))
        }
    }
}

/// The profile's point and its derivative with respect to jefflyy's
/// parameter `s`, rounded to single precision.
fn profile_at(curve: &Curve, s: f32, (s_min, s_max): (f32, f32)) -> ([f32; 2], [f32; 2]) {
    let width = f64::from(s_max) - f64::from(s_min);
    let u = (f64::from(s) - f64::from(s_min)) / width;
    let (point, derivative) = curve.evaluate(u);
    let tangent = derivative / width;
    (
        [point.x as f32, point.y as f32],
        [tangent.x as f32, tangent.y as f32],
    )
}

/// One start's Newton iteration: the hit's distance and parameter, if it
/// ends on a root whose distance their test accepts.
fn newton(curve: &Curve, ray: &SingleRay, mut s: f32, range: (f32, f32)) -> Option<(f32, f32)> {
    let ([ox, oy, oz], [dx, dy, dz]) = (ray.o, ray.d);
    for _ in 0..STEPS {
        // Out of range (or not a number): no root.
        if !(s >= range.0 && s <= range.1) {
            return None;
        }
        let (point, tangent) = profile_at(curve, s, range);
        let a = ox * dy + dx * (point[1] - oy);
        let b = oz * dy + dz * (point[1] - oy);
        let c = dy * point[0];
        let f = a * a + b * b - c * c;
        if f.abs() < ROOT_TOLERANCE {
            return hit_distance(ray, point).map(|t| (t, s));
        }
        let (a, b, c) = (f64::from(a), f64::from(b), f64::from(c));
        let slope = 2.0 * a * f64::from(dx) * f64::from(tangent[1])
            + 2.0 * b * f64::from(dz) * f64::from(tangent[1])
            - 2.0 * c * f64::from(dy) * f64::from(tangent[0]);
        if slope == 0.0 {
            return None;
        }
        let wide = f64::from(s);
        let next = (wide - wide * f64::from(f) / slope) as f32;
        if next == s {
            // Stuck (at s = 0, or a step below rounding): every further
            // step would be this one, and |f| stays too large.
            return None;
        }
        s = next;
    }
    None
}

/// The ray's distance to the root at profile point `point`: from the
/// height when the ray is not flat, else from the circle of radius
/// `|x|` in the radial plane (the far crossing from inside it, the near
/// one from outside); `None` when the ray misses that circle or it lies
/// behind.
fn hit_distance(ray: &SingleRay, point: [f32; 2]) -> Option<f32> {
    let ([ox, oy, oz], [dx, dy, dz]) = (ray.o, ray.d);
    if dy.abs() > FLAT {
        return Some((point[1] - oy) / dy);
    }
    let from_axis = ox * ox + oz * oz;
    let radius = point[0] * point[0];
    let flat = (dx * dx + dz * dz).sqrt();
    let along = -(ox * (dx / flat) + oz * (dz / flat));
    if from_axis >= radius && along <= 0.0 {
        return None;
    }
    let apart = from_axis - along * along;
    if apart >= radius {
        return None;
    }
    let half_chord = (radius - apart).sqrt();
    let t = if from_axis > radius {
        along - half_chord
    } else {
        along + half_chord
    };
    Some(t / (dx * dx + dy * dy + dz * dz).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Profile;
    use crate::math::{Point3, Vec3};

    fn cylinder(kind: CurveKind) -> Curve {
        let controls = (0..4).map(|i| [1.0, f64::from(i)]).collect();
        Curve::new(&Profile { kind, controls }).expect("a curve")
    }

    #[test]
    fn a_b_spline_runs_over_its_knots_range() {
        let spline = cylinder(CurveKind::Bspline);
        assert_eq!(parameter_range(&spline), (3.0 / 7.0, 4.0 / 7.0));
        assert_eq!(parameter_range(&cylinder(CurveKind::Bezier)), (0.0, 1.0));
    }

    #[test]
    fn a_ray_across_a_cylinder_meets_its_near_side_where_roots_are_found() {
        // A unit cylinder from y = 0 to 3, crossed level with y = 2.4
        // (s = 0.8: quick convergence) from x = -5.
        let curve = cylinder(CurveKind::Bezier);
        let ray = Ray::new(Point3::new(-5.0, 2.4, 0.0), Vec3::new(1.0, 0.001, 0.0), 0.0);
        let hit = intersect(&curve, &ray, 0.0, f64::INFINITY).expect("a hit");
        assert!((hit.t - 4.0).abs() < 1e-3, "{}", hit.t);
    }
}
