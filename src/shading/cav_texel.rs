//! cav's texture lookup (CaveSpiderLZJ/PathTracingFinal,
//! `src/material.cpp`): the texel of an image at a hit as its renderer
//! reads it.
//!
//! Its coordinates (u, v) are multiplied by the material's `textureScale`,
//! wrapped into [0, 1) with floor, and the texel is column `int(u w)`, row
//! `int(v h)` counted from the top of the file (not flipped), each byte
//! divided by **256**. A plane's (u, v) are its point's coordinates along
//! cav's frame, in world units (see `Plane::with_cav_frame`); other shapes
//! keep their uv.

use crate::color::Color;
use crate::geometry::UvMapping;
use crate::geometry::plane::PLANE_TILING;
use crate::texture::Texture;
use crate::world::WorldHit;

/// cav's divisor of a byte, where images are decoded by 255.
const BYTE_SCALE: f64 = 255.0 / 256.0;

/// The colour of `image` at `hit` by cav's rule, its coordinates times
/// `scale`. The image is stored upside down in the `cav` look (its rows
/// top-down, `TextureRows::Down`), so [`Texture::lookup`] reads row
/// `v h` from the top of the file.
#[inline]
pub fn cav_texel(image: &Texture, hit: &WorldHit, scale: f64) -> Color {
    let (u, v) = match hit.uv_mapping {
        UvMapping::Tiled => (hit.uv[0] / PLANE_TILING, hit.uv[1] / PLANE_TILING),
        UvMapping::Unit => (hit.uv[0], hit.uv[1]),
    };
    let wrap = |x: f64| {
        let scaled = x * scale;
        scaled - scaled.floor()
    };
    image.lookup(wrap(u), wrap(v)) * BYTE_SCALE
}
