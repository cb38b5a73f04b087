//! Reading a texture image: a regular file within
//! [`MAX_TEXTURE_BYTES`], whose header is checked against the memory budget
//! before it is decoded (a small file may claim a huge image), decoded into
//! linear texels (no gamma conversion): 8-bit values in [0, 1], PFM values
//! as stored.

use std::path::Path;

use image::Limits;

use crate::image_io::{check_decodable, decode_image, describe_error, is_pfm, reader_for};
use crate::limits::{MAX_TEXTURE_BYTES, MemoryBudget, read_within};
use crate::texture::Texture;

/// Bytes per texel while decoding: the decoder's buffer (at most RGBA f32,
/// 16 bytes), its RGB f32 copy (12) and the texture's texels (12).
const DECODING_BYTES_PER_TEXEL: u64 = 40;

/// Decodes the image `file` into a texture, within `budget`.
/// PFM files (linear values, as this renderer writes them) are read too,
/// and TGA by its extension.
pub fn read_texture(file: &Path, budget: MemoryBudget) -> Result<Texture, String> {
    let bytes = read_within(file, MAX_TEXTURE_BYTES, "limits::MAX_TEXTURE_BYTES")?;
    check_decodable(&bytes, file, budget, DECODING_BYTES_PER_TEXEL)?;
    if is_pfm(&bytes) {
        let (image, _) = decode_image(&bytes, file)?;
        return Ok(Texture {
            width: image.width,
            height: image.height,
            texels: image
                .pixels
                .iter()
                .map(|c| [c.r as f32, c.g as f32, c.b as f32])
                .collect(),
        });
    }
    let mut reader = reader_for(&bytes, file)?;
    let mut limits = Limits::default();
    limits.max_alloc = Some(budget.bytes);
    reader.limits(limits);
    let image = reader.decode().map_err(describe_error)?.to_rgb32f();
    let (width, height) = image.dimensions();
    let texels = image.pixels().map(|p| [p.0[0], p.0[1], p.0[2]]).collect();
    Ok(Texture {
        width: width as usize,
        height: height as usize,
        texels,
    })
}
