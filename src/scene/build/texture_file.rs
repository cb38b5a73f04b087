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
/// Returns it with the course framework's reading of the same file where
/// that differs ([`framework_bmp_reading`]).
pub fn read_texture_readings(
    file: &Path,
    budget: MemoryBudget,
) -> Result<(Texture, Option<Texture>), String> {
    let bytes = read_within(file, MAX_TEXTURE_BYTES, "limits::MAX_TEXTURE_BYTES")?;
    let texture = decode_texture(&bytes, file, budget)?;
    let framework = framework_bmp_reading(&bytes)
        .filter(|read| (read.width, read.height) == (texture.width, texture.height));
    Ok((texture, framework))
}

fn decode_texture(bytes: &[u8], file: &Path, budget: MemoryBudget) -> Result<Texture, String> {
    check_decodable(bytes, file, budget, DECODING_BYTES_PER_TEXEL)?;
    if is_pfm(bytes) {
        let (image, _) = decode_image(bytes, file)?;
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
    let mut reader = reader_for(bytes, file)?;
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

/// Where the course framework's `Image::LoadBMP` starts reading pixels:
/// the end of the 14-byte file header and the 40-byte info header.
const FRAMEWORK_BMP_PIXELS_AT: usize = 54;

/// A 24-bit uncompressed BMP as the course framework's `Image::LoadBMP`
/// reads it (Cambrian-yzt/PathTracer `src/image.cpp`): its rows, bottom
/// first, 4-byte aligned, from byte 54 whatever the file's own pixel
/// offset (bytes 10-13) says, each byte over 255. A file with a longer
/// header (a BITMAPV5 header of 124 bytes puts the pixels at byte 138) is
/// read 84 bytes early: its first 28 texels are header bytes and every
/// texel is the pixel 28 before it in the file (the last 28 pixels are
/// never read). `None` for other files and for BMPs whose
/// pixels start at byte 54 (then the reading is ours).
pub fn framework_bmp_reading(bytes: &[u8]) -> Option<Texture> {
    let word = |at: usize| -> Option<u32> {
        Some(u32::from_le_bytes(bytes.get(at..at + 4)?.try_into().ok()?))
    };
    if bytes.get(..2)? != [b'B', b'M'] {
        return None;
    }
    let offset = word(10)? as usize;
    let (width, height) = (word(18)? as i32, word(22)? as i32);
    let bits = u16::from_le_bytes(bytes.get(28..30)?.try_into().ok()?);
    let compression = word(30)?;
    if offset == FRAMEWORK_BMP_PIXELS_AT || bits != 24 || compression != 0 {
        return None;
    }
    let (width, height) = (usize::try_from(width).ok()?, usize::try_from(height).ok()?);
    if width == 0 || height == 0 {
        return None;
    }
    let stride = (3 * width).div_ceil(4) * 4;
    let mut line = vec![0u8; stride];
    let mut texels = vec![[0.0f32; 3]; width.checked_mul(height)?];
    for row in 0..height {
        // A short read (a truncated file) keeps the rest of the previous
        // row in the buffer, as `fread` into the same line does.
        let start = FRAMEWORK_BMP_PIXELS_AT.saturating_add(row.saturating_mul(stride));
        let available = bytes.get(start..).unwrap_or(&[]);
        let n = available.len().min(stride);
        line[..n].copy_from_slice(&available[..n]);
        let top_down = height - 1 - row;
        for (column, texel) in texels[top_down * width..(top_down + 1) * width]
            .iter_mut()
            .enumerate()
        {
            let byte = |k: usize| (f64::from(line[3 * column + k]) / 255.0) as f32;
            *texel = [byte(2), byte(1), byte(0)];
        }
    }
    Some(Texture {
        width,
        height,
        texels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 24-bit BMP of `width` x 2 pixels whose pixels start at `offset`,
    /// pixel k (in file order) of colour (k, 100 + k, 200 + k) as
    /// (red, green, blue), header bytes 54.. filled with 7.
    fn bmp(width: usize, offset: usize) -> Vec<u8> {
        let stride = (3 * width).div_ceil(4) * 4;
        let mut bytes = vec![7u8; offset + 2 * stride];
        bytes[..2].copy_from_slice(b"BM");
        bytes[10..14].copy_from_slice(&(offset as u32).to_le_bytes());
        bytes[14..18].copy_from_slice(&((offset - 14) as u32).to_le_bytes());
        bytes[18..22].copy_from_slice(&(width as u32).to_le_bytes());
        bytes[22..26].copy_from_slice(&2u32.to_le_bytes());
        bytes[26..28].copy_from_slice(&1u16.to_le_bytes());
        bytes[28..30].copy_from_slice(&24u16.to_le_bytes());
        bytes[30..34].copy_from_slice(&0u32.to_le_bytes());
        for row in 0..2 {
            for column in 0..width {
                let k = (row * width + column) as u8;
                let at = offset + row * stride + 3 * column;
                bytes[at..at + 3].copy_from_slice(&[200 + k, 100 + k, k]);
            }
        }
        bytes
    }

    #[test]
    fn the_framework_reads_pixels_from_byte_54_whatever_the_header_says() {
        assert!(framework_bmp_reading(&bmp(40, 54)).is_none());
        let read = framework_bmp_reading(&bmp(40, 138)).expect("a longer header");
        assert_eq!((read.width, read.height), (40, 2));
        let value = |v: u8| (f64::from(v) / 255.0) as f32;
        // Row 0 of the file is the bottom row: our last.
        let bottom = &read.texels[40..];
        // 84 header bytes (28 texels) come first, then pixel 0 of the file.
        assert_eq!(bottom[27], [value(7), value(7), value(7)]);
        assert_eq!(bottom[28], [value(0), value(100), value(200)]);
        assert_eq!(bottom[39], [value(11), value(111), value(211)]);
        // The top row goes on 28 pixels behind: pixel 40 + 5 - 28 = 17.
        assert_eq!(read.texels[5], [value(17), value(117), value(217)]);
        assert_eq!(read.texels[39], [value(51), value(151), value(251)]);
    }
}
