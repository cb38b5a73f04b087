//! The Portable Float Map format: linear 32-bit float pixels, rows stored bottom to top.
//!
//! Header: `PF` (RGB) or `Pf` (grayscale), the width and height, and a scale whose
//! sign gives the byte order (negative: little-endian, positive: big-endian). The
//! scale's magnitude is ignored, as most readers do. Each header field is separated
//! by whitespace, and exactly one whitespace byte follows the scale. The pixel data
//! must have exactly the size the header announces: missing or extra bytes are an
//! error, which also catches a malformed header that happens to parse.

use super::{Image, MAX_DIMENSION, MAX_PIXELS};
use crate::color::Color;

/// Headers longer than this are rejected before any parsing of numbers.
const MAX_HEADER_BYTES: usize = 128;

/// Whether `bytes` starts like a PFM file.
pub fn is_pfm(bytes: &[u8]) -> bool {
    bytes.len() >= 3
        && (bytes.starts_with(b"PF") || bytes.starts_with(b"Pf"))
        && bytes[2].is_ascii_whitespace()
}

/// Encodes `image` as a little-endian RGB PFM file held in memory.
pub(super) fn encode(image: &Image) -> Vec<u8> {
    let header = format!("PF\n{} {}\n-1.0\n", image.width, image.height);
    let mut bytes = Vec::with_capacity(header.len() + image.pixels.len() * 12);
    bytes.extend_from_slice(header.as_bytes());
    for row in image.pixels.chunks_exact(image.width).rev() {
        for color in row {
            for channel in [color.r, color.g, color.b] {
                bytes.extend_from_slice(&(channel as f32).to_le_bytes());
            }
        }
    }
    bytes
}

/// Splits off the next whitespace-delimited token, skipping leading whitespace.
fn next_token<'a>(bytes: &'a [u8], position: &mut usize) -> Result<&'a str, String> {
    while *position < bytes.len() && bytes[*position].is_ascii_whitespace() {
        *position += 1;
    }
    let start = *position;
    while *position < bytes.len() && !bytes[*position].is_ascii_whitespace() {
        *position += 1;
    }
    if start == *position || *position >= MAX_HEADER_BYTES {
        return Err("PFM header is truncated or malformed".to_string());
    }
    std::str::from_utf8(&bytes[start..*position]).map_err(|_| "PFM header is not ASCII".to_string())
}

fn parse_dimension(token: &str, what: &str) -> Result<usize, String> {
    let value: usize = token
        .parse()
        .map_err(|_| format!("PFM {what} '{token}' is not a positive integer"))?;
    if value == 0 || value > MAX_DIMENSION {
        return Err(format!("PFM {what} {value} is outside 1..={MAX_DIMENSION}"));
    }
    Ok(value)
}

/// The width and height a PFM header claims (checked before decoding).
pub(super) fn dimensions(bytes: &[u8]) -> Result<(usize, usize), String> {
    let mut position = 0;
    next_token(bytes, &mut position)?;
    let width = parse_dimension(next_token(bytes, &mut position)?, "width")?;
    let height = parse_dimension(next_token(bytes, &mut position)?, "height")?;
    Ok((width, height))
}

/// Decodes a PFM file (`PF` or `Pf`, either byte order) without panicking on bad input.
pub(super) fn decode(bytes: &[u8]) -> Result<Image, String> {
    let mut position = 0;
    let channels = match next_token(bytes, &mut position)? {
        "PF" => 3,
        "Pf" => 1,
        other => return Err(format!("'{other}' is not a PFM signature (PF or Pf)")),
    };
    let width = parse_dimension(next_token(bytes, &mut position)?, "width")?;
    let height = parse_dimension(next_token(bytes, &mut position)?, "height")?;
    let scale_token = next_token(bytes, &mut position)?;
    let scale: f64 = scale_token
        .parse()
        .map_err(|_| format!("PFM scale '{scale_token}' is not a number"))?;
    if !scale.is_finite() || scale == 0.0 {
        return Err(format!("PFM scale {scale} must be finite and non-zero"));
    }
    let little_endian = scale < 0.0;
    // Exactly one whitespace byte separates the header from the data.
    if position >= bytes.len() || !bytes[position].is_ascii_whitespace() {
        return Err("PFM header is not followed by pixel data".to_string());
    }
    position += 1;

    let pixel_count = width * height;
    if pixel_count > MAX_PIXELS {
        return Err(format!(
            "{width}x{height} PFM exceeds the limit of {MAX_PIXELS} pixels"
        ));
    }
    let data_bytes = pixel_count * channels * 4;
    let data = &bytes[position..];
    if data.len() != data_bytes {
        return Err(format!(
            "PFM data has {} bytes, but {width}x{height}x{channels} floats need {data_bytes}",
            data.len()
        ));
    }

    let read_float = |chunk: &[u8]| -> f64 {
        let word = [chunk[0], chunk[1], chunk[2], chunk[3]];
        if little_endian {
            f32::from_le_bytes(word) as f64
        } else {
            f32::from_be_bytes(word) as f64
        }
    };
    let mut pixels = vec![Color::BLACK; pixel_count];
    let row_bytes = width * channels * 4;
    // File rows run bottom to top; `Image` rows run top to bottom.
    for (file_row, row_data) in data.chunks_exact(row_bytes).enumerate() {
        let y = height - 1 - file_row;
        let row = &mut pixels[y * width..(y + 1) * width];
        for (pixel, sample) in row.iter_mut().zip(row_data.chunks_exact(channels * 4)) {
            *pixel = if channels == 3 {
                Color::new(
                    read_float(&sample[0..4]),
                    read_float(&sample[4..8]),
                    read_float(&sample[8..12]),
                )
            } else {
                Color::gray(read_float(sample))
            };
        }
    }
    Ok(Image {
        width,
        height,
        pixels,
    })
}
