//! Reading and writing images: BMP, PNG and PFM, written atomically.

use std::path::Path;

use crate::color::Color;

/// A linear RGB image, row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<Color>,
}

/// Writes `image` to `path`, the format chosen by the extension (`.bmp`, `.png`:
/// each channel clamped to [0, 1], raised to `1/gamma` when `gamma` is given,
/// scaled by 255; `.pfm`: linear radiance). The file appears whole or not at all.
pub fn write_image(_path: &Path, _image: &Image, _gamma: Option<f64>) -> Result<(), String> {
    todo!("imaging helper")
}

/// Reads a BMP, PNG or PFM image (LDR values mapped to [0, 1] without gamma).
pub fn read_image(_path: &Path) -> Result<Image, String> {
    todo!("imaging helper")
}
