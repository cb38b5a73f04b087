//! Points sampled on the surface of a shape, as seen from a reference
//! point: the emitter half of the shape contract (`Shape::area`,
//! `Shape::sample`, `Shape::pdf`). A uniform area density becomes a density
//! in solid angle by `dist^2 / (|cos_light| area)`; emitters are two-sided,
//! as in the original estimator, which adds emission whichever side a ray
//! hits.

use crate::math::{Point3, Vec3};
use crate::trig::sin_cos_turns;

/// Below this `|cos|` at the light, a sampled point is dropped (the density
/// in solid angle would be unbounded; such points carry no energy anyway).
const MIN_LIGHT_COSINE: f64 = 1e-12;

/// A point chosen on a shape, seen from the reference point.
#[derive(Clone, Copy, Debug)]
pub struct ShapeSample {
    pub point: Point3,
    /// Unit direction from the reference point to `point`.
    pub direction: Vec3,
    pub distance: f64,
    /// Density of `direction` in solid angle.
    pub pdf: f64,
}

/// A uniformly chosen area point (of a region of area `area`) turned into
/// a direction with its solid-angle density.
pub fn from_area_sample(
    reference: &Point3,
    point: &Point3,
    normal: &Vec3,
    area: f64,
) -> Option<ShapeSample> {
    let offset = point - reference;
    let distance = offset.norm();
    if !(distance > 0.0 && distance.is_finite()) {
        return None;
    }
    let direction = offset / distance;
    let pdf = area_to_solid_angle(reference, point, normal, area);
    (pdf > 0.0 && pdf.is_finite()).then_some(ShapeSample {
        point: *point,
        direction,
        distance,
        pdf,
    })
}

/// `dist^2 / (|cos_light| * area)`: a uniform area density seen from `reference`.
pub fn area_to_solid_angle(reference: &Point3, point: &Point3, normal: &Vec3, area: f64) -> f64 {
    let offset = point - reference;
    let distance_squared = offset.norm_squared();
    let distance = distance_squared.sqrt();
    if !(distance > 0.0 && area > 0.0) {
        return 0.0;
    }
    let cosine = normal.dot(&offset).abs() / distance;
    if cosine < MIN_LIGHT_COSINE {
        return 0.0;
    }
    distance_squared / (cosine * area)
}

/// A uniform unit vector.
pub fn uniform_sphere(u: [f64; 2]) -> Vec3 {
    let z = 1.0 - 2.0 * u[0];
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (sin, cos) = sin_cos_turns(u[1]);
    Vec3::new(r * cos, r * sin, z)
}

/// Shirley and Chiu's concentric map from the unit square to the unit disk
/// (uniform density; the original's squared-uniform lens was not).
pub fn concentric_disk(square: [f64; 2]) -> (f64, f64) {
    let a = 2.0 * square[0] - 1.0;
    let b = 2.0 * square[1] - 1.0;
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    // The angle in turns: pi/4 (b/a), or pi/2 - pi/4 (a/b), over 2 pi.
    let (radius, turns) = if a.abs() > b.abs() {
        let turns = 0.125 * (b / a);
        (a, if turns < 0.0 { turns + 1.0 } else { turns })
    } else {
        (b, 0.25 - 0.125 * (a / b))
    };
    let (sin, cos) = sin_cos_turns(turns);
    (radius * cos, radius * sin)
}
