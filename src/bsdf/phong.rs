//! The energy-normalised Phong lobe (Lafortune and Willems, "Using the
//! modified Phong reflectance model for physically based rendering", 1994):
//! `color (n + 2) / (2 pi) cos^n(a)`, `a` the angle between the incoming
//! direction and the mirror direction of the outgoing one. At normal
//! incidence it reflects at most `color`; it is reciprocal, since the
//! mirror of `wo` makes the same angle with `wi` as the mirror of `wi` with
//! `wo`. It is sampled by `cos^n(a)` about the mirror direction over the
//! whole sphere; the directions below the surface carry nothing.

use std::f64::consts::PI;

use super::LobeSample;
use crate::color::Color;
use crate::math::{Vec3, orthonormal_basis};
use crate::trig::sin_cos_turns;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Phong {
    pub color: Color,
    pub exponent: f64,
}

impl Phong {
    fn mirror(wo: &Vec3) -> Vec3 {
        Vec3::new(-wo.x, -wo.y, wo.z)
    }

    /// `cos^n(a)`, 0 beyond a right angle from the mirror direction.
    fn lobe(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        let cos_a = Phong::mirror(wo).dot(wi);
        if cos_a > 0.0 {
            cos_a.powf(self.exponent)
        } else {
            0.0
        }
    }

    pub fn sample(&self, wo: &Vec3, u: [f64; 2]) -> LobeSample {
        let n = self.exponent;
        let cos_a = u[0].powf(1.0 / (n + 1.0));
        let sin_a = (1.0 - cos_a * cos_a).max(0.0).sqrt();
        let (sin_phi, cos_phi) = sin_cos_turns(u[1]);
        let axis = Phong::mirror(wo);
        let (t, b) = orthonormal_basis(&axis);
        let wi = t * (sin_a * cos_phi) + b * (sin_a * sin_phi) + axis * cos_a;
        let weight = if wi.z > 0.0 && wo.z > 0.0 {
            self.color * ((n + 2.0) / (n + 1.0) * wi.z)
        } else {
            Color::BLACK
        };
        LobeSample {
            wi,
            weight,
            pdf: (n + 1.0) / (2.0 * PI) * cos_a.powf(n),
            delta: false,
        }
    }

    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        if wi.z <= 0.0 || wo.z <= 0.0 {
            return Color::BLACK;
        }
        let n = self.exponent;
        self.color * ((n + 2.0) / (2.0 * PI) * self.lobe(wo, wi) * wi.z)
    }

    pub fn pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        let n = self.exponent;
        (n + 1.0) / (2.0 * PI) * self.lobe(wo, wi)
    }
}
