//! Estimators of the radiance arriving along a camera ray, each reading a
//! [`RenderScene`].

pub mod caustics;
pub mod cav;
pub mod original;
pub mod path;
pub mod path_log;
pub mod point_lights;
pub mod ppm;
pub mod raycast;
pub mod rub;
pub mod scatter;
pub mod split;
pub mod sppm;
pub mod volpath;
pub mod whitted;

use crate::color::Color;
use crate::math::Ray;
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;
use path_log::{PathEvent, PathLog, Silent, Term};

pub use crate::look::Integrator;

impl Integrator {
    /// The radiance along the camera ray `ray` of `sample`; light that the
    /// sample's light subpath (if any) sends to other pixels goes to `splats`.
    pub fn radiance(
        &self,
        scene: &RenderScene,
        ray: Ray,
        sample: &CameraSample,
        sampler: &mut Sampler,
        splats: &mut Splats,
    ) -> Color {
        self.radiance_logged(scene, ray, sample, sampler, splats, &mut Silent)
    }

    /// [`Integrator::radiance`], reporting what the path does to `log`
    /// (ray casting and paths through media report their estimate only).
    #[inline(always)]
    pub fn radiance_logged(
        &self,
        scene: &RenderScene,
        ray: Ray,
        sample: &CameraSample,
        sampler: &mut Sampler,
        splats: &mut Splats,
        log: &mut impl PathLog,
    ) -> Color {
        let whole = match self {
            Integrator::Original => return original::radiance(scene, ray, sampler, log),
            Integrator::Path if scene.media() => volpath::radiance(scene, ray, sampler),
            Integrator::Path => return path::radiance(scene, ray, sample, sampler, splats, log),
            Integrator::RayCast => raycast::radiance(scene, ray),
            Integrator::Rub => rub::radiance(scene, ray, sampler),
            Integrator::Cav => cav::radiance(scene, ray, sampler),
            Integrator::Whitted => whitted::radiance_shadowed(scene, ray, scene.max_depth()),
            Integrator::WhittedUnshadowed => {
                whitted::radiance_unshadowed(scene, ray, scene.max_depth())
            }
            // Photon mapping renders whole passes (`render::photon_passes`), not
            // camera samples: `Renderer::new` refuses it. A camera sample
            // gets the path integrator's estimate, the image SPPM converges to.
            Integrator::Sppm => return path::radiance(scene, ray, sample, sampler, splats, log),
        };
        log.record(|| PathEvent::Added {
            depth: 0,
            term: Term::Estimate,
            mis_weight: None,
            value: whole,
        });
        whole
    }
}

/// Where a camera ray comes from: its pixel and lens sample (what light
/// tracing's MIS weights need to know of the camera's side).
#[derive(Clone, Copy, Debug, Default)]
pub struct CameraSample {
    pub pixel_x: usize,
    /// Row from the bottom of the image.
    pub pixel_y: usize,
    /// The unit-square lens sample of the ray (`[0.5, 0.5]` for a pinhole).
    pub lens: [f64; 2],
}

/// What one camera sample's light subpath adds to the film (light tracing):
/// radiance for at most the 2x2 pixels around the film position it reaches,
/// as contributions to the film's light-tracing sums, and whether a light
/// subpath was traced at all (light tracing's estimate is the sum over
/// light subpaths divided by their number).
#[derive(Clone, Copy, Debug, Default)]
pub struct Splats {
    entries: [(usize, usize, Color); 4],
    len: usize,
    pub light_paths: u32,
}

impl Splats {
    /// Adds radiance to pixel (`x`, `y`), `y` from the bottom; beyond four
    /// entries (which one film position never needs) it is dropped.
    pub fn push(&mut self, x: usize, y: usize, value: Color) {
        if self.len < self.entries.len() {
            self.entries[self.len] = (x, y, value);
            self.len += 1;
        }
    }

    pub fn iter(&self) -> impl Iterator<Item = &(usize, usize, Color)> {
        self.entries[..self.len].iter()
    }
}
