//! Reading files with a size cap, checking an image's header before it is
//! decoded, and decoding LDR formats through the `image` crate.

use std::io::{Cursor, ErrorKind};
use std::path::Path;

use image::{DynamicImage, ImageError, ImageFormat, ImageReader, Limits};

use super::{Image, MAX_DIMENSION, MAX_PIXELS, PixelValues, bmp_format, pfm};
use crate::color::Color;
use crate::limits::{MemoryBudget, read_within};

/// The largest file read: an uncompressed float RGB image at the pixel cap, plus a header.
const MAX_FILE_BYTES: u64 = (MAX_PIXELS as u64) * 12 + 4096;

/// Reads the whole file, refusing directories, devices and files larger
/// than [`MAX_FILE_BYTES`] before reading.
pub(super) fn read_capped(path: &Path) -> Result<Vec<u8>, String> {
    read_within(path, MAX_FILE_BYTES, "the largest float image")
}

/// Checks an encoded image before it is decoded: a known format, a header
/// that reads, dimensions whose decoding (`bytes_per_pixel` each) fits
/// `budget` (a small file may claim a huge image), and for BMP the length
/// its header promises. Returns the width and height.
/// A PFM's header is read by `pfm`; TGA, which has no signature, is
/// recognised by the extension of `path`.
pub fn check_decodable(
    bytes: &[u8],
    path: &Path,
    budget: MemoryBudget,
    bytes_per_pixel: u64,
) -> Result<(u32, u32), String> {
    if pfm::is_pfm(bytes) {
        let (width, height) = pfm::dimensions(bytes)?;
        budget.check_texture(width as u64, height as u64, bytes_per_pixel)?;
        return Ok((width as u32, height as u32));
    }
    let reader = reader_for(bytes, path)?;
    let (width, height) = reader.into_dimensions().map_err(describe_error)?;
    budget.check_texture(width as u64, height as u64, bytes_per_pixel)?;
    bmp_format::check_complete(bytes)?;
    Ok((width, height))
}

/// A reader of `bytes` (not PFM, which `pfm` reads), its format
/// recognised by its content, or else by the extension of `path`: TGA has
/// no signature to recognise.
pub fn reader_for<'a>(
    bytes: &'a [u8],
    path: &Path,
) -> Result<ImageReader<Cursor<&'a [u8]>>, String> {
    let mut reader = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| format!("cannot read: {e}"))?;
    if reader.format().is_none() {
        match ImageFormat::from_path(path) {
            Ok(format) if format.reading_enabled() => reader.set_format(format),
            _ => {
                return Err(
                    "unrecognised image format (readable: BMP, PNG, JPEG, TGA, PFM, EXR)"
                        .to_string(),
                );
            }
        }
    }
    Ok(reader)
}

/// A decoder's error for messages: a file that ends early is called
/// truncated (the decoder says "failed to fill whole buffer").
pub fn describe_error(error: ImageError) -> String {
    match &error {
        ImageError::IoError(io) if io.kind() == ErrorKind::UnexpectedEof => {
            "truncated: the file ends before its image data does".to_string()
        }
        _ => format!("cannot decode: {error}"),
    }
}

/// Decodes BMP, PNG, JPEG, TGA or EXR bytes; 8-bit values become `v / 255`,
/// no gamma; float values are kept. Integer samples (8 or 16 bits) are
/// display values, float samples (EXR) linear radiance.
pub(super) fn decode_ldr(bytes: &[u8], path: &Path) -> Result<(Image, PixelValues), String> {
    // Decoding takes up to 16 bytes per pixel (RGBA f32), `Color` 24 more.
    let (claimed_width, claimed_height) =
        check_decodable(bytes, path, MemoryBudget::default(), 40)?;
    if claimed_width as usize * claimed_height as usize > MAX_PIXELS {
        return Err(format!(
            "{claimed_width}x{claimed_height} image exceeds the limit of {MAX_PIXELS} pixels"
        ));
    }
    let mut reader = reader_for(bytes, path)?;
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_DIMENSION as u32);
    limits.max_image_height = Some(MAX_DIMENSION as u32);
    reader.limits(limits);
    let decoded = reader.decode().map_err(describe_error)?;
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
