//! From a material's description to its lobes: which lobe each weight and field of the
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

use crate::bsdf::conductor::Conductor;
use crate::bsdf::cook_torrance::CookTorrance;
use crate::bsdf::dielectric::Dielectric;
use crate::bsdf::osb_glossy::OsbGlossy;
use crate::bsdf::phong::Phong;
use crate::bsdf::rough_dielectric::RoughDielectric;
use crate::bsdf::{
    DielectricFresnel, GlassChoice, Lambert, Lobe, LobeSet, LookLobes, MIN_ROUGHNESS,
};
use crate::color::Color;
use crate::scene::model::{DiffuseModel, Material};

/// Diffuse rates at or below this are ignored (the original's threshold).
pub const MIN_DIFFUSE_RATE: f64 = 1e-4;

/// The lobes of `material` (see the module documentation) in a look; the
/// tints of the weighted lobes are the hit's colour.
pub fn lobe_set(material: &Material, look: LookLobes) -> LobeSet {
    let osb_glossy = look.osb_glossy && material.osb_glossy;
    let mut set = LobeSet::new(material.ior, material.angular_weights);
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
            set.weighted().last(),
            Some((Lobe::Dielectric(_) | Lobe::RoughDielectric(_), _))
        );
        set.set_dispersion(material.dispersion.filter(|_| pushed));
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

#[cfg(test)]
mod tests {
    use super::lobe_set;
    use crate::bsdf::ConductorFresnel;
    use crate::color::Color;
    use crate::look::Look;
    use crate::scene::model::{Coat, Material};

    #[test]
    fn only_the_osb_look_swaps_the_coat_for_osb_s_glossy_lobe() {
        let glossy = Material {
            osb_glossy: true,
            coat: Some(Coat {
                alpha: 0.1,
                color: Color::gray(0.2),
                fresnel: ConductorFresnel::Schlick,
            }),
            ..Material::DEFAULT
        };
        assert_eq!(lobe_set(&glossy, Look::OSB.lobes()).len(), 1);
        assert_eq!(lobe_set(&glossy, Look::PHYSICAL.lobes()).len(), 2);
    }
}
