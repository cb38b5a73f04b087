//! The point and directional lights of PA1 scenes, added at diffuse vertices.
//!
//! The course framework shades with `albedo * color * max(0, n . l)` and no
//! distance falloff; the port adds exactly that radiance with a shadow ray, so
//! that a PA1 scene looks as its author saw it.

use crate::color::Color;
use crate::scene::model::{Light, Scene};
use crate::shading::Shading;
use crate::world::World;

/// The lights that are sampled by shadow rays (see `SceneView::direct_lights`).
pub fn direct_lights(scene: &Scene) -> &[Light] {
    let mut has_emitter = false;
    scene.root.for_each_leaf(&mut |leaf| {
        for m in leaf.materials().filter_map(|i| scene.materials.get(i)) {
            has_emitter |= !m.emission.is_black();
        }
    });
    if has_emitter { &[] } else { &scene.lights }
}

/// Radiance reflected at a diffuse vertex from the point and directional lights.
/// The caller weights it by the diffuse rate and the path throughput.
pub fn direct(world: &World, lights: &[Light], at: &Shading) -> Color {
    let mut sum = Color::BLACK;
    for light in lights {
        let (to_light, distance, color) = match light {
            Light::Point { position, color } => {
                let offset = position - at.point;
                let distance = offset.norm();
                if distance <= 0.0 {
                    continue;
                }
                (offset / distance, distance, *color)
            }
            Light::Directional { direction, color } => {
                let Some(d) = (-direction).try_normalize(1e-12) else {
                    continue;
                };
                (d, f64::INFINITY, *color)
            }
            // Disk and area lights are emitting geometry in the world (the
            // scene builder adds it): found by rays, not here.
            Light::Disk { .. } | Light::Area { .. } => continue,
        };
        let cosine = at.normal.dot(&to_light);
        if cosine <= 0.0 || at.geometric.dot(&to_light) <= 0.0 {
            continue;
        }
        let origin = at.spawn_origin(&to_light);
        let shadow = crate::math::Ray::new(origin, to_light, 0.0);
        if world.occluded(&shadow, 0.0, distance * (1.0 - 1e-9)) {
            continue;
        }
        sum += at.color * color * cosine;
    }
    sum
}
