//! The looks' rules that change a scene's materials before they are made
//! into render materials: how a renderer picks its lobe from the weights
//! written in the file, and whether its emitters also reflect light.

use super::Look;
use crate::color::Color;
use crate::scene::model::Material;

/// How a renderer chooses the lobe of a material from its written weights.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LobeChoice {
    /// One lobe per scattering by its (normalised) weight: ours and most
    /// coursework renderers'.
    #[default]
    Weights,
    /// yangjunx21's exact tests: diffuse only where the diffuse weight is 1,
    /// a mirror only where the mirror weight is 1, and smooth glass of index
    /// 1.5 for everything else, whatever index the material gives.
    WholeWeights,
}

/// Whose reading of an OBJ's `.mtl` materials wins over the scene's
/// `MaterialIndex`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MtlReading {
    /// None: the scene's material (ours, with a warning).
    #[default]
    Ignored,
    /// emily-jia's loader and `.mtl` reader, whose materials have their
    /// `Ni` while those of the scene file have index 1
    /// (see [`crate::render_scene::emily_jia_mtl`]).
    EmilyJia,
}

/// yangjunx21's fixed index of refraction.
const YANGJUNX21_IOR: f64 = 1.5;

impl Look {
    /// `material` as this look's renderer reads it.
    pub fn adapt_material(&self, material: &mut Material) {
        if self.lobe_choice == LobeChoice::WholeWeights {
            whole_weights(material);
        }
        if !self.emitters_reflect && !material.emission.is_black() {
            // A hit on an emitter returns its emission and ends the path:
            // the same as an emitter that reflects nothing.
            material.color = Color::BLACK;
            material.texture = None;
            material.checker = None;
            material.phong = None;
            material.coat = None;
        }
    }
}

fn whole_weights(material: &mut Material) {
    let (diffuse, specular, refract) = if material.diffuse == 1.0 {
        (1.0, 0.0, 0.0)
    } else if material.specular == 1.0 {
        (0.0, 1.0, 0.0)
    } else {
        material.ior = YANGJUNX21_IOR;
        material.dispersion = None;
        (0.0, 0.0, 1.0)
    };
    material.diffuse = diffuse;
    material.specular = specular;
    material.refract = refract;
    material.angular_weights = None;
}

#[cfg(test)]
mod tests {
    use super::*;

    fn weights(m: &Material) -> (f64, f64, f64) {
        (m.diffuse, m.specular, m.refract)
    }

    #[test]
    fn whole_weights_send_every_mixed_material_to_glass_of_index_1_5() {
        let look = Look {
            lobe_choice: LobeChoice::WholeWeights,
            ..Look::ORIGINAL
        };
        let mut mixed = Material {
            diffuse: 0.5,
            specular: 0.5,
            ior: 2.4,
            ..Material::DEFAULT
        };
        look.adapt_material(&mut mixed);
        assert_eq!(weights(&mixed), (0.0, 0.0, 1.0));
        assert_eq!(mixed.ior, 1.5);
        let mut mirror = Material {
            diffuse: 0.0,
            specular: 1.0,
            ..Material::DEFAULT
        };
        look.adapt_material(&mut mirror);
        assert_eq!(weights(&mirror), (0.0, 1.0, 0.0));
        let mut plain = Material::DEFAULT;
        Look::ORIGINAL.adapt_material(&mut plain);
        assert_eq!(plain, Material::DEFAULT);
    }
}
