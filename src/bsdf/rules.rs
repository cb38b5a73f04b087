//! The conventions of a rendering that shape the lobes: the look's and the
//! estimator's ([`Rules`], applied per hit), and what a look decides about
//! the lobes a material makes ([`LookLobes`], applied when the render scene
//! makes them: `render_scene::lobes`).

use super::dielectric::GlassChoice;
use super::fresnel::DielectricFresnel;

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
