//! What a render says about its scene before it starts: the parts of the
//! scene its integrator leaves out (participating media, dispersion) and
//! how it renders them.

use crate::look::Integrator;
use crate::scene::model::Scene;

/// A message about a render's settings, printed before it starts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Notice {
    /// How something is rendered.
    Note(String),
    /// Something in the scene that is not rendered.
    Warning(String),
}

impl std::fmt::Display for Notice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Notice::Note(text) => write!(f, "note: {text}"),
            Notice::Warning(text) => write!(f, "warning: {text}"),
        }
    }
}

/// What a render of `scene` leaves out because of its participating media,
/// one note each: the estimators other than `path` ignore media, the path
/// integrator's light subpaths are off in scenes with media.
pub fn media_notes(scene: &Scene, integrator: Integrator) -> Vec<Notice> {
    if !scene.has_media() {
        return Vec::new();
    }
    if integrator != Integrator::Path {
        let name = integrator.name();
        return vec![Notice::Note(format!(
            "the {name} estimator ignores participating media (Medium, mist): \
             '--integrator path' renders them"
        ))];
    }
    vec![Notice::Note(
        "participating media: light subpaths and split bounces (caustics) are off, \
         the path integrator samples lights and bounces only"
            .to_string(),
    )]
}

/// What a render of `scene` with `integrator` says about its dispersive
/// materials: warnings where the estimator renders them with one index
/// (the original estimator, ray casting, and the path integrator of scenes
/// with media, which stays RGB), a note that the path integrator's light
/// subpaths are off.
pub fn dispersion_notes(scene: &Scene, integrator: Integrator) -> Vec<Notice> {
    if !scene.has_dispersion() {
        return Vec::new();
    }
    let single = "renders dispersive materials with one index for all wavelengths";
    let notice = match integrator {
        Integrator::Path if scene.has_media() => Notice::Warning(format!(
            "with participating media the path integrator {single} (spectral paths \
             are not traced through media)"
        )),
        Integrator::Path => Notice::Note(
            "dispersion: a path is split to one wavelength (or one RGB channel) at \
             the first dispersive glass it meets; light subpaths and split bounces \
             (caustics) are off"
                .to_string(),
        ),
        other => Notice::Warning(format!(
            "the {} estimator {single}: '--integrator path' renders the dispersion",
            other.name()
        )),
    };
    vec![notice]
}
