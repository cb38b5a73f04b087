//! Per-pixel accumulation of radiance samples, and the image they average to.

use crate::color::Color;
use crate::image_io::Image;

/// One pixel's running sums (Welford would be overkill: the mean and a
/// variance estimate from the first two moments are all that is needed).
#[derive(Clone, Copy, Debug, Default)]
pub struct PixelSum {
    pub sum: Color,
    pub sum_of_squares: f64,
    pub samples: u32,
    /// Samples dropped because they were NaN or infinite.
    pub dropped: u32,
}

impl PixelSum {
    pub fn add(&mut self, sample: Color) {
        if !sample.is_finite() {
            self.dropped += 1;
            return;
        }
        self.sum += sample;
        let l = sample.average();
        self.sum_of_squares += l * l;
        self.samples += 1;
    }

    pub fn mean(&self) -> Color {
        if self.samples == 0 {
            Color::BLACK
        } else {
            self.sum / self.samples as f64
        }
    }
}

/// The sums of every pixel, row-major with row 0 at the top. Renders add to a
/// film, so that a longer render continues a shorter one.
#[derive(Clone, Debug)]
pub struct Film {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<PixelSum>,
}

impl Film {
    pub fn new(width: usize, height: usize) -> Film {
        Film {
            width,
            height,
            pixels: vec![PixelSum::default(); width * height],
        }
    }

    /// The average of each pixel's samples.
    pub fn to_image(&self) -> Image {
        Image {
            width: self.width,
            height: self.height,
            pixels: self.pixels.iter().map(PixelSum::mean).collect(),
        }
    }

    pub fn samples(&self) -> u64 {
        self.pixels.iter().map(|p| p.samples as u64).sum()
    }

    pub fn dropped(&self) -> u64 {
        self.pixels.iter().map(|p| p.dropped as u64).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_samples_are_dropped_and_counted() {
        let mut p = PixelSum::default();
        p.add(Color::gray(1.0));
        p.add(Color::new(f64::NAN, 0.0, 0.0));
        p.add(Color::new(0.0, f64::INFINITY, 0.0));
        p.add(Color::gray(3.0));
        assert_eq!(p.samples, 2);
        assert_eq!(p.dropped, 2);
        assert_eq!(p.mean(), Color::gray(2.0));
    }
}
