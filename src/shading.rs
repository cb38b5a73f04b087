//! What a surface hit means for light transport: the material, its colour
//! (texture or constant), and normals oriented towards the incoming ray.

use crate::color::Color;
use crate::math::{Point3, Ray, Vec3, offset_origin};
use crate::scene::model::{Material, Scene};
use crate::world::{UvMapping, WorldHit};

/// A hit seen from the ray that found it.
pub struct Shading<'a> {
    pub point: Point3,
    pub material: &'a Material,
    /// Texture colour where the material has a texture, else its colour.
    pub color: Color,
    /// Unit geometric normal on the side the ray came from.
    pub geometric: Vec3,
    /// Unit shading normal (interpolated, normal-mapped) on that same side.
    pub normal: Vec3,
    /// Whether the ray arrived from the outside (the side the geometric normal
    /// points to): decides entering or leaving glass for every shape.
    pub entering: bool,
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
        let mut normal = match material.normal_map.and_then(|i| scene.textures.get(i)) {
            Some(map) => perturb(hit, map.lookup(hit.uv[0], hit.uv[1])),
            None => hit.shading_normal,
        };
        if normal.dot(&geometric) < 0.0 {
            normal = -normal;
        }
        let color = match material.texture.and_then(|i| scene.textures.get(i)) {
            Some(texture) => match hit.uv_mapping {
                UvMapping::Unit => texture.lookup(hit.uv[0], hit.uv[1]),
                UvMapping::Tiled => texture.lookup_tiled(hit.uv[0], hit.uv[1]),
            },
            None => material.color,
        };
        Shading {
            point: hit.point,
            material,
            color,
            geometric,
            normal,
            entering,
        }
    }

    /// The origin of a ray leaving this point in `direction`: pushed off the
    /// surface along the geometric normal, to the side the ray goes to (see
    /// [`offset_origin`]), so that it cannot re-hit the surface.
    pub fn spawn_origin(&self, direction: &Vec3) -> Point3 {
        offset_origin(&self.point, &self.geometric, direction)
    }
}

/// Tangent-space normal mapping: texel (r, g, b) in [0, 1] is the normal
/// (2r - 1, 2g - 1, 2b - 1) in the frame (tangent, bitangent, normal), the
/// tangent along `dpdu`.
fn perturb(hit: &WorldHit, texel: Color) -> Vec3 {
    let n = hit.shading_normal;
    // dpdu is not normalised: the tolerance is relative to its length.
    let t = (hit.dpdu - n * n.dot(&hit.dpdu)).try_normalize(1e-12 * hit.dpdu.norm());
    let Some(t) = t else { return n };
    let b = n.cross(&t);
    let local = Vec3::new(
        2.0 * texel.r - 1.0,
        2.0 * texel.g - 1.0,
        2.0 * texel.b - 1.0,
    );
    (t * local.x + b * local.y + n * local.z)
        .try_normalize(1e-12)
        .unwrap_or(n)
}
