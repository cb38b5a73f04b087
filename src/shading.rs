//! What a surface hit means for light transport: the material, its colour
//! (a procedural checker at the world point, a texture at the hit's uv or by
//! the material's `uv_rule`, or constant), and normals (interpolated, normal- and bump-mapped,
//! see `surface_maps`) oriented towards the incoming ray.

use crate::bsdf::{Bsdf, LobeSet, Rules};
use crate::color::Color;
use crate::math::{Point3, Ray, Vec3};
use crate::scene::model::{Material, Scene};
use crate::surface_maps;
use crate::world::{self, WorldHit};

/// A hit seen from the ray that found it.
pub struct Shading<'a> {
    pub point: Point3,
    pub material: &'a Material,
    /// Its index in the scene's materials.
    pub material_index: usize,
    /// Texture colour where the material has a texture, else its colour.
    pub color: Color,
    /// Unit geometric normal on the side the ray came from.
    pub geometric: Vec3,
    /// Unit shading normal (interpolated, normal-mapped) on that same side.
    pub normal: Vec3,
    /// Whether the ray arrived from the outside (the side the geometric normal
    /// points to): decides entering or leaving glass for every shape.
    pub entering: bool,
    /// Rays leave from `point` itself (see [`WorldHit::leaves_from_point`]).
    pub leaves_from_point: bool,
}

impl<'a> Shading<'a> {
    pub fn new(scene: &'a Scene, hit: &WorldHit, ray: &Ray) -> Shading<'a> {
        let material = scene
            .materials
            .get(hit.material)
            .unwrap_or(&Material::DEFAULT);
        let entering = hit.geometric_normal.dot(&ray.direction) < 0.0;
        let geometric = if entering {
            hit.geometric_normal
        } else {
            -hit.geometric_normal
        };
        // Interpolated normal, then the normal map, then the bump map.
        let mut normal = match material.normal_map.and_then(|i| scene.textures.get(i)) {
            Some(map) => surface_maps::normal_mapped(hit, hit.shading_normal, map),
            None => hit.shading_normal,
        };
        if let Some(bump) = material.bump
            && let Some(map) = scene.textures.get(bump.texture)
        {
            normal = surface_maps::bumped(hit, normal, map, bump.scale);
        }
        if normal.dot(&geometric) < 0.0 {
            normal = -normal;
        }
        let color = surface_color(scene, material, hit);
        Shading {
            point: hit.point,
            material,
            material_index: hit.material,
            color,
            geometric,
            normal,
            entering,
            leaves_from_point: hit.leaves_from_point,
        }
    }

    /// The BSDF of this hit, made of `set` (its material's lobes), for
    /// light leaving towards `wo` (unit, on the side of the normals).
    #[inline(always)]
    pub fn bsdf<'s>(&self, set: &'s LobeSet, wo: &Vec3, rules: Rules) -> Bsdf<'s> {
        let cos_o = self.normal.dot(wo);
        Bsdf::new(set, self.color, &self.normal, self.entering, cos_o, rules)
    }

    /// The origin of a ray leaving this point in `direction`, as for the hit
    /// it was made from ([`world::spawn_origin`]).
    #[inline]
    pub fn spawn_origin(&self, direction: &Vec3) -> Point3 {
        world::spawn_origin(
            &self.point,
            &self.geometric,
            self.leaves_from_point,
            direction,
        )
    }
}

/// The colour of `material` at `hit`: its checker at the world point, its
/// texture at the hit's uv or where its `uv_rule` says, or its `color`.
fn surface_color(scene: &Scene, material: &Material, hit: &WorldHit) -> Color {
    if let Some(checker) = &material.checker {
        return checker.color_at(&hit.point);
    }
    let Some(texture) = material.texture.and_then(|i| scene.textures.get(i)) else {
        return material.color;
    };
    match material.uv_rule {
        None => surface_maps::texel_at(texture, hit),
        Some(rule) => {
            let [a, b] = rule.coordinates(&hit.point, hit.t, hit.uv);
            texture.lookup_rows_down(a, b)
        }
    }
}
