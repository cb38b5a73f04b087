//! Box resampling with fractional coverage: every target pixel is the mean of
//! the source pixels under it, each weighted by the area of it that the
//! target pixel covers.
//!
//! Target pixel `j` of an axis covers the source interval `[j s, (j + 1) s)`
//! with `s = source / target`; a source pixel `[i, i + 1)` weighs its overlap
//! with that interval. The two axes are independent, so a pixel's weight is
//! the product of its column's and its row's. An integer-factor reduction is
//! then exactly the mean of each `s x s` block, and a size that does not
//! divide shares the straddling pixels between their neighbours. Values are
//! kept unrounded.

use crate::image_io::DisplayImage;

/// An RGB image of unrounded values on the 0-255 scale, row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Resampled {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<[f64; 3]>,
}

impl Resampled {
    /// Rounds every value to the nearest byte (a picture for a page).
    pub fn to_display(&self) -> DisplayImage {
        DisplayImage {
            width: self.width,
            height: self.height,
            pixels: self
                .pixels
                .iter()
                .map(|p| p.map(|v| v.round().clamp(0.0, 255.0) as u8))
                .collect(),
        }
    }
}

/// Resizes `image` to `width` x `height` (both at least 1) by the box rule
/// above; it also enlarges (each target pixel then covers part of one or two
/// source pixels).
pub fn box_resize(image: &DisplayImage, width: usize, height: usize) -> Resampled {
    let (width, height) = (width.max(1), height.max(1));
    let columns = coverage(image.width, width);
    let rows = coverage(image.height, height);
    let mut pixels = Vec::with_capacity(width * height);
    for row in &rows {
        for column in &columns {
            let mut sum = [0.0; 3];
            let mut total = 0.0;
            for &(y, wy) in row {
                let line = &image.pixels[y * image.width..(y + 1) * image.width];
                for &(x, wx) in column {
                    let weight = wx * wy;
                    for (s, &v) in sum.iter_mut().zip(&line[x]) {
                        *s += weight * v as f64;
                    }
                    total += weight;
                }
            }
            pixels.push(sum.map(|s| if total > 0.0 { s / total } else { 0.0 }));
        }
    }
    Resampled {
        width,
        height,
        pixels,
    }
}

/// For each of `target` pixels along an axis of `source` pixels: the source
/// pixels it covers and the length of each overlap.
fn coverage(source: usize, target: usize) -> Vec<Vec<(usize, f64)>> {
    let scale = source as f64 / target as f64;
    (0..target)
        .map(|j| {
            let (start, end) = (j as f64 * scale, (j + 1) as f64 * scale);
            let first = start.floor() as usize;
            let last = (end.ceil() as usize).min(source);
            (first..last)
                .filter_map(|i| {
                    let overlap = end.min(i as f64 + 1.0) - start.max(i as f64);
                    (overlap > 0.0).then_some((i, overlap))
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(width: usize, height: usize, value: impl Fn(usize, usize) -> [u8; 3]) -> DisplayImage {
        DisplayImage {
            width,
            height,
            pixels: (0..width * height)
                .map(|i| value(i % width, i / width))
                .collect(),
        }
    }

    #[test]
    fn the_same_size_changes_nothing() {
        let source = image(7, 5, |x, y| [(x * 30) as u8, (y * 50) as u8, (x * y) as u8]);
        let same = box_resize(&source, 7, 5);
        assert_eq!(same.to_display(), source);
        for (a, b) in same.pixels.iter().zip(&source.pixels) {
            assert_eq!(*a, b.map(|v| v as f64));
        }
    }

    #[test]
    fn an_integer_factor_is_the_mean_of_each_block() {
        let source = image(4, 2, |x, y| [(x * 10 + y * 100) as u8, 0, 255]);
        let half = box_resize(&source, 2, 1);
        // Blocks {0, 10, 100, 110} and {20, 30, 120, 130}.
        assert_eq!(half.pixels, vec![[55.0, 0.0, 255.0], [75.0, 0.0, 255.0]]);
    }

    #[test]
    fn fractional_coverage_shares_the_straddling_pixel() {
        // Three pixels into two: each target covers 1.5 source pixels.
        let source = image(3, 1, |x, _| [[0, 90, 180][x], 0, 0]);
        let resized = box_resize(&source, 2, 1);
        assert_eq!(resized.pixels[0][0], (0.0 + 0.5 * 90.0) / 1.5);
        assert_eq!(resized.pixels[1][0], (0.5 * 90.0 + 180.0) / 1.5);
    }

    #[test]
    fn the_mean_of_the_image_is_kept_for_any_size() {
        let source = image(37, 23, |x, y| {
            [((x * 7 + y * 13) % 256) as u8, (x * 6) as u8, 9]
        });
        let mean =
            |pixels: &[[f64; 3]]| pixels.iter().map(|p| p[0]).sum::<f64>() / pixels.len() as f64;
        let source_mean = mean(&box_resize(&source, 37, 23).pixels);
        for (w, h) in [(32, 20), (5, 3), (1, 1), (10, 23)] {
            let resized = box_resize(&source, w, h);
            assert!(
                (mean(&resized.pixels) - source_mean).abs() < 1e-9,
                "{w}x{h}"
            );
        }
    }
}
