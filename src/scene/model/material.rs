//! The material model: what every dialect's material becomes (the weights
//! of the original's lobes, the lobes some dialects add, its images and
//! how they are read).

use crate::bsdf::phong::Phong;
use crate::bsdf::{AngularWeights, ConductorFresnel, MIN_ROUGHNESS};
use crate::color::Color;
use crate::medium::Medium;
use crate::spectral::Dispersion;
use crate::texture::checker::Checker;
use crate::texture::uv_rule::UvRule;

/// One normalised material: the weights of the original's three lobes
/// (`diffuse + specular + refract`, normally 1), what each of them is, and
/// the lobes that some dialects add on top (see `docs/materials.md` for the
/// table from dialect fields to these).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub color: Color,
    /// What the material emits, its `boost` (or `illumination`) included.
    pub emission: Color,
    /// The factor `boost` (rub) or `illumination` put into `emission`: rub's
    /// renderer applies it only to emitters seen after a bounce, so the
    /// `rub` look divides it out of emitters seen directly.
    pub boost: f64,
    pub diffuse: f64,
    pub specular: f64,
    pub refract: f64,
    pub ior: f64,
    /// Index into `Scene::textures`.
    pub texture: Option<usize>,
    /// Where `texture` is read: afb's rules from the world point (`Func`);
    /// `None`: at the shape's uv.
    pub uv_rule: Option<UvRule>,
    /// cav's `textureScale`: the factor of its texture coordinates before
    /// they wrap (1 when not written; only the `cav` look reads it).
    pub texture_scale: f64,
    /// A procedural colour at the world point (rub's `checkerTexture`),
    /// instead of `texture` and `color`.
    pub checker: Option<Checker>,
    /// Index into `Scene::textures`: a tangent-space normal map.
    pub normal_map: Option<usize>,
    /// A greyscale height map (bump map).
    pub bump: Option<Bump>,
    /// GGX roughness `alpha` of the specular and refract lobes: 0 is a
    /// perfect mirror and smooth glass, larger is a rough conductor and a
    /// rough dielectric.
    pub roughness: f64,
    /// What the diffuse weight scatters by.
    pub diffuse_model: DiffuseModel,
    /// The Fresnel term of the specular weight (a conductor).
    pub conductor_fresnel: ConductorFresnel,
    /// A Phong lobe added on top of the weights (PA1 `specularColor` and
    /// `shininess`).
    pub phong: Option<Phong>,
    /// A GGX specular coat added on top of the weights (`glossy`, bow's
    /// `GlossyMaterial`).
    pub coat: Option<Coat>,
    /// osb's `glossy 1`: in looks that render it, the diffuse weight is
    /// osb's own glossy weight and `coat` is left out (see
    /// `bsdf::osb_glossy`); elsewhere `coat` is its physical reading.
    pub osb_glossy: bool,
    /// Weights of the specular and refract lobes that depend on the angle of
    /// incidence (cav's `Fresnel { fbase fscale power }`); they replace
    /// `specular` and `refract`, and the diffuse weight is the rest.
    pub angular_weights: Option<AngularWeights>,
    /// The medium inside the shapes of this material (a `Medium` block in
    /// the material): a ray that crosses their surface inwards enters it,
    /// one that crosses outwards returns to the scene's medium. `None`:
    /// crossing the surface does not change the medium.
    pub interior: Option<Medium>,
    /// An `interface`: the surface neither scatters nor emits, rays cross
    /// it unchanged (only the medium changes: the boundary of a medium).
    pub interface: bool,
    /// How the index of its refract lobe depends on the wavelength
    /// (Cambrian's `cauchy`, yuzc19's `dispersion` flag); `None`: `ior`
    /// for every wavelength.
    pub dispersion: Option<Dispersion>,
}

impl Material {
    /// White, fully diffuse, not emitting, IOR 1.5.
    pub const DEFAULT: Material = Material {
        color: Color::WHITE,
        emission: Color::BLACK,
        boost: 1.0,
        diffuse: 1.0,
        specular: 0.0,
        refract: 0.0,
        ior: 1.5,
        texture: None,
        uv_rule: None,
        texture_scale: 1.0,
        checker: None,
        normal_map: None,
        bump: None,
        roughness: 0.0,
        diffuse_model: DiffuseModel::Lambert,
        conductor_fresnel: ConductorFresnel::Constant,
        phong: None,
        coat: None,
        osb_glossy: false,
        angular_weights: None,
        interior: None,
        interface: false,
        dispersion: None,
    };

    /// Whether some lobe of the material is a perfect mirror or smooth glass
    /// (what light subpaths for caustics go through).
    pub fn has_delta_lobe(&self) -> bool {
        let smooth = self.roughness < MIN_ROUGHNESS;
        (smooth && (self.specular > 0.0 || self.refract > 0.0 || self.angular_weights.is_some()))
            || self.coat.is_some_and(|c| c.alpha < MIN_ROUGHNESS)
    }
}

impl Default for Material {
    fn default() -> Self {
        Material::DEFAULT
    }
}

/// A height map: the grey value `g` of the texture (in [0, 1]) lifts the
/// surface along its normal by `scale * (2 g - 1)` world units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bump {
    /// Index into `Scene::textures`.
    pub texture: usize,
    pub scale: f64,
}

/// What the diffuse weight of a material scatters by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DiffuseModel {
    /// Lambert: `color / pi`.
    Lambert,
    /// rub's Cook-Torrance (`cookTorrence a F0 x`): GGX with `alpha`, a
    /// Schlick Fresnel term from the scalar `f0`, and the Schlick-Smith
    /// shadowing with `k = (alpha + 1)^2 / 8`, times the colour.
    CookTorrance { alpha: f64, f0: f64 },
}

/// A conductor lobe added on top of the weights, with its own colour: a
/// GGX coat (`alpha`), or a mirror at `alpha` 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coat {
    pub alpha: f64,
    /// Reflectance (constant Fresnel) or reflectance at normal incidence (Schlick).
    pub color: Color,
    pub fresnel: ConductorFresnel,
}
