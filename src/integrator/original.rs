//! The original renderer's estimator, iterative: emission at every vertex, at
//! most five scattering vertices, one lobe chosen per vertex by the rates.
//!
//! The original traced the diffuse and mirror lobes both (branching) and both
//! glass lobes at the first two bounces; choosing one lobe with probability
//! equal to its weight and dividing by that probability has the same expected
//! value, and costs one path per sample.

use crate::color::Color;
use crate::math::Ray;
use crate::sampler::Sampler;
use crate::sampling::{cosine_hemisphere, reflect};
use crate::shading::Shading;

use super::SceneView;
use super::lobes::{GlassChoice, Lobe, Lobes, glass_direction, pa1_lights};

/// Scattering vertices of the original before a path ends.
pub const MAX_DEPTH: u32 = 5;

pub fn radiance(view: &SceneView, mut ray: Ray, sampler: &mut Sampler) -> Color {
    let mut result = Color::BLACK;
    let mut throughput = Color::WHITE;
    let mut depth = 0;
    loop {
        let Some(hit) = view.world.intersect(&ray, 0.0, f64::INFINITY) else {
            if depth == 0 {
                result += throughput * view.scene.background;
            }
            break;
        };
        let at = Shading::new(view.scene, &hit, &ray);
        let material = at.material;
        result += throughput * material.emission;
        depth += 1;
        if depth > view.max_depth || at.color.is_black() {
            break;
        }
        let lobes = Lobes::of(material);
        result += throughput * pa1_lights(view, &at, &lobes);
        if lobes.total() <= 0.0 {
            break;
        }
        throughput *= at.color * lobes.total();
        let direction = match lobes.pick(sampler.next_f64()) {
            Lobe::Diffuse => cosine_hemisphere(&at.normal, sampler.next_2d()),
            Lobe::Mirror => reflect(&ray.direction, &at.normal),
            Lobe::Glass => {
                glass_direction(&ray, &at, sampler, &mut throughput, GlassChoice::Smallpt)
            }
        };
        ray = Ray::new(at.spawn_origin(&direction), direction, ray.time);
    }
    result
}
