//! 24-bit BMP encoding through the `bmp` crate, and the length a BMP
//! header promises (to call a short file truncated, with what it lacks).

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

/// Checks that a BMP file is as long as its header says: its pixel rows
/// start at the header's offset and take `height` rows of `width` pixels
/// at its bits per pixel, each padded to 4 bytes. Not BMP, or compressed
/// (whose length the header does not give): nothing to check.
pub fn check_complete(bytes: &[u8]) -> Result<(), String> {
    if !bytes.starts_with(b"BM") {
        return Ok(());
    }
    let word = |at: usize| -> Option<u32> {
        let b = bytes.get(at..at + 4)?;
        Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    let half = |at: usize| -> Option<u16> {
        let b = bytes.get(at..at + 2)?;
        Some(u16::from_le_bytes([b[0], b[1]]))
    };
    let (Some(offset), Some(header_size)) = (word(10), word(14)) else {
        return Err(format!(
            "truncated: {} bytes, shorter than a BMP file header (18 bytes)",
            bytes.len()
        ));
    };
    if header_size < 40 {
        // An OS/2 core header: rare, left to the decoder.
        return Ok(());
    }
    let (Some(width), Some(height), Some(bits), Some(compression)) =
        (word(18), word(22), half(28), word(30))
    else {
        return Err(format!(
            "truncated: {} bytes, shorter than its BMP headers ({} bytes)",
            bytes.len(),
            14 + header_size
        ));
    };
    // BI_RGB or BI_BITFIELDS: uncompressed rows.
    if compression != 0 && compression != 3 {
        return Ok(());
    }
    let (width, height) = (width as i32 as i64, height as i32 as i64);
    let row_bytes = (width.unsigned_abs() * bits as u64).div_ceil(32) * 4;
    let expected = offset as u64 + row_bytes * height.unsigned_abs();
    if (bytes.len() as u64) < expected {
        return Err(format!(
            "truncated: its header describes a {}x{} image of {bits} bits per pixel, {expected} \
             bytes with its pixel rows, but the file has {} bytes ({} missing)",
            width.abs(),
            height.abs(),
            bytes.len(),
            expected - bytes.len() as u64
        ));
    }
    Ok(())
}
