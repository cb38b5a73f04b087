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
//! | `osb_glossy`, in looks that render it | osb's glossy weight instead of Lambert, and no coat | `diffuse` |
//!
//! cav's `angular_weights` replace the three weights by their
//! angle-dependent values at each hit (and the glass then refracts only: its
//! reflection is the specular weight). The weighted lobes take the hit's
//! colour as their tint; Phong and the coat keep their own.

use super::LobeSet;
use super::conductor::Conductor;
use super::cook_torrance::CookTorrance;
use super::dielectric::{Dielectric, GlassChoice};
use super::fresnel::DielectricFresnel;
use super::lambert::Lambert;
use super::lobe::Lobe;
use super::osb_glossy::OsbGlossy;
use super::phong::Phong;
use super::rough_dielectric::RoughDielectric;
use crate::color::Color;
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

/// What a look decides about the lobes of a material.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LookLobes {
    /// Whether Phong lobes (PA1's `specularColor`/`shininess`) are rendered.
    pub phong: bool,
    /// Whether osb's `glossy` is its own renderer's weight (see
    /// [`OsbGlossy`]) rather than a physical GGX coat.
    pub osb_glossy: bool,
}

impl LobeSet {
    /// The lobes of `material` (see the module documentation); the tints
    /// of the weighted lobes are the hit's colour.
    pub fn from_material(material: &Material, look: LookLobes) -> LobeSet {
        let osb_glossy = look.osb_glossy && material.osb_glossy;
        let mut set = LobeSet {
            ior: material.ior,
            angular: material.angular_weights,
            ..LobeSet::default()
        };
        let angular = material.angular_weights.is_some();
        // With angular weights every one of the three lobes is kept, its
        // weight set per hit.
        let (diffuse, specular, refract) = if angular {
            (0.0, 0.0, 0.0)
        } else {
            (material.diffuse, material.specular, material.refract)
        };
        let placeholder = Color::WHITE;
        if diffuse > MIN_DIFFUSE_RATE || angular {
            let lobe = match material.diffuse_model {
                DiffuseModel::Lambert if osb_glossy => {
                    Lobe::OsbGlossy(OsbGlossy { color: placeholder })
                }
                DiffuseModel::Lambert => Lobe::Lambert(Lambert {
                    albedo: placeholder,
                }),
                DiffuseModel::CookTorrance { alpha, f0 } => Lobe::CookTorrance(CookTorrance {
                    color: placeholder,
                    alpha: alpha.max(MIN_ROUGHNESS),
                    f0,
                }),
            };
            set.push_slot(lobe, diffuse, true, true);
        }
        let alpha = material.roughness;
        if specular > 0.0 || angular {
            let conductor = Conductor {
                tint: placeholder,
                alpha,
                fresnel: material.conductor_fresnel,
            };
            set.push_slot(Lobe::Conductor(conductor), specular, true, true);
        }
        if refract > 0.0 || angular {
            let lobe = if alpha < MIN_ROUGHNESS {
                Lobe::Dielectric(Dielectric {
                    tint: placeholder,
                    eta_above: 1.0,
                    eta_below: material.ior,
                    fresnel: DielectricFresnel::None,
                    choice: GlassChoice::default(),
                })
            } else {
                Lobe::RoughDielectric(RoughDielectric {
                    tint: placeholder,
                    alpha,
                    eta_above: 1.0,
                    eta_below: material.ior,
                    fresnel: DielectricFresnel::None,
                })
            };
            // cav's glass only refracts: its reflection is the conductor.
            set.push_slot(lobe, refract, true, !angular);
            let pushed = matches!(
                set.lobes.last(),
                Some(Lobe::Dielectric(_) | Lobe::RoughDielectric(_))
            );
            set.dispersion = material.dispersion.filter(|_| pushed);
        }
        if let Some(phong) = material.phong.filter(|_| look.phong) {
            let lobe = Phong {
                color: phong.color,
                exponent: phong.exponent.max(0.0),
            };
            set.push_slot(Lobe::Phong(lobe), 1.0, false, true);
        }
        if let Some(coat) = material.coat.filter(|_| !osb_glossy) {
            let lobe = Conductor {
                tint: coat.color,
                alpha: coat.alpha,
                fresnel: coat.fresnel,
            };
            set.push_slot(Lobe::Conductor(lobe), 1.0, false, true);
        }
        set
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
