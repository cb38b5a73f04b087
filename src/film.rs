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

/// Averages a row-major film (row 0 at the top) into an image.
pub fn to_image(width: usize, height: usize, pixels: &[PixelSum]) -> Image {
    Image {
        width,
        height,
        pixels: pixels.iter().map(PixelSum::mean).collect(),
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
