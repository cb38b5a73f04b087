//! From a material to its BSDF: which lobe each weight and field of the
//! built material becomes (the dialect fields behind them are listed in
//! `docs/materials.md`).
//!
//! | material | lobe | weight |
//! |---|---|---|
//! | `diffuse` with `DiffuseModel::Lambert` | Lambert, albedo = colour (texture) | `diffuse` (ignored at or below 1e-4, as the original) |
//! | `diffuse` with `DiffuseModel::CookTorrance` | rub's Cook-Torrance, colour | `diffuse` |
//! | `specular`, `roughness` < 1e-3 | mirror, reflectance = colour (or Schlick from it) | `specular` |
//! | `specular`, `roughness` >= 1e-3 | GGX conductor, `alpha = roughness` | `specular` |
//! | `refract`, `roughness` < 1e-3 | smooth glass of `ior`, tint = colour | `refract` |
//! | `refract`, `roughness` >= 1e-3 | GGX rough dielectric, `alpha = roughness` | `refract` |
//! | `phong` | energy-normalised Phong of `color`, `exponent` | 1 |
//! | `coat` | GGX conductor with Schlick's term from `f0`, `alpha` | 1 |
//!
//! cav's `angular_weights` replace the specular and refract weights by
//! their angle-dependent values (and the glass then refracts only: its
//! reflection is the specular weight).

use super::Bsdf;
use super::conductor::Conductor;
use super::cook_torrance::CookTorrance;
use super::dielectric::{Dielectric, GlassChoice};
use super::fresnel::DielectricFresnel;
use super::lambert::Lambert;
use super::lobe::Lobe;
use super::phong::Phong;
use super::rough_dielectric::RoughDielectric;
use crate::color::Color;
use crate::math::Vec3;
use crate::scene::model::{AngularWeights, DiffuseModel, MIN_ROUGHNESS, Material};

/// Diffuse rates at or below this are ignored (the original's threshold).
pub const MIN_DIFFUSE_RATE: f64 = 1e-4;

/// The conventions of a rendering that shape the lobes (the look's, and
/// the estimator's).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rules {
    pub fresnel: DielectricFresnel,
    pub glass: GlassChoice,
}

/// Makes `bsdf` the BSDF of `material` at a hit (in place: a BSDF is a few
/// hundred bytes, and a vertex should not copy them): `color` is the
/// material's colour there (texture or constant), `normal` the unit shading
/// normal on the side of `wo`, `entering` whether `wo` is outside (the side
/// the geometric normal points to), `cos_o` the cosine of `wo` with the
/// normal (for angle-dependent weights).
#[inline(always)]
pub fn from_material(
    bsdf: &mut Bsdf,
    material: &Material,
    color: Color,
    normal: &Vec3,
    entering: bool,
    cos_o: f64,
    rules: Rules,
) {
    bsdf.reset(normal);
    let (diffuse, specular, refract) = match &material.angular_weights {
        None => (material.diffuse, material.specular, material.refract),
        Some(a) => a.weights(cos_o, entering, material.ior),
    };
    if diffuse > MIN_DIFFUSE_RATE {
        let lobe = match material.diffuse_model {
            DiffuseModel::Lambert => Lobe::Lambert(Lambert { albedo: color }),
            DiffuseModel::CookTorrance { alpha, f0 } => Lobe::CookTorrance(CookTorrance {
                color,
                alpha: alpha.max(MIN_ROUGHNESS),
                f0,
            }),
        };
        bsdf.push(lobe, diffuse);
    }
    let alpha = material.roughness;
    if specular > 0.0 {
        let conductor = Conductor {
            tint: color,
            alpha,
            fresnel: material.conductor_fresnel,
        };
        bsdf.push(Lobe::Conductor(conductor), specular);
    }
    if refract > 0.0 {
        let (eta_above, eta_below) = if entering {
            (1.0, material.ior)
        } else {
            (material.ior, 1.0)
        };
        let fresnel = if material.angular_weights.is_some() {
            DielectricFresnel::None
        } else {
            rules.fresnel
        };
        let lobe = if alpha < MIN_ROUGHNESS {
            Lobe::Dielectric(Dielectric {
                tint: color,
                eta_above,
                eta_below,
                fresnel,
                choice: rules.glass,
            })
        } else {
            Lobe::RoughDielectric(RoughDielectric {
                tint: color,
                alpha,
                eta_above,
                eta_below,
                fresnel,
            })
        };
        bsdf.push(lobe, refract);
    }
    if let Some(phong) = material.phong {
        let lobe = Phong {
            color: phong.color,
            exponent: phong.exponent.max(0.0),
        };
        bsdf.push(Lobe::Phong(lobe), 1.0);
    }
    if let Some(coat) = material.coat {
        let lobe = Conductor {
            tint: coat.color,
            alpha: coat.alpha,
            fresnel: coat.fresnel,
        };
        bsdf.push(Lobe::Conductor(lobe), 1.0);
    }
}

impl AngularWeights {
    /// (diffuse, specular, refract) for light leaving at `cos_o` on the
    /// outside (`entering`) or the inside of a dielectric of index `ior`.
    pub fn weights(&self, cos_o: f64, entering: bool, ior: f64) -> (f64, f64, f64) {
        let total = self.base + self.scale;
        let c = cos_o.clamp(0.0, 1.0);
        let falloff = (1.0 - c).powf(self.power);
        let reflection = if entering || ior <= 1.0 {
            self.base + self.scale * falloff
        } else if (1.0 - c * c) * ior * ior >= 1.0 {
            // Beyond the critical angle.
            total
        } else {
            let critical = 1.0 - (1.0 - 1.0 / (ior * ior)).sqrt();
            self.base + self.scale * falloff / critical.powf(self.power)
        };
        let reflection = reflection.clamp(0.0, total.max(0.0));
        (
            (1.0 - total).max(0.0),
            reflection,
            (total - reflection).max(0.0),
        )
    }
}
