//! OpenEXR encoding (32-bit float RGB, linear radiance) through the `image`
//! crate's pure-Rust `exr` backend.

use std::io::Cursor;

use image::codecs::openexr::OpenExrEncoder;
use image::{ExtendedColorType, ImageEncoder};

use super::Image;

/// Encodes `image` as an RGB float EXR file held in memory.
pub(super) fn encode(image: &Image) -> Result<Vec<u8>, String> {
    let bytes: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|c| [c.r as f32, c.g as f32, c.b as f32])
        .flat_map(f32::to_ne_bytes)
        .collect();
    let mut out = Cursor::new(Vec::new());
    OpenExrEncoder::new(&mut out)
        .write_image(
            &bytes,
            image.width as u32,
            image.height as u32,
            ExtendedColorType::Rgb32F,
        )
        .map_err(|e| format!("cannot encode EXR: {e}"))?;
    Ok(out.into_inner())
}
