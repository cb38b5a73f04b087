//! 8-bit display images: the bytes a BMP or PNG holds, as the look-alike
//! criterion, FLIP and the error maps see them.

use std::path::Path;

use super::quantize::Quantizer;
use super::{Image, write_image};
use crate::color::Color;

/// An 8-bit RGB image, row 0 at the top.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DisplayImage {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<[u8; 3]>,
}

impl DisplayImage {
    /// The bytes that `write_image` stores for `image` in a BMP or PNG file
    /// without gamma (the PA framework writer: clamp, `int(c * 255)`), so that
    /// a rendered image is measured exactly as `render -o x.png` writes it.
    /// For an image read from an 8-bit file these are the file's own bytes
    /// (`v / 255 * 255` truncates back to `v` for every byte).
    pub fn from_image(image: &Image) -> DisplayImage {
        let quantizer = Quantizer::FRAMEWORK;
        DisplayImage {
            width: image.width,
            height: image.height,
            pixels: image.pixels.iter().map(|&c| quantizer.rgb(c)).collect(),
        }
    }

    /// Values `v / 255`, the inverse of [`DisplayImage::from_image`].
    pub fn to_image(&self) -> Image {
        Image {
            width: self.width,
            height: self.height,
            pixels: self
                .pixels
                .iter()
                .map(|p| {
                    Color::new(
                        p[0] as f64 / 255.0,
                        p[1] as f64 / 255.0,
                        p[2] as f64 / 255.0,
                    )
                })
                .collect(),
        }
    }

    /// Writes the bytes unchanged to a `.bmp` or `.png` file, atomically.
    pub fn write(&self, path: &Path) -> Result<(), String> {
        write_image(path, &self.to_image(), None)
    }

    /// Checks that the pixel buffer matches the size and that it is not empty.
    pub fn validate(&self, name: &str) -> Result<(), String> {
        if self.pixels.len() != self.width * self.height {
            return Err(format!(
                "{name} image claims {}x{} pixels but holds {}",
                self.width,
                self.height,
                self.pixels.len()
            ));
        }
        if self.pixels.is_empty() {
            return Err(format!("{name} image is empty"));
        }
        Ok(())
    }
}
