//! The render materials of a scene: each scene material with its lobes made
//! for the look, its colour source (a texel times the colour in looks that
//! multiply), and its images resolved.

use std::sync::Arc;

use super::lobes::lobe_set;
use crate::look::{Look, TextureFrames};
use crate::scene::model::{Material, Scene};
use crate::shading::{ColorSource, RenderMaterial, SurfaceColor};
use crate::texture::Texture;

/// One render material per material of `scene`, in order.
pub fn render_materials(scene: &Scene, look: Look) -> Vec<RenderMaterial> {
    scene
        .materials
        .iter()
        .map(|material| render_material(material, &scene.textures, look))
        .collect()
}

/// The render material of a hit without a material.
pub fn default_material(look: Look) -> RenderMaterial {
    render_material(&Material::DEFAULT, &[], look)
}

fn render_material(material: &Material, textures: &[Arc<Texture>], look: Look) -> RenderMaterial {
    let image = |index: Option<usize>| index.and_then(|i| textures.get(i)).cloned();
    let source = match (&material.checker, image(material.texture)) {
        (Some(checker), _) => ColorSource::Checker(*checker),
        (None, Some(image)) if look.texture_frames == TextureFrames::Cav => {
            ColorSource::CavTexture {
                image,
                scale: material.texture_scale,
            }
        }
        (None, Some(image)) => ColorSource::Texture {
            image,
            rule: material.uv_rule,
        },
        (None, None) => ColorSource::Constant(material.color),
    };
    let tint = (look.texture_times_color && material.texture.is_some()).then_some(material.color);
    RenderMaterial {
        lobes: lobe_set(material, look.lobes()),
        color: SurfaceColor { source, tint },
        emission: material.emission,
        boost: material.boost,
        normal_map: image(material.normal_map),
        bump: material
            .bump
            .and_then(|bump| Some((image(Some(bump.texture))?, bump.scale))),
        phong: material.phong,
        interior: material.interior,
        interface: material.interface,
    }
}
