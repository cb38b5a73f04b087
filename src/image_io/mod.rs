//! Reading and writing images: BMP, PNG, PFM and OpenEXR, written atomically;
//! the 8-bit encoding (exposure, tone curve, gamma) of BMP and PNG.
//!
//! The format of a written file is chosen by its extension (case-insensitive);
//! a read file is recognised by its content. Every writer encodes the whole file
//! in memory first and hands the bytes to [`atomic::write_file`], so the
//! destination either receives a complete image or is left exactly as it was.
//! Commands that work long reserve their outputs first ([`PendingFile`]: the
//! temporary exists before the work starts), refuse outputs that are inputs
//! ([`refuse_inputs`]) and put them in place together ([`commit_together`]).

mod atomic;
mod bmp_format;
mod commit;
mod decode;
mod display;
mod exr_format;
mod inputs;
mod pfm;
mod png_format;
mod quantize;
mod tonemap;

pub use tonemap::{Encoding, Tonemap};

/// Writes any bytes to a file whole or not at all (temporary file + rename).
pub use atomic::write_file as write_atomically;
pub use atomic::{PendingFile, TEMPORARY_MARK};
pub use bmp_format::check_complete as check_bmp_complete;
pub use commit::commit_together;
pub use decode::{check_decodable, describe_error, reader_for};
pub use display::DisplayImage;
pub use inputs::{refuse_inputs, refuse_shared_outputs};
pub use pfm::is_pfm;

use std::path::Path;

use crate::color::Color;

/// A linear RGB image, row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<Color>,
}

/// What the values of a read image are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelValues {
    /// Display values (8- or 16-bit BMP, PNG, JPEG, TGA), read as `v / max`:
    /// what a viewer shows, whatever gamma made them.
    Display,
    /// Linear radiance as stored (PFM, EXR), possibly above 1.
    Linear,
}

/// The largest width or height accepted when reading or writing.
pub(crate) const MAX_DIMENSION: usize = crate::limits::MAX_IMAGE_SIDE as usize;

/// The largest pixel count accepted when reading (64 Mpixel, 1.5 GiB of `Color`).
pub(crate) const MAX_PIXELS: usize = 1 << 26;

/// The file formats this module writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Bmp,
    Png,
    Pfm,
    Exr,
}

const SUPPORTED_EXTENSIONS: &str = ".bmp, .png, .pfm, .exr";

impl Format {
    fn from_path(path: &Path) -> Result<Format, String> {
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase());
        match extension.as_deref() {
            Some("bmp") => Ok(Format::Bmp),
            Some("png") => Ok(Format::Png),
            Some("pfm") => Ok(Format::Pfm),
            Some("exr") => Ok(Format::Exr),
            Some(other) => Err(format!(
                "{}: unsupported image extension '.{other}' (supported: {SUPPORTED_EXTENSIONS})",
                path.display()
            )),
            None => Err(format!(
                "{}: no image extension (supported: {SUPPORTED_EXTENSIONS})",
                path.display()
            )),
        }
    }
}

/// Whether `path` names a format that keeps linear radiance (`.pfm`,
/// `.exr`), which exposure, tone curve and gamma do not touch.
pub fn is_hdr(path: &Path) -> bool {
    matches!(Format::from_path(path), Ok(Format::Pfm | Format::Exr))
}

/// Checks, before any work is done, that an image of `width` x `height` can be
/// written to `path` (known extension, size within limits).
pub fn check_writable(path: &Path, width: usize, height: usize) -> Result<(), String> {
    Format::from_path(path)?;
    if width == 0 || height == 0 || width > MAX_DIMENSION || height > MAX_DIMENSION {
        return Err(format!(
            "{}: cannot write a {width}x{height} image (1 to {MAX_DIMENSION} pixels per side)",
            path.display()
        ));
    }
    Ok(())
}

/// Checks that the pixel buffer matches the dimensions and that the size is writable.
fn validate(path: &Path, image: &Image) -> Result<(), String> {
    if image.width == 0 || image.height == 0 {
        return Err(format!(
            "{}: cannot write an empty {}x{} image",
            path.display(),
            image.width,
            image.height
        ));
    }
    if image.width > MAX_DIMENSION || image.height > MAX_DIMENSION {
        return Err(format!(
            "{}: image of {}x{} exceeds the limit of {MAX_DIMENSION} pixels per side",
            path.display(),
            image.width,
            image.height
        ));
    }
    if image.pixels.len() != image.width * image.height {
        return Err(format!(
            "{}: image claims {}x{} pixels but holds {}",
            path.display(),
            image.width,
            image.height,
            image.pixels.len()
        ));
    }
    Ok(())
}

/// Writes `image` to `path`, the format chosen by the extension (`.bmp`, `.png`:
/// each channel clamped to [0, 1], raised to `1/gamma` when `gamma` is given,
/// scaled by 255; `.pfm` and `.exr`: linear radiance). The file appears whole
/// or not at all.
pub fn write_image(path: &Path, image: &Image, gamma: Option<f64>) -> Result<(), String> {
    write_encoded(path, image, &Encoding::gamma(gamma))
}

/// [`write_image`] with an exposure and a tone curve for 8-bit output
/// (`.bmp`, `.png`) as `encoding` says; `.pfm` and `.exr` stay linear.
pub fn write_encoded(path: &Path, image: &Image, encoding: &Encoding) -> Result<(), String> {
    atomic::write_file(path, &encode_image(path, image, encoding)?)
}

/// The bytes of the file [`write_encoded`] writes, for a [`PendingFile`].
pub fn encode_image(path: &Path, image: &Image, encoding: &Encoding) -> Result<Vec<u8>, String> {
    let format = Format::from_path(path)?;
    validate(path, image)?;
    let bytes = match format {
        Format::Bmp => bmp_format::encode(image, encoding),
        Format::Png => png_format::encode(image, encoding),
        Format::Pfm => Ok(pfm::encode(image)),
        Format::Exr => exr_format::encode(image),
    }
    .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(bytes)
}

/// Reads a BMP, PNG, PFM or EXR image (LDR values mapped to [0, 1] without
/// gamma; HDR values as stored).
///
/// The format is recognised by the file's content, not its extension. JPEG and
/// TGA files are read too. PFM values are returned as stored (linear).
pub fn read_image(path: &Path) -> Result<Image, String> {
    read_image_encoded(path).map(|(image, _)| image)
}

/// [`read_image`], and whether the file held display values or linear radiance.
pub fn read_image_encoded(path: &Path) -> Result<(Image, PixelValues), String> {
    let bytes = decode::read_capped(path)?;
    decode_image(&bytes, path).map_err(|e| format!("{}: {e}", path.display()))
}

/// Decodes the bytes of an image file read from `path` (whose extension
/// names the format when its content does not: TGA): PFM, or BMP, PNG,
/// JPEG, TGA, EXR.
pub fn decode_image(bytes: &[u8], path: &Path) -> Result<(Image, PixelValues), String> {
    if pfm::is_pfm(bytes) {
        pfm::decode(bytes).map(|image| (image, PixelValues::Linear))
    } else {
        decode::decode_ldr(bytes, path)
    }
}

#[cfg(test)]
mod tests;
