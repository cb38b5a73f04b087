//! Estimators of the radiance arriving along a camera ray.

pub mod lights;
pub mod original;

use crate::color::Color;
use crate::math::Ray;
use crate::sampler::Sampler;
use crate::scene::model::{Light, Scene};
use crate::world::World;

/// Which estimator renders the image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrator {
    /// The original renderer's estimator (see docs/original-renderer.md).
    Original,
}

impl Integrator {
    pub fn radiance(&self, view: &SceneView, ray: Ray, sampler: &mut Sampler) -> Color {
        match self {
            Integrator::Original => original::radiance(view, ray, sampler),
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
    /// Scattering vertices before a path ends (the original: 5).
    pub max_depth: u32,
}

impl<'a> SceneView<'a> {
    pub fn new(scene: &'a Scene, world: &'a World) -> SceneView<'a> {
        SceneView {
            scene,
            world,
            direct_lights: lights::direct_lights(scene),
            max_depth: original::MAX_DEPTH,
        }
    }
}
