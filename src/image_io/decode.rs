//! Reading files with a size cap, and decoding LDR formats through the `image` crate.

use std::fs::File;
use std::io::{Cursor, Read};
use std::path::Path;

use image::{DynamicImage, ImageReader, Limits};

use super::{Image, MAX_DIMENSION, MAX_PIXELS, PixelValues};
use crate::color::Color;

/// The largest file read: an uncompressed float RGB image at the pixel cap, plus a header.
const MAX_FILE_BYTES: u64 = (MAX_PIXELS as u64) * 12 + 4096;

/// Reads the whole file, refusing files larger than [`MAX_FILE_BYTES`].
pub(super) fn read_capped(path: &Path) -> Result<Vec<u8>, String> {
    let shown = path.display();
    let file = File::open(path).map_err(|e| format!("{shown}: cannot open: {e}"))?;
    let mut bytes = Vec::new();
    // Reading through `take` also guards against files that grow while read.
    file.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("{shown}: cannot read: {e}"))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(format!(
            "{shown}: file larger than the limit of {MAX_FILE_BYTES} bytes"
        ));
    }
    Ok(bytes)
}

/// Decodes BMP, PNG, JPEG, TGA or EXR bytes; 8-bit values become `v / 255`,
/// no gamma; float values are kept. Integer samples (8 or 16 bits) are
/// display values, float samples (EXR) linear radiance.
pub(super) fn decode_ldr(bytes: &[u8]) -> Result<(Image, PixelValues), String> {
    let mut reader = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| format!("cannot read: {e}"))?;
    if reader.format().is_none() {
        return Err(
            "unrecognised image format (readable: BMP, PNG, JPEG, TGA, PFM, EXR)".to_string(),
        );
    }
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_DIMENSION as u32);
    limits.max_image_height = Some(MAX_DIMENSION as u32);
    reader.limits(limits);
    let decoded = reader.decode().map_err(|e| format!("cannot decode: {e}"))?;
    let (width, height) = (decoded.width() as usize, decoded.height() as usize);
    if width * height > MAX_PIXELS {
        return Err(format!(
            "{width}x{height} image exceeds the limit of {MAX_PIXELS} pixels"
        ));
    }
    let encoding = match decoded {
        DynamicImage::ImageRgb32F(_) | DynamicImage::ImageRgba32F(_) => PixelValues::Linear,
        _ => PixelValues::Display,
    };
    let pixels = match decoded {
        // 8-bit sources are divided in f64 so that `v / 255` is exact to the last bit.
        DynamicImage::ImageLuma8(_)
        | DynamicImage::ImageLumaA8(_)
        | DynamicImage::ImageRgb8(_)
        | DynamicImage::ImageRgba8(_) => decoded
            .to_rgb8()
            .pixels()
            .map(|p| {
                Color::new(
                    p[0] as f64 / 255.0,
                    p[1] as f64 / 255.0,
                    p[2] as f64 / 255.0,
                )
            })
            .collect(),
        _ => decoded
            .to_rgb32f()
            .pixels()
            .map(|p| Color::new(p[0] as f64, p[1] as f64, p[2] as f64))
            .collect(),
    };
    Ok((
        Image {
            width,
            height,
            pixels,
        },
        encoding,
    ))
}
