//! The lobes that dialect fields add to a material's three weights: the
//! table from `scene-format.md`'s field names to the BSDF's lobes and their
//! parameters (`docs/materials.md` has it with the reasons).
//!
//! | field (dialects) | lobe | parameter |
//! |---|---|---|
//! | `specularColor` + `shininess`/`exponent` (PA1 and every dialect where `specularColor` is not emission) | Phong on top of the weights | colour = `specularColor`, exponent = `shininess` (default 0) |
//! | `fuzz` (shu, cui, dst), `fuzziness` (cyf) | the specular weight becomes a GGX conductor | `alpha = 0.3 fuzz` (fuzz clamped to 1) |
//! | `roughness` (canonical, bow, piu) | the specular and refract weights become GGX | `alpha = roughness` |
//! | `GlossyMaterial { albedo roughness metallic }` (bow) | diffuse weight `1 - metallic`, plus a GGX coat | `alpha = roughness`, Schlick `F0 = 0.04 + (albedo - 0.04) metallic` |
//! | `metallic` elsewhere | not rendered (warned) | |
//! | `glossy 1` (osb) | a GGX coat on top of the diffuse weight; in the osb look, osb's own glossy weight instead (`bsdf::osb_glossy`) | `alpha = 0.1`, Schlick `F0 = 0.2`, as osb's renderer fixes them |
//! | `cookTorrence a F0 x` (rub) | the diffuse weight becomes rub's Cook-Torrance | `alpha = a`, scalar `F0` (`x` unused, as in rub) |
//! | `Fresnel { fbase fscale power }` (cav) | angle-dependent specular and refract weights | see `AngularWeights` |
//! | `reflectiveColor` (MIT 6.837 legacy) | a mirror on top of the weights | reflectance = `reflectiveColor` |
//!
//! Why `0.3 fuzz`: RTIOW's fuzzy metal reflects `normalize(r + fuzz s)`,
//! `s` uniform in the unit ball; at normal incidence the median angle of that
//! lobe to the mirror direction equals the median angle of GGX's reflected
//! lobe (twice the visible normals' angle) when `alpha = 0.304 fuzz` for
//! small fuzz and `0.293 fuzz` at fuzz 1 (computed numerically).

use crate::bsdf::ConductorFresnel;
use crate::bsdf::phong::Phong;
use crate::color::Color;
use crate::scene::build::Context;
use crate::scene::build::weights::Fields;
use crate::scene::error::SceneError;
use crate::scene::model::{Coat, DiffuseModel, Material};

/// GGX alpha per unit of RTIOW fuzz (see the module documentation).
pub const ALPHA_PER_FUZZ: f64 = 0.3;

/// osb's glossy coat: its renderer fixes alpha and F0.
const OSB_GLOSSY_ALPHA: f64 = 0.1;
const OSB_GLOSSY_F0: f64 = 0.2;

/// Dielectric reflectance at normal incidence of bow's metallic blend.
const DIELECTRIC_F0: f64 = 0.04;

