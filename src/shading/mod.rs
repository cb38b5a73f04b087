//! What a surface hit means for light transport: the material, its colour
//! (see [`SurfaceColor`]), and normals (interpolated, normal- and
//! bump-mapped, see `surface_maps`) oriented towards the incoming ray.

mod cav_texel;
mod material;
pub mod surface_maps;

pub use cav_texel::cav_texel;
pub use material::{ColorSource, RenderMaterial, SurfaceColor};

use crate::bsdf::{Bsdf, Rules};
use crate::color::Color;
use crate::math::{Point3, Ray, Vec3};
use crate::world::{self, WorldHit};

/// A hit seen from the ray that found it.
pub struct Shading<'a> {
    pub point: Point3,
    pub material: &'a RenderMaterial,
    /// The material's colour at the hit (its tint included).
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
    /// The hit `hit` of `ray` on a surface of `material`.
    pub fn new(material: &'a RenderMaterial, hit: &WorldHit, ray: &Ray) -> Shading<'a> {
        let entering = hit.geometric_normal.dot(&ray.direction) < 0.0;
        let geometric = if entering {
            hit.geometric_normal
        } else {
            -hit.geometric_normal
        };
        // Interpolated normal, then the normal map, then the bump map.
        let mut normal = match &material.normal_map {
            Some(map) => surface_maps::normal_mapped(hit, hit.shading_normal, map),
            None => hit.shading_normal,
        };
        if let Some((map, scale)) = &material.bump {
            normal = surface_maps::bumped(hit, normal, map, *scale);
        }
        if normal.dot(&geometric) < 0.0 {
            normal = -normal;
        }
        Shading {
            point: hit.point,
            material,
            color: material.color.at(hit),
            geometric,
            normal,
            entering,
            leaves_from_point: hit.leaves_from_point,
        }
    }

    /// The BSDF of this hit (its material's lobes, tinted by its colour)
    /// for light leaving towards `wo` (unit, on the side of the normals).
    #[inline(always)]
    pub fn bsdf(&self, wo: &Vec3, rules: Rules) -> Bsdf<'a> {
        let cos_o = self.normal.dot(wo);
        let set = &self.material.lobes;
        let bsdf = Bsdf::new(set, self.color, &self.normal, self.entering, cos_o, rules);
        if self.leaves_from_point {
            bsdf.on_nonreciprocal(&self.geometric)
        } else {
            bsdf
        }
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
