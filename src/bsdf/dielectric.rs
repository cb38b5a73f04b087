//! Smooth dielectrics (glass): a delta lobe that reflects or refracts by a
//! roulette on the Fresnel reflectance.
//!
//! Refracted light keeps its radiance (smallpt's glass, no factor of the
//! squared index ratio): for a closed object seen and lit from outside the
//! factors of entering and leaving cancel, so the image is the physical one.

use super::LobeSample;
use super::fresnel::{DielectricFresnel, dielectric};
use crate::color::Color;
use crate::math::Vec3;

/// How the glass lobe chooses between reflection and refraction.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GlassChoice {
    /// smallpt's roulette: reflect with probability 0.25 + R / 2.
    Smallpt,
    /// Reflect with probability R: the weights are exactly the tint, the
    /// same expectation with less variance.
    #[default]
    Fresnel,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dielectric {
    pub tint: Color,
    /// Index on the side of the outgoing direction (+z).
    pub eta_above: f64,
    /// Index on the other side.
    pub eta_below: f64,
    pub fresnel: DielectricFresnel,
    pub choice: GlassChoice,
}

impl Dielectric {
    /// One of the two directions; `uc` in [0, 1) decides.
    pub fn sample(&self, wo: &Vec3, uc: f64) -> LobeSample {
        let cos_o = wo.z.abs();
        let reflected = Vec3::new(-wo.x, -wo.y, wo.z);
        let reflectance = dielectric(self.fresnel, cos_o, self.eta_above, self.eta_below);
        let reflect = |weight: f64| LobeSample {
            wi: reflected,
            weight: self.tint * weight,
            pdf: 1.0,
            delta: true,
        };
        if reflectance >= 1.0 {
            return reflect(1.0);
        }
        let eta = self.eta_above / self.eta_below;
        let cos_t = (1.0 - eta * eta * (1.0 - cos_o * cos_o)).max(0.0).sqrt();
        let refracted = LobeSample {
            wi: Vec3::new(-eta * wo.x, -eta * wo.y, -cos_t.copysign(wo.z)),
            weight: self.tint,
            pdf: 1.0,
            delta: true,
        };
        if reflectance <= 0.0 {
            return refracted;
        }
        let p = match self.choice {
            GlassChoice::Smallpt => 0.25 + 0.5 * reflectance,
            GlassChoice::Fresnel => reflectance.clamp(1e-6, 1.0 - 1e-6),
        };
        if uc < p {
            reflect(reflectance / p)
        } else {
            LobeSample {
                weight: self.tint * ((1.0 - reflectance) / (1.0 - p)),
                ..refracted
            }
        }
    }
}
