//! 24-bit BMP encoding through the `bmp` crate.

use super::Image;
use super::quantize::Quantizer;
use super::tonemap::Encoding;

/// Encodes `image` as a 24-bit BMP file held in memory.
pub(super) fn encode(image: &Image, encoding: &Encoding) -> Result<Vec<u8>, String> {
    let quantizer = Quantizer::new(encoding)?;
    // The bmp crate computes the file size in u32; refuse what would overflow it.
    let row_bytes = (image.width as u64) * 3 + (image.width as u64 % 4);
    if row_bytes * image.height as u64 + 54 > u32::MAX as u64 {
        return Err(format!(
            "a {}x{} image is too large for a BMP file",
            image.width, image.height
        ));
    }
    let (width, height) = (image.width as u32, image.height as u32);
    let mut bitmap = bmp::Image::new(width, height);
    for (y, row) in image.pixels.chunks_exact(image.width).enumerate() {
        for (x, &color) in row.iter().enumerate() {
            let [r, g, b] = quantizer.rgb(color);
            // `set_pixel` takes y = 0 at the top, like `Image`.
            bitmap.set_pixel(x as u32, y as u32, bmp::Pixel::new(r, g, b));
        }
    }
    let mut bytes = Vec::new();
    bitmap
        .to_writer(&mut bytes)
        .map_err(|e| format!("cannot encode BMP: {e}"))?;
    Ok(bytes)
}