pub fn add_lobes(
    context: &mut Context,
    f: &Fields,
    name: &str,
    specular_is_emission: bool,
    material: &mut Material,
) -> Result<(), SceneError> {
    if let Some(fuzz) = f.fuzz {
        material.roughness = ALPHA_PER_FUZZ * fuzz.clamp(0.0, 1.0);
    }
    if let Some(roughness) = f.roughness {
        material.roughness = roughness.max(0.0);
    }
    if let Some(specular) = f.specular_color
        && !specular_is_emission
        && !specular.is_black()
    {
        material.phong = Some(Phong {
            color: specular,
            exponent: f.shininess.map_or(0.0, |(n, _)| n.max(0.0)),
        });
    } else if let Some((_, at)) = f.shininess {
        let why = if specular_is_emission {
            "specularColor is the emission in this dialect"
        } else {
            "specularColor is black or absent"
        };
        context.not_rendered(at, "shininess", why)?;
    }
    if name == "GlossyMaterial" {
        let metallic = f.metallic.map_or(0.0, |(m, _)| m.clamp(0.0, 1.0));
        let albedo = material.color;
        material.diffuse *= 1.0 - metallic;
        material.coat = Some(Coat {
            alpha: material.roughness,
            color: albedo.map(|a| DIELECTRIC_F0 + (a - DIELECTRIC_F0) * metallic),
            fresnel: ConductorFresnel::Schlick,
        });
        material.roughness = 0.0;
    } else if let Some((_, at)) = f.metallic {
        context.not_rendered(at, "metallic", "only bow's GlossyMaterial has it")?;
    }
    if f.glossy == Some(true) {
        material.osb_glossy = true;
        material.coat = Some(Coat {
            alpha: OSB_GLOSSY_ALPHA,
            color: Color::gray(OSB_GLOSSY_F0),
            fresnel: ConductorFresnel::Schlick,
        });
    }
    if let Some(reflective) = f.reflective_color.filter(|c| !c.is_black()) {
        material.coat = Some(Coat {
            alpha: 0.0,
            color: reflective,
            fresnel: ConductorFresnel::Constant,
        });
    }
    if let Some((alpha, f0)) = f.cook_torrance {
        material.diffuse_model = DiffuseModel::CookTorrance {
            alpha: alpha.abs(),
            f0: f0.clamp(0.0, 1.0),
        };
    }
    if let Some(weights) = f.angular {
        material.angular_weights = Some(weights);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::bsdf::ConductorFresnel;
    use crate::bsdf::phong::Phong;
    use crate::color::Color;
    use crate::scene::build::build_text;
    use crate::scene::model::{Coat, DiffuseModel, Material};

    fn scene(materials: &str) -> crate::scene::model::Scene {
        build_text(&format!(
            "PerspectiveCamera {{ width 2 height 2 }}\nMaterials {{\n{materials}\n}}\n\
             Group {{ Sphere {{ center 0 0 0 radius 1 }} }}"
        ))
        .expect("builds")
    }

    fn material(text: &str) -> Material {
        scene(text).materials.remove(0)
    }

    #[test]
    fn pa1_specular_fields_become_a_phong_lobe() {
        let m = material("PhongMaterial { diffuseColor 1 0 0 specularColor 1 1 1 shininess 20 }");
        let phong = Phong {
            color: Color::WHITE,
            exponent: 20.0,
        };
        assert_eq!(m.phong, Some(phong));
        assert_eq!((m.diffuse, m.color), (1.0, Color::new(1.0, 0.0, 0.0)));
        // Black specular colour: no lobe, and the exponent says so.
        let s = scene("Material { specularColor 0 0 0 shininess 20 }");
        assert_eq!(s.materials[0].phong, None);
        assert!(
            s.warnings[0]
                .message
                .contains("'shininess' is not rendered")
        );
        assert_eq!(s.warnings[0].location.line, 3);
    }

    #[test]
    fn fuzz_and_roughness_become_ggx_alpha() {
        let m = material("MetalMaterial { attenuation 0.8 0.8 0.8 fuzz 0.5 }");
        assert_eq!((m.specular, m.roughness), (1.0, 0.15));
        assert_eq!(material("Metal { fuzziness 3 }").roughness, 0.3);
        let m = material("Material { specularRate 1 roughness 0.2 }");
        assert_eq!((m.specular, m.roughness), (1.0, 0.2));
    }

    #[test]
    fn glossy_materials_get_a_coat() {
        let m = material("GlossyMaterial { albedo 0.5 0.5 0.5 roughness 0.3 metallic 0.5 }");
        assert!((m.diffuse - 0.5).abs() < 1e-12);
        let coat = m.coat.expect("coat");
        assert_eq!(coat.alpha, 0.3);
        assert!((coat.color.r - 0.27).abs() < 1e-12);
        assert_eq!(coat.fresnel, ConductorFresnel::Schlick);
        let m = material("Material { color 1 0 0 glossy 1 type 1 0 0 }");
        let coat = Coat {
            alpha: 0.1,
            color: Color::gray(0.2),
            fresnel: ConductorFresnel::Schlick,
        };
        assert_eq!(m.coat, Some(coat));
        assert!(m.osb_glossy);
        assert_eq!(material("Material { glossy 0 }").coat, None);
    }

    #[test]
    fn rub_cook_torrance_and_cav_fresnel_weights() {
        let m = material("Material { diffuseColor 1 1 1 perDiffuse 1 cookTorrence 0.4 0.9 7 }");
        let model = DiffuseModel::CookTorrance {
            alpha: 0.4,
            f0: 0.9,
        };
        assert_eq!(m.diffuse_model, model);
        let m = material(
            "Material { diffuseColor 1 1 1 refractiveIndex 1.5 Fresnel { fbase 0.05 fscale 0.92 power 10 } }",
        );
        let weights = m.angular_weights.expect("weights");
        let (d, s, r) = weights.weights(1.0, true, 1.5);
        assert!((d - 0.03).abs() < 1e-12 && (s - 0.05).abs() < 1e-12 && (r - 0.92).abs() < 1e-12);
        let (_, s, r) = weights.weights(0.0, true, 1.5);
        assert!((s - 0.97).abs() < 1e-12 && r.abs() < 1e-12);
        // Inside, beyond the critical angle: everything reflects.
        let (_, s, r) = weights.weights(0.3, false, 1.5);
        assert!((s - 0.97).abs() < 1e-12 && r == 0.0);
    }

    #[test]
    fn fields_that_are_not_rendered_warn_with_their_line() {
        let s =
            scene("Material {\n color 1 1 1\n textureScale 2\n transparency 0.5\n metallic 1 }");
        let messages: Vec<_> = s
            .warnings
            .iter()
            .map(|w| (w.location.line, w.message.clone()))
            .collect();
        assert_eq!(messages.len(), 3, "{messages:?}");
        assert!(messages[0].0 == 5 && messages[0].1.contains("'textureScale'"));
        assert!(messages[1].0 == 6 && messages[1].1.contains("'transparency'"));
        assert!(messages[2].0 == 7 && messages[2].1.contains("'metallic'"));
    }
}
