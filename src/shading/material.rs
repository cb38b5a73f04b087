//! A material as a render reads it: its lobes made once for the look, where
//! its colour comes from, its normal and height maps, what it emits and the
//! medium behind its surface. The render-time scene holds one per scene
//! material (see `render_scene`); a hit finds everything here.

use std::sync::Arc;

use super::surface_maps;
use crate::bsdf::LobeSet;
use crate::bsdf::phong::Phong;
use crate::color::Color;
use crate::medium::Medium;
use crate::texture::Texture;
use crate::texture::checker::Checker;
use crate::texture::uv_rule::UvRule;
use crate::world::WorldHit;

/// One material, ready for shading.
#[derive(Clone, Debug)]
pub struct RenderMaterial {
    /// The lobes of its BSDF, with the look's rules applied.
    pub lobes: LobeSet,
    /// The colour that tints the weighted lobes at a hit.
    pub color: SurfaceColor,
    pub emission: Color,
    /// The factor already in `emission` that rub's renderer applies only
    /// to emitters seen after a bounce (`Material::boost`).
    pub boost: f64,
    /// A tangent-space normal map.
    pub normal_map: Option<Arc<Texture>>,
    /// A height map, and the world units a grey step of 1 lifts the surface.
    pub bump: Option<(Arc<Texture>, f64)>,
    /// PA1's `specularColor` and `shininess` (what ray casting shades with).
    pub phong: Option<Phong>,
    /// The medium inside the shapes of this material (the scene material's
    /// `interior`: a ray that crosses their surface inwards enters it).
    pub interior: Option<Medium>,
    /// Rays cross the surface unchanged: the boundary of a medium.
    pub interface: bool,
}

/// Where the colour of a surface comes from.
#[derive(Clone, Debug)]
pub struct SurfaceColor {
    pub source: ColorSource,
    /// The material's colour times the source (Cambrian's `colour x
    /// texture`, in looks that multiply); `None`: the source alone.
    pub tint: Option<Color>,
}

/// The colour of a surface before its tint.
#[derive(Clone, Debug)]
pub enum ColorSource {
    Constant(Color),
    /// rub's procedural checker at the world point.
    Checker(Checker),
    /// An image at the hit's uv (`rule: None`) or where afb's `Func` rule
    /// puts the world point.
    Texture {
        image: Arc<Texture>,
        rule: Option<UvRule>,
    },
    /// An image read as cav's renderer reads it (see [`super::cav_texel`]),
    /// its coordinates times `scale` (the material's `textureScale`).
    CavTexture {
        image: Arc<Texture>,
        scale: f64,
    },
}

impl SurfaceColor {
    /// The colour at `hit`.
    #[inline]
    pub fn at(&self, hit: &WorldHit) -> Color {
        let color = match &self.source {
            ColorSource::Constant(color) => *color,
            ColorSource::Checker(checker) => checker.color_at(&hit.point),
            ColorSource::Texture { image, rule: None } => surface_maps::texel_at(image, hit),
            ColorSource::CavTexture { image, scale } => super::cav_texel(image, hit, *scale),
            ColorSource::Texture {
                image,
                rule: Some(rule),
            } => {
                let [a, b] = rule.coordinates(&hit.point, hit.t, hit.uv);
                image.lookup_rows_down(a, b)
            }
        };
        match self.tint {
            Some(tint) => color * tint,
            None => color,
        }
    }
}
