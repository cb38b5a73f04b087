//! 8-bit RGB PNG encoding through the `image` crate.

use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder};

use super::Image;
use super::quantize::Quantizer;
use super::tonemap::Encoding;

/// Encodes `image` as an 8-bit RGB PNG file held in memory.
pub(super) fn encode(image: &Image, encoding: &Encoding) -> Result<Vec<u8>, String> {
    let quantizer = Quantizer::new(encoding)?;
    let samples: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|&color| quantizer.rgb(color))
        .collect();
    let mut bytes = Vec::new();
    PngEncoder::new(&mut bytes)
        .write_image(
            &samples,
            image.width as u32,
            image.height as u32,
            ExtendedColorType::Rgb8,
        )
        .map_err(|e| format!("cannot encode PNG: {e}"))?;
    Ok(bytes)
}
