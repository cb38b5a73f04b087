//! The Lambert lobe: `albedo / pi`, sampled by the cosine.

use std::f64::consts::PI;

use super::LobeSample;
use crate::color::Color;
use crate::math::Vec3;
use crate::trig::sin_cos_turns;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lambert {
    pub albedo: Color,
}

impl Lambert {
    #[inline]
    pub fn sample(&self, u: [f64; 2]) -> LobeSample {
        let wi = cosine_hemisphere(u);
        LobeSample {
            wi,
            weight: self.albedo,
            pdf: wi.z / PI,
            delta: false,
        }
    }

    pub fn eval(&self, wi: &Vec3) -> Color {
        self.albedo * (wi.z.max(0.0) / PI)
    }

    pub fn pdf(&self, wi: &Vec3) -> f64 {
        wi.z.max(0.0) / PI
    }
}

/// A cosine-distributed direction about +z (density `z / pi`).
#[inline]
pub fn cosine_hemisphere(u: [f64; 2]) -> Vec3 {
    let (sin, cos) = sin_cos_turns(u[0]);
    let r2 = u[1];
    let r = r2.sqrt();
    Vec3::new(cos * r, sin * r, (1.0 - r2).max(0.0).sqrt())
}
