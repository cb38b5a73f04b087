//! Per-pixel accumulation of radiance samples, and the image they average to.

use crate::color::Color;
use crate::image_io::Image;

/// A sample is reported as a firefly when its luminance exceeds this many
/// times the running mean of its pixel (plus [`FIREFLY_FLOOR`]), once the
/// pixel has [`FIREFLY_MIN_SAMPLES`] samples: a robust bound that needs no
/// second pass and no knowledge of the scene's brightness.
pub const FIREFLY_FACTOR: f64 = 32.0;
pub const FIREFLY_FLOOR: f64 = 0.05;
pub const FIREFLY_MIN_SAMPLES: u32 = 8;

/// One pixel's running sums (the mean and a variance estimate from the first
/// two moments of luminance are all that adaptive sampling needs).
#[derive(Clone, Copy, Debug, Default)]
pub struct PixelSum {
    pub sum: Color,
    /// Sum of squared sample luminances.
    pub sum_of_squares: f64,
    pub samples: u32,
    /// Samples dropped because they were NaN or infinite.
    pub dropped: u32,
    /// Samples above the firefly bound (kept, unless clamped).
    pub fireflies: u32,
    /// Adaptive sampling stopped this pixel.
    pub converged: bool,
}

impl PixelSum {
    /// Adds one sample; `clamp` scales a sample down to that luminance
    /// (biased, off by default).
    pub fn add(&mut self, mut sample: Color, clamp: Option<f64>) {
        if !sample.is_finite() {
            self.dropped += 1;
            return;
        }
        let mut l = sample.luminance();
        if self.samples >= FIREFLY_MIN_SAMPLES {
            let mean = self.sum.luminance() / self.samples as f64;
            if l > FIREFLY_FACTOR * (mean + FIREFLY_FLOOR) {
                self.fireflies += 1;
            }
        }
        if let Some(limit) = clamp
            && l > limit
        {
            sample *= limit / l;
            l = limit;
        }
        self.sum += sample;
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

    /// Standard error of the mean luminance (infinite below two samples).
    pub fn standard_error(&self) -> f64 {
        if self.samples < 2 {
            return f64::INFINITY;
        }
        let n = self.samples as f64;
        let mean = self.sum.luminance() / n;
        let variance = ((self.sum_of_squares / n - mean * mean) * n / (n - 1.0)).max(0.0);
        (variance / n).sqrt()
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

    pub fn fireflies(&self) -> u64 {
        self.pixels.iter().map(|p| p.fireflies as u64).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_samples_are_dropped_and_counted() {
        let mut p = PixelSum::default();
        p.add(Color::gray(1.0), None);
        p.add(Color::new(f64::NAN, 0.0, 0.0), None);
        p.add(Color::new(0.0, f64::INFINITY, 0.0), None);
        p.add(Color::gray(3.0), None);
        assert_eq!(p.samples, 2);
        assert_eq!(p.dropped, 2);
        assert_eq!(p.mean(), Color::gray(2.0));
    }

    #[test]
    fn standard_error_matches_the_textbook_formula() {
        let mut p = PixelSum::default();
        for v in [1.0, 2.0, 3.0, 4.0] {
            p.add(Color::gray(v), None);
        }
        // Sample variance 5/3, n = 4.
        assert!((p.standard_error() - (5.0f64 / 3.0 / 4.0).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn fireflies_are_counted_and_clamping_bounds_the_sample() {
        let mut p = PixelSum::default();
        for _ in 0..FIREFLY_MIN_SAMPLES {
            p.add(Color::gray(0.5), None);
        }
        p.add(Color::gray(1.0), None);
        assert_eq!(p.fireflies, 0);
        p.add(Color::gray(1000.0), Some(10.0));
        assert_eq!(p.fireflies, 1);
        let expected =
            (0.5 * FIREFLY_MIN_SAMPLES as f64 + 1.0 + 10.0) / (FIREFLY_MIN_SAMPLES as f64 + 2.0);
        assert!((p.mean().g - expected).abs() < 1e-9);
    }
}
