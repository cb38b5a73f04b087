//! The course framework's ray casting (the PA1 look): the first hit only,
//! shaded for every point and directional light by the framework's Phong
//! term, with no shadows, no ambient light and no bounces.
//!
//! `kd max(0, n . l) + ks max(0, v . r)^shininess`, times the light's
//! colour, with `r = 2 (n . l) n - l` from the unclamped `n . l` and `v`
//! towards the eye; the specular term is not gated by `n . l`, and lights
//! do not fall off with distance (Achazwl's and aliezlo's `rc`, looks.md).
//! `kd` is the material's colour or texel, `ks` and the exponent its
//! `specularColor` and `shininess`. A ray that misses gives the background.
//! `n` faces the ray, except in the looks that shade with the normal as the
//! shape stores it (`Look::normals_as_stored`).

use crate::color::Color;
use crate::math::{Point3, Ray, Vec3};
use crate::scene::model::Light;
use crate::shading::Shading;

use crate::render_scene::RenderScene;

pub fn radiance(scene: &RenderScene, ray: Ray) -> Color {
    let Some(hit) = scene.intersect(&ray) else {
        return scene.background();
    };
    let mut at = scene.shade(&hit, &ray);
    if scene.look().normals_as_stored && !at.entering {
        // Back on the side the shape's normal points to (a triangle's winding).
        at.normal = -at.normal;
    }
    let v = -ray.direction;
    let mut sum = at.material.emission;
    for light in scene.lights() {
        if let Some(toward) = toward_light(light, &at.point) {
            sum += phong(&at, &v, &toward.direction) * toward.color;
        }
    }
    sum
}

/// Where a point or directional light is seen from a point, and its colour
/// there (no falloff with distance).
pub struct TowardLight {
    /// Unit direction to the light.
    pub direction: Vec3,
    pub color: Color,
    /// Distance to the light (infinite for a directional light).
    pub distance: f64,
}

/// The light `light` as seen from `point`; `None` for area lights (which
/// are emitting shapes) and a point light at the point itself.
pub fn toward_light(light: &Light, point: &Point3) -> Option<TowardLight> {
    let toward = |position: &Point3| {
        let offset = position - point;
        let distance = offset.norm();
        offset
            .try_normalize(1e-300)
            .map(|direction| (direction, distance))
    };
    match light {
        Light::Point { position, color } => {
            toward(position).map(|(direction, distance)| TowardLight {
                direction,
                color: *color,
                distance,
            })
        }
        Light::Directional { direction, color } => {
            (-direction).try_normalize(1e-300).map(|l| TowardLight {
                direction: l,
                color: *color,
                distance: f64::INFINITY,
            })
        }
        Light::Spot {
            position,
            direction,
            color,
            exponent,
        } => toward(position).map(|(l, distance)| TowardLight {
            direction: l,
            color: *color * direction.dot(&-l).max(0.0).powf(*exponent),
            distance,
        }),
        Light::Disk { .. } | Light::Area { .. } => None,
    }
}

/// The framework's Phong term at `at` for a light in the unit direction
/// `l`, seen from `v`: `kd max(0, n . l) + ks max(0, v . r)^shininess`,
/// `r = 2 (n . l) n - l` from the unclamped `n . l`, the specular term not
/// gated by `n . l`.
pub fn phong(at: &Shading, v: &Vec3, l: &Vec3) -> Color {
    let n = at.normal;
    let cos = n.dot(l);
    let diffuse = at.color * cos.max(0.0);
    match at.material.phong {
        Some(p) if !p.color.is_black() => {
            let r: Vec3 = n * (2.0 * cos) - l;
            diffuse + p.color * v.dot(&r).max(0.0).powf(p.exponent)
        }
        _ => diffuse,
    }
}
