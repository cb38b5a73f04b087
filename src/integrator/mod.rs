//! Estimators of the radiance arriving along a camera ray.

pub mod lights;
pub mod lobes;
pub mod original;
pub mod path;

use crate::color::Color;
use crate::lights::Emitters;
use crate::math::Ray;
use crate::sampler::Sampler;
use crate::scene::model::{Light, Scene};
use crate::world::World;

/// Which estimator renders the image.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Integrator {
    /// The original renderer's estimator (see docs/original-renderer.md).
    Original,
    /// The same expected image with next-event estimation and multiple
    /// importance sampling at diffuse vertices (see [`path`]).
    #[default]
    Path,
}

impl Integrator {
    pub const ALL: [Integrator; 2] = [Integrator::Path, Integrator::Original];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            Integrator::Original => "original",
            Integrator::Path => "path",
        }
    }

    /// Parses a command-line name, as returned by [`Integrator::name`].
    pub fn from_name(name: &str) -> Option<Integrator> {
        Integrator::ALL.into_iter().find(|i| i.name() == name)
    }

    pub fn radiance(&self, view: &SceneView, ray: Ray, sampler: &mut Sampler) -> Color {
        match self {
            Integrator::Original => original::radiance(view, ray, sampler),
            Integrator::Path => path::radiance(view, ray, sampler),
        }
    }
}

/// Everything an estimator reads: the built scene and its geometry.
pub struct SceneView<'a> {
    pub scene: &'a Scene,
    pub world: &'a World,
    /// The point and directional lights that are added by shadow rays:
    /// those of scenes without emissive materials (the PA1 scenes, lit only by
    /// such lights). Scenes with emitters are path traced from them alone, as
    /// the coursework path tracers did.
    pub direct_lights: &'a [Light],
    /// The emissive shapes that next-event estimation samples.
    pub emitters: Emitters,
    /// Scattering vertices before a path ends (the original: 5).
    pub max_depth: u32,
}

impl<'a> SceneView<'a> {
    pub fn new(scene: &'a Scene, world: &'a World) -> SceneView<'a> {
        SceneView {
            scene,
            world,
            direct_lights: lights::direct_lights(scene),
            emitters: Emitters::build(scene, world),
            max_depth: original::MAX_DEPTH,
        }
    }
}
