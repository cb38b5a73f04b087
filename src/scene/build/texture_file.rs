//! Reading a texture image: a regular file within
//! [`MAX_TEXTURE_BYTES`], whose header is checked against the memory budget
//! before it is decoded (a small file may claim a huge image), decoded into
//! linear [0, 1] texels (no gamma conversion).

use std::io::Cursor;
use std::path::Path;

use image::{ImageReader, Limits};

use crate::image_io::{check_decodable, describe_error};
use crate::limits::{MAX_TEXTURE_BYTES, MemoryBudget, read_within};
use crate::texture::Texture;

/// Bytes per texel while decoding: the decoder's buffer (at most RGBA f32,
/// 16 bytes), its RGB f32 copy (12) and the texture's texels (12).
const DECODING_BYTES_PER_TEXEL: u64 = 40;

/// Decodes the image `file` into a texture, within `budget`.
pub fn read_texture(file: &Path, budget: MemoryBudget) -> Result<Texture, String> {
    let bytes = read_within(file, MAX_TEXTURE_BYTES, "limits::MAX_TEXTURE_BYTES")?;
    check_decodable(&bytes, budget, DECODING_BYTES_PER_TEXEL)?;
    let mut reader = ImageReader::new(Cursor::new(&bytes))
        .with_guessed_format()
        .map_err(|e| e.to_string())?;
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
