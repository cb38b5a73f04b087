//! Sampling a sphere as seen from a point: uniformly in the cone it
//! subtends from outside, by area from inside (or from its own surface).

use std::f64::consts::PI;

use super::Sphere;
use super::surface_samples::{ShapeSample, area_to_solid_angle, from_area_sample, uniform_sphere};
use crate::math::{Point3, Vec3, orthonormal_basis};
use crate::trig::sin_cos_turns;

/// A reference point within this relative margin of a sphere's radius counts
/// as inside (area sampling), so points on the sphere itself are handled.
const SURFACE_MARGIN: f64 = 1e-6;

/// The cone a sphere subtends from an outside point.
pub struct Cone {
    /// Unit axis towards the centre.
    axis: Vec3,
    distance: f64,
    cos_max: f64,
    /// `1 - cos_max`, computed without cancellation.
    one_minus_cos_max: f64,
    /// Uniform density over the cone.
    pub pdf: f64,
}

impl Sphere {
    /// Surface area.
    pub fn area(&self) -> f64 {
        4.0 * PI * self.radius * self.radius
    }

    /// A uniform point on the surface at shutter time `time`, and its unit normal.
    pub fn sample_area(&self, time: f64, u: [f64; 2]) -> (Point3, Vec3) {
        let normal = uniform_sphere(u);
        (self.center_at(time) + normal * self.radius, normal)
    }

    /// The cone the sphere subtends at `time` from `reference`; `None`
    /// when `reference` is inside or on the surface.
    pub fn cone(&self, time: f64, reference: &Point3) -> Option<Cone> {
        let offset = self.center_at(time) - reference;
        let distance_squared = offset.norm_squared();
        let radius_squared = self.radius * self.radius;
        if distance_squared <= radius_squared * (1.0 + SURFACE_MARGIN) {
            return None;
        }
        let distance = distance_squared.sqrt();
        let sin2_max = radius_squared / distance_squared;
        let cos_max = (1.0 - sin2_max).max(0.0).sqrt();
        let one_minus_cos_max = sin2_max / (1.0 + cos_max);
        Some(Cone {
            axis: offset / distance,
            distance,
            cos_max,
            one_minus_cos_max,
            pdf: 1.0 / (2.0 * PI * one_minus_cos_max),
        })
    }

    /// A point seen from `reference` at `time`: in the cone from outside,
    /// by area from inside.
    pub fn sample_from(&self, reference: &Point3, time: f64, u: [f64; 2]) -> Option<ShapeSample> {
        let Some(cone) = self.cone(time, reference) else {
            let (point, normal) = self.sample_area(time, u);
            return from_area_sample(reference, &point, &normal, self.area());
        };
        // cos(theta) uniform in [cos_max, 1].
        let one_minus_cos = u[0] * cone.one_minus_cos_max;
        let cos_theta = 1.0 - one_minus_cos;
        let sin_theta = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
        let (sin_phi, cos_phi) = sin_cos_turns(u[1]);
        let (t, b) = orthonormal_basis(&cone.axis);
        // Unit to rounding in the orthonormal frame of the axis.
        let direction =
            t * (sin_theta * cos_phi) + b * (sin_theta * sin_phi) + cone.axis * cos_theta;
        // Nearest intersection along the direction: d cos - sqrt(r^2 - d^2 sin^2).
        let d = cone.distance;
        let perpendicular2 = d * d * sin_theta * sin_theta;
        let half_chord = (self.radius * self.radius - perpendicular2).max(0.0).sqrt();
        let distance = d * cos_theta - half_chord;
        debug_assert!(cos_theta >= cone.cos_max - 1e-9);
        if !(distance > 0.0 && distance.is_finite()) {
            return None;
        }
        Some(ShapeSample {
            point: reference + direction * distance,
            direction,
            distance,
            pdf: cone.pdf,
        })
    }

    /// The solid-angle density with which [`Sphere::sample_from`] gives
    /// `point` (unit normal `normal`).
    pub fn pdf_from(&self, reference: &Point3, time: f64, point: &Point3, normal: &Vec3) -> f64 {
        match self.cone(time, reference) {
            Some(cone) => cone.pdf,
            None => area_to_solid_angle(reference, point, normal, self.area()),
        }
    }
}
