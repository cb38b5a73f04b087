//! The Newton intersector of surfaces of revolution against a fine tessellation of
//! the same profile (2,000 exact cone frusta) on random rays aimed at the bounds.

mod common;

use common::*;
use pathtracer::geometry::curve::Point2;
use pathtracer::geometry::{Curve, Revolution};
use pathtracer::math::Ray;
use pathtracer::rng::Rng;

/// Roots of `qa x^2 + 2 qb x + qc = 0` (stable form).
fn quadratic_roots(qa: f64, qb: f64, qc: f64) -> [f64; 2] {
    if qa == 0.0 {
        return [-qc / (2.0 * qb), f64::NAN];
    }
    let discriminant = qb * qb - qa * qc;
    if discriminant < 0.0 {
        return [f64::NAN; 2];
    }
    let root = -(qb + discriminant.sqrt().copysign(qb));
    [root / qa, qc / root]
}

/// Nearest hit of a ray with the surface swept by the segment a-b of the (x, y)
/// profile: an exact cone frustum. Steep segments are solved for t (s is linear in
/// y), flat ones for s (t is linear in s), so that neither divides by a tiny number.
fn frustum_hit(a: Point2, b: Point2, ray: &Ray) -> Option<f64> {
    let (o, d) = (ray.origin, ray.direction);
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    // r(t)^2 = ra t^2 + 2 rb t + rc.
    let ra = d.x * d.x + d.z * d.z;
    let rb = o.x * d.x + o.z * d.z;
    let rc = o.x * o.x + o.z * o.z;
    let mut hits = [(f64::NAN, f64::NAN); 2]; // (t, s)
    if dy.abs() >= dx.abs() {
        // s = alpha + beta t, x = p + q t.
        let (alpha, beta) = ((o.y - a.y) / dy, d.y / dy);
        let (p, q) = (a.x + dx * alpha, dx * beta);
        let roots = quadratic_roots(ra - q * q, rb - p * q, rc - p * p);
        hits = roots.map(|t| (t, alpha + beta * t));
    } else if d.y != 0.0 {
        // t = alpha + beta s.
        let (alpha, beta) = ((a.y - o.y) / d.y, dy / d.y);
        let roots = quadratic_roots(
            ra * beta * beta - dx * dx,
            ra * alpha * beta + rb * beta - a.x * dx,
            ra * alpha * alpha + 2.0 * rb * alpha + rc - a.x * a.x,
        );
        hits = roots.map(|s| (alpha + beta * s, s));
    }
    hits.into_iter()
        .filter(|&(t, s)| t > 0.0 && t.is_finite() && (0.0..=1.0).contains(&s))
        .map(|(t, _)| t)
        .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))))
}

#[test]
fn newton_revolution_agrees_with_fine_tessellation() {
    const SEGMENTS: usize = 2000;
    const RAYS: usize = 20_000;
    for (name, profile) in [
        ("vase (Bezier)", vase()),
        ("wine glass (B-spline)", wine_glass()),
    ] {
        let surface = Revolution::new(&profile).unwrap();
        let curve = Curve::new(&profile).unwrap();
        let points: Vec<Point2> = (0..=SEGMENTS)
            .map(|i| curve.evaluate(i as f64 / SEGMENTS as f64).0)
            .collect();
        let bounds = surface.bounds();
        let scale = bounds.extent().norm();
        let mut rng = Rng::new(99, 1);
        let (mut hit_miss, mut distance, mut hits, mut worst) = (0, 0, 0, 0.0f64);
        for _ in 0..RAYS {
            let mut ray = ray_at_box(&mut rng, &bounds);
            ray.direction = ray.direction.normalize();
            let reference = points
                .windows(2)
                .filter_map(|w| frustum_hit(w[0], w[1], &ray))
                .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))));
            let newton = surface.intersect(&ray, 0.0, f64::INFINITY).map(|h| h.t);
            match (reference, newton) {
                (Some(a), Some(b)) => {
                    hits += 1;
                    worst = worst.max((a - b).abs());
                    if (a - b).abs() > 1e-3 * scale {
                        distance += 1;
                    }
                }
                (None, None) => {}
                _ => hit_miss += 1,
            }
        }
        let rate = (hit_miss + distance) as f64 / RAYS as f64;
        println!(
            "{name}: {hits} hits of {RAYS} rays; hit/miss mismatches {hit_miss}, \
             |dt| > 1e-3 * size: {distance}; disagreement rate {:.4}%; \
             largest |dt| among agreeing hits {worst:.2e}",
            rate * 100.0
        );
        assert!(hits > RAYS / 4, "{name}: rays should mostly hit");
        assert!(rate < 1e-3, "{name}: disagreement rate {rate}");
    }
}

/// A profile that crosses the axis (x changes sign): the surface is the union of
/// the sweeps of both halves, and seeds must still be found near the crossing.
#[test]
fn profile_crossing_the_axis_agrees_with_tessellation() {
    let profile = pathtracer::geometry::Profile {
        kind: pathtracer::geometry::CurveKind::Bezier,
        controls: vec![[-1.0, 0.0], [0.5, 1.0], [1.5, 2.0], [-0.5, 3.0]],
    };
    let surface = Revolution::new(&profile).unwrap();
    let curve = Curve::new(&profile).unwrap();
    let points: Vec<Point2> = (0..=2000)
        .map(|i| curve.evaluate(i as f64 / 2000.0).0)
        .collect();
    let bounds = surface.bounds();
    let scale = bounds.extent().norm();
    let mut rng = Rng::new(4, 4);
    let mut disagreements = 0;
    let rays = 5000;
    for _ in 0..rays {
        let mut ray = ray_at_box(&mut rng, &bounds);
        ray.direction = ray.direction.normalize();
        let reference = points
            .windows(2)
            .filter_map(|w| frustum_hit(w[0], w[1], &ray))
            .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))));
        let newton = surface.intersect(&ray, 0.0, f64::INFINITY).map(|h| h.t);
        let agree = match (reference, newton) {
            (Some(a), Some(b)) => (a - b).abs() <= 1e-3 * scale,
            (None, None) => true,
            _ => false,
        };
        disagreements += !agree as usize;
    }
    println!("axis-crossing profile: {disagreements} disagreements in {rays} rays");
    assert!(disagreements * 1000 < rays, "{disagreements}");
}
