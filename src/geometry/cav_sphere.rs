//! cav's sphere test in its own single-precision arithmetic
//! (CaveSpiderLZJ/PathTracingFinal, `include/sphere.hpp`,
//! `include/object3d.hpp`, `src/main.cpp`), which the `cav` look keeps
//! because the lights of its scenes depend on it:
//!
//! - a ray leaves a surface from the hit point moved 1e-5 along its new
//!   direction, and a hit counts from a distance of 1e-4;
//! - the distance of the centre to the ray's line is measured to the foot
//!   of the perpendicular, the half chord and the origin's distance to
//!   that foot are square roots of differences of squares, all in `f32`;
//! - the origin is *inside* when its distance to the centre is at most
//!   the radius; from inside, the hit is the far root when the centre lies
//!   ahead and the near one when it lies behind, and its normal points
//!   **inwards**; from outside, only the near root of a sphere ahead counts.
//!
//! Its lights are caps of radius-600 spheres under the ceiling. There the
//! rounding of the hit distance (about 1e-4 at that scale) puts most points
//! of the cap a little inside the sphere, and a diffuse ray leaving such a
//! point downwards meets the cap again from inside when the point lies deep
//! enough (about one bounce in twenty): the path collects the light's
//! emission twice, and more when it is caught between the cap and the
//! ceiling. Small spheres see rounding errors far below 1e-4, so they
//! look as ours do; a ray refracted into one starts 1e-5 inside it and
//! meets its far side from inside, with the inward normal.

use crate::math::{Point3, Ray, Vec3};

/// cav's smallest accepted hit distance (`TMIN`).
pub const MIN_DISTANCE: f32 = 1e-4;

/// How far along its direction cav moves the origin of a ray that leaves a
/// surface (`DELTA`).
pub const LEAVING_OFFSET: f64 = 1e-5;

/// Where a ray meets the sphere by cav's test: the distance along our ray,
/// and whether the ray started inside (then the normal points inwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CavHit {
    pub t: f64,
    pub inside: bool,
}

type V = [f32; 3];

fn to_f32(v: &Vec3) -> V {
    [v.x as f32, v.y as f32, v.z as f32]
}

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V, b: V) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn distance(a: V, b: V) -> f32 {
    let d = sub(a, b);
    dot(d, d).sqrt()
}

/// The hit of `ray` (its origin a camera or a surface point) with the
/// sphere (`center`, `radius`) in `(t_min, t_max)` by cav's test, the ray
/// starting `LEAVING_OFFSET` along its direction as cav's do. As in cav's
/// code, `t` is a distance along the normalised direction whatever the
/// length of `ray.direction`: for a direction shorter than a unit, the
/// point `ray.at(t)` falls short of the sphere, and `t` compares with
/// other shapes' (in units of the direction) as cav's group compares them.
#[inline]
pub fn intersect(
    center: &Point3,
    radius: f64,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<CavHit> {
    let length = ray.direction.norm();
    if length == 0.0 || !length.is_finite() {
        return None;
    }
    let unit = ray.direction / length;
    let origin = to_f32(&(ray.origin + unit * LEAVING_OFFSET));
    let raw = to_f32(&unit);
    let norm = dot(raw, raw).sqrt();
    let direction = [raw[0] / norm, raw[1] / norm, raw[2] / norm];
    let centre = to_f32(center);
    let radius = radius as f32;
    let along = dot(direction, sub(centre, origin));
    let ahead = along >= 0.0;
    let foot = [
        origin[0] + along * direction[0],
        origin[1] + along * direction[1],
        origin[2] + along * direction[2],
    ];
    let off_axis = distance(centre, foot);
    if off_axis > radius {
        return None;
    }
    let from_origin = distance(centre, origin);
    let half_chord = (radius * radius - off_axis * off_axis).sqrt();
    let to_foot = (from_origin * from_origin - off_axis * off_axis).sqrt();
    let inside = from_origin <= radius;
    let t = match (inside, ahead) {
        (false, false) => return None,
        (false, true) => to_foot - half_chord,
        (true, true) => to_foot + half_chord,
        (true, false) => half_chord - to_foot,
    };
    // NaN (a negative square root from rounding) fails as in cav's test.
    if t.is_nan() || t < MIN_DISTANCE {
        return None;
    }
    let t = f64::from(t) + LEAVING_OFFSET;
    (t > t_min && t < t_max).then_some(CavHit { t, inside })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_from_outside_the_near_root_and_from_inside_the_far_one() {
        let center = Point3::new(0.5, -1.0, 2.0);
        let outside = Ray::new(Point3::new(0.5, -1.0, -8.0), Vec3::z(), 0.0);
        let hit = intersect(&center, 2.0, &outside, 0.0, f64::INFINITY).expect("hit");
        assert!((hit.t - 8.0).abs() < 1e-5 && !hit.inside, "{hit:?}");
        let from_centre = Ray::new(center, Vec3::new(0.0, 0.6, 0.8), 0.0);
        let hit = intersect(&center, 2.0, &from_centre, 0.0, f64::INFINITY).expect("hit");
        assert!((hit.t - 2.0).abs() < 1e-5 && hit.inside, "{hit:?}");
        let away = Ray::new(Point3::new(0.5, -1.0, -8.0), -Vec3::z(), 0.0);
        assert_eq!(intersect(&center, 2.0, &away, 0.0, f64::INFINITY), None);
    }

    #[test]
    fn measures_along_the_normalised_direction_whatever_its_length() {
        // cav's t is a distance: a direction of length 0.5 meets the
        // sphere 8 away at t = 8 (not 16), whose point falls halfway; and
        // the range applies to that distance.
        let center = Point3::new(0.5, -1.0, 2.0);
        let short = Ray::new(Point3::new(0.5, -1.0, -8.0), Vec3::z() * 0.5, 0.0);
        let hit = intersect(&center, 2.0, &short, 0.0, f64::INFINITY).expect("hit");
        assert!((hit.t - 8.0).abs() < 1e-5, "{hit:?}");
        assert!((short.at(hit.t).z - -4.0).abs() < 1e-5);
        assert_eq!(intersect(&center, 2.0, &short, 0.0, 7.0), None);
    }
}
