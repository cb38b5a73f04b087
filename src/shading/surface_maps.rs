//! Images that tilt the shading normal: tangent-space normal maps and height
//! (bump) maps, both read at a hit's uv with its mapping.

use crate::color::Color;
use crate::geometry::UvMapping;
use crate::math::Vec3;
use crate::texture::Texture;
use crate::world::WorldHit;

/// The texel of `texture` at the hit's uv: clamped for [`UvMapping::Unit`],
/// wrapped for [`UvMapping::Tiled`] (as the colour texture).
pub fn texel_at(texture: &Texture, hit: &WorldHit) -> Color {
    match hit.uv_mapping {
        UvMapping::Unit => texture.lookup(hit.uv[0], hit.uv[1]),
        UvMapping::Tiled => texture.lookup_tiled(hit.uv[0], hit.uv[1]),
    }
}

/// Tangent-space normal mapping of `normal`: texel (r, g, b) in [0, 1] is the
/// normal (2r - 1, 2g - 1, 2b - 1) in the frame (tangent, bitangent, normal),
/// the tangent along `dpdu`.
pub fn normal_mapped(hit: &WorldHit, normal: Vec3, map: &Texture) -> Vec3 {
    let texel = texel_at(map, hit);
    let n = normal;
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

/// Blinn's bump mapping of `normal` by a height map: the grey value `g` (the
/// red channel of the nearest texel, wrapped around) lifts the surface by
/// `h = scale (2 g - 1)` along the normal, so the bumped surface has the
/// derivatives `dpdu + h_u n` and `dpdv + h_v n`, and the normal their cross
/// product, on the side of `normal`. `h_u` and `h_v` are central differences
/// one texel apart (a step of 1/width in u for unit uv, one texel for tiled
/// uv). The derivatives are first projected onto the plane of `normal`, so
/// that a constant height leaves an interpolated or normal-mapped normal as
/// it is.
pub fn bumped(hit: &WorldHit, normal: Vec3, map: &Texture, scale: f64) -> Vec3 {
    if map.width == 0 || map.height == 0 {
        return normal;
    }
    let (step_u, step_v) = match hit.uv_mapping {
        UvMapping::Unit => (1.0 / map.width as f64, 1.0 / map.height as f64),
        UvMapping::Tiled => (1.0, 1.0),
    };
    let [u, v] = hit.uv;
    let height = |u: f64, v: f64| {
        let grey = match hit.uv_mapping {
            UvMapping::Unit => map.lookup_wrapped(u, v).r,
            UvMapping::Tiled => map.lookup_tiled(u, v).r,
        };
        scale * (2.0 * grey - 1.0)
    };
    let h_u = (height(u + step_u, v) - height(u - step_u, v)) / (2.0 * step_u);
    let h_v = (height(u, v + step_v) - height(u, v - step_v)) / (2.0 * step_v);
    let n = normal;
    let dpdu = hit.dpdu - n * n.dot(&hit.dpdu);
    let dpdv = hit.dpdv - n * n.dot(&hit.dpdv);
    let bumped = (dpdu + n * h_u).cross(&(dpdv + n * h_v));
    let length = bumped.norm();
    if !(length > 0.0 && length.is_finite()) {
        return normal;
    }
    let bumped = bumped / length;
    if bumped.dot(&n) < 0.0 {
        -bumped
    } else {
        bumped
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Point3;

    /// A hit on the plane z = 0 with uv = (x, y) * `texels` per unit.
    fn flat_hit(uv: [f64; 2], mapping: UvMapping, per_unit: f64) -> WorldHit {
        WorldHit {
            t: 1.0,
            point: Point3::new(uv[0] / per_unit, uv[1] / per_unit, 0.0),
            geometric_normal: Vec3::z(),
            shading_normal: Vec3::z(),
            dpdu: Vec3::x() / per_unit,
            dpdv: Vec3::y() / per_unit,
            uv,
            uv_mapping: mapping,
            material: 0,
            primitive: 0,
            element: 0,
            leaves_from_point: false,
        }
    }

    #[test]
    fn handedness_of_the_derivatives_does_not_flip_the_tilt() {
        // A ramp rising along +u: the normal leans towards -u whichever way
        // dpdu x dpdv points.
        let map = Texture {
            width: 4,
            height: 1,
            texels: (0..4).map(|i| [0.1 * i as f32; 3]).collect(),
        };
        let mut hit = flat_hit([0.6, 0.5], UvMapping::Unit, 1.0);
        let right = bumped(&hit, Vec3::z(), &map, 0.01);
        hit.dpdv = -hit.dpdv;
        let left = bumped(&hit, Vec3::z(), &map, 0.01);
        assert!(right.x < 0.0 && right.z > 0.0, "{right:?}");
        assert!((right - left).norm() < 1e-12, "{right:?} {left:?}");
    }

    #[test]
    fn empty_map_changes_nothing() {
        let map = Texture {
            width: 0,
            height: 0,
            texels: Vec::new(),
        };
        let hit = flat_hit([0.5, 0.5], UvMapping::Unit, 1.0);
        assert_eq!(bumped(&hit, Vec3::z(), &map, 1.0), Vec3::z());
    }
}
