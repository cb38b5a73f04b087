//! Per-pixel accumulation of radiance samples, and the image they average to.

use std::sync::atomic::{AtomicU64, Ordering};

use crate::allocation::{check_available, filled};
use crate::color::Color;
use crate::fixed_sum::{FixedColor, FixedSquares};
use crate::image_io::Image;
use crate::limits::{MemoryBudget, is_usable_radiance};

/// A sample is reported as a firefly when its luminance exceeds this many
/// times the running mean of its pixel (plus [`FIREFLY_FLOOR`]), once the
/// pixel has [`FIREFLY_MIN_SAMPLES`] samples: a robust bound that needs no
/// second pass and no knowledge of the scene's brightness.
pub const FIREFLY_FACTOR: f64 = 32.0;
pub const FIREFLY_FLOOR: f64 = 0.05;
pub const FIREFLY_MIN_SAMPLES: u32 = 8;

/// One pixel's running sums (the mean and a variance estimate from the first
/// two moments of luminance are all that adaptive sampling needs), in fixed
/// point so that sums of parts add up exactly to the sum of the whole.
#[derive(Clone, Copy, Debug, Default)]
pub struct PixelSum {
    pub sum: FixedColor,
    /// Sum of squared sample luminances.
    pub sum_of_squares: FixedSquares,
    pub samples: u32,
    /// Samples dropped because they were NaN, infinite or beyond
    /// [`MAX_RADIANCE`](crate::limits::MAX_RADIANCE).
    pub dropped: u32,
    /// Samples above the firefly bound (kept, unless clamped). The bound is
    /// the running mean of the samples added so far, so a film rendered in
    /// parts counts its fireflies against each part's own mean.
    pub fireflies: u32,
    /// Samples with a channel beyond `fixed_sum::MAX_SAMPLE`, clamped there.
    pub saturated: u32,
    /// Adaptive sampling stopped this pixel.
    pub converged: bool,
}

// The memory budget counts a pixel's sums by `limits::PIXEL_SUM_BYTES`.
const _: () = assert!(std::mem::size_of::<PixelSum>() as u64 == crate::limits::PIXEL_SUM_BYTES);

impl PixelSum {
    /// Adds one sample; `clamp` scales a sample down to that luminance
    /// (biased, off by default). A sample that is not finite or that a f32
    /// output could not hold is dropped and counted: the mean of kept
    /// samples is then within [`MAX_RADIANCE`](crate::limits::MAX_RADIANCE).
    pub fn add(&mut self, mut sample: Color, clamp: Option<f64>) {
        if !is_usable_radiance([sample.r, sample.g, sample.b]) {
            self.dropped += 1;
            return;
        }
        let mut l = sample.luminance();
        // With no negative sum the mean is at least 0 and the bound at least
        // FIREFLY_FACTOR * FIREFLY_FLOOR: most samples need not convert the
        // sums to find the mean.
        let may_exceed = l > FIREFLY_FACTOR * FIREFLY_FLOOR || self.sum.has_negative();
        if self.samples >= FIREFLY_MIN_SAMPLES && may_exceed {
            let mean = self.sum.to_color().luminance() / self.samples as f64;
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
        self.saturated += self.sum.add(sample) as u32;
        self.sum_of_squares.add(l);
        self.samples += 1;
    }

    /// Adds the sums of other samples of the same pixel.
    pub fn add_sum(&mut self, other: &PixelSum) {
        self.sum.add_sum(&other.sum);
        self.sum_of_squares.add_sum(&other.sum_of_squares);
        self.samples = self.samples.saturating_add(other.samples);
        self.dropped = self.dropped.saturating_add(other.dropped);
        self.fireflies = self.fireflies.saturating_add(other.fireflies);
        self.saturated = self.saturated.saturating_add(other.saturated);
    }

    pub fn mean(&self) -> Color {
        if self.samples == 0 {
            Color::BLACK
        } else {
            self.sum.to_color() / self.samples as f64
        }
    }

    /// Standard error of the mean luminance (infinite below two samples).
    pub fn standard_error(&self) -> f64 {
        if self.samples < 2 {
            return f64::INFINITY;
        }
        let n = self.samples as f64;
        let mean = self.sum.to_color().luminance() / n;
        let variance = ((self.sum_of_squares.to_f64() / n - mean * mean) * n / (n - 1.0)).max(0.0);
        (variance / n).sqrt()
    }
}

/// Light-tracing sums are kept in fixed point with this many fractional
/// bits: integer sums do not depend on the order of the additions, so an
/// image stays the same for any thread count.
pub const SPLAT_FRACTION_BITS: u32 = 20;
const SPLAT_SCALE: f64 = (1u64 << SPLAT_FRACTION_BITS) as f64;

/// A splat's channel in fixed point; negative and non-finite values count
/// as zero, huge ones saturate.
fn to_fixed(value: f64) -> u64 {
    if value.is_finite() && value > 0.0 {
        (value * SPLAT_SCALE).round().min(u64::MAX as f64 / 4.0) as u64
    } else {
        0
    }
}

/// The sums of every pixel, row-major with row 0 at the top. Renders add to a
/// film, so that a longer render continues a shorter one.
#[derive(Clone, Debug)]
pub struct Film {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<PixelSum>,
    /// Light tracing's sums per pixel and channel (fixed point, see
    /// [`SPLAT_FRACTION_BITS`]), and the number of light subpaths they come from.
    pub splats: Vec<[u64; 3]>,
    pub light_paths: u64,
    /// Light tracing's splats dropped for a non-finite or too large value.
    pub splats_dropped: u64,
}

impl Film {
    /// A film of a size already checked against the memory budget (see
    /// [`Film::within`]).
    pub fn new(width: usize, height: usize) -> Film {
        Film {
            width,
            height,
            pixels: vec![PixelSum::default(); width * height],
            splats: vec![[0; 3]; width * height],
            light_paths: 0,
            splats_dropped: 0,
        }
    }

    /// A film of `width` x `height`, or an error if the system refuses the
    /// memory (see [`crate::allocation`]).
    pub fn try_new(width: usize, height: usize) -> Result<Film, String> {
        let pixels = width.saturating_mul(height);
        Ok(Film {
            width,
            height,
            pixels: filled(pixels, PixelSum::default(), "the film")?,
            splats: filled(pixels, [0; 3], "the film's light sums")?,
            light_paths: 0,
            splats_dropped: 0,
        })
    }

    /// A film, once its size is checked against `budget` and the system
    /// (before anything is allocated).
    pub fn within(width: usize, height: usize, budget: MemoryBudget) -> Result<Film, String> {
        budget.check_image(width as u64, height as u64)?;
        check_available(
            MemoryBudget::image_bytes(width as u64, height as u64),
            &format!("a {width}x{height} render"),
        )?;
        Film::try_new(width, height)
    }

    /// Each pixel: the average of its samples plus light tracing's estimate
    /// (its sums over the number of light subpaths).
    pub fn to_image(&self) -> Image {
        let light_paths = self.light_paths.max(1) as f64 * SPLAT_SCALE;
        Image {
            width: self.width,
            height: self.height,
            pixels: self
                .pixels
                .iter()
                .zip(&self.splats)
                .map(|(pixel, splat)| {
                    pixel.mean()
                        + Color::new(
                            splat[0] as f64 / light_paths,
                            splat[1] as f64 / light_paths,
                            splat[2] as f64 / light_paths,
                        )
                })
                .collect(),
        }
    }

    pub fn samples(&self) -> u64 {
        self.pixels.iter().map(|p| p.samples as u64).sum()
    }

    /// Camera samples and light-tracing splats dropped for a value that
    /// is not finite or too large for a f32 output.
    pub fn dropped(&self) -> u64 {
        self.pixels.iter().map(|p| p.dropped as u64).sum::<u64>() + self.splats_dropped
    }

    pub fn fireflies(&self) -> u64 {
        self.pixels.iter().map(|p| p.fireflies as u64).sum()
    }

    pub fn saturated(&self) -> u64 {
        self.pixels.iter().map(|p| p.saturated as u64).sum()
    }

    /// Adds the sums of `other`, a film of the same size (other samples, or
    /// other pixels): integer sums, so the result does not depend on how a
    /// render was split or in which order the parts are added.
    pub fn add_film(&mut self, other: &Film) -> Result<(), String> {
        if (self.width, self.height) != (other.width, other.height) {
            return Err(format!(
                "cannot add a {}x{} film to a {}x{} one",
                other.width, other.height, self.width, self.height
            ));
        }
        for (pixel, part) in self.pixels.iter_mut().zip(&other.pixels) {
            pixel.add_sum(part);
        }
        for (pixel, part) in self.splats.iter_mut().zip(&other.splats) {
            for (total, value) in pixel.iter_mut().zip(part) {
                *total = total.saturating_add(*value);
            }
        }
        self.light_paths = self.light_paths.saturating_add(other.light_paths);
        self.splats_dropped = self.splats_dropped.saturating_add(other.splats_dropped);
        Ok(())
    }
}

/// Light tracing's sums of one render pass, added to from every thread.
pub struct SplatSums {
    sums: Vec<AtomicU64>,
    light_paths: AtomicU64,
    /// Splats dropped for a non-finite or too large channel.
    dropped: AtomicU64,
}

impl SplatSums {
    /// Sums for a film of `pixels` pixels (0: none, splats are dropped).
    pub fn new(pixels: usize) -> SplatSums {
        SplatSums {
            sums: (0..3 * pixels).map(|_| AtomicU64::new(0)).collect(),
            light_paths: AtomicU64::new(0),
            dropped: AtomicU64::new(0),
        }
    }

    /// [`SplatSums::new`], or an error if the system refuses the memory.
    pub fn try_new(pixels: usize) -> Result<SplatSums, String> {
        let count = pixels.saturating_mul(3);
        let mut sums = Vec::new();
        if sums.try_reserve_exact(count).is_err() {
            return Err(format!(
                "cannot allocate {} for the light sums of a pass: the system refused the memory",
                crate::limits::show_bytes((count as u64).saturating_mul(8))
            ));
        }
        sums.extend((0..count).map(|_| AtomicU64::new(0)));
        Ok(SplatSums {
            sums,
            light_paths: AtomicU64::new(0),
            dropped: AtomicU64::new(0),
        })
    }

    /// Adds `value` to pixel `index` (row-major, row 0 at the top),
    /// saturating rather than wrapping; a value that is not finite or
    /// beyond [`MAX_RADIANCE`](crate::limits::MAX_RADIANCE) is dropped and
    /// counted.
    pub fn add(&self, index: usize, value: Color) {
        if !is_usable_radiance([value.r, value.g, value.b]) {
            self.dropped.fetch_add(1, Ordering::Relaxed);
            return;
        }
        for (channel, v) in [value.r, value.g, value.b].into_iter().enumerate() {
            let fixed = to_fixed(v);
            if let (Some(sum), true) = (self.sums.get(3 * index + channel), fixed > 0) {
                // Never fails: the closure always returns `Some`.
                let _ = sum.fetch_update(Ordering::Relaxed, Ordering::Relaxed, |total| {
                    Some(total.saturating_add(fixed))
                });
            }
        }
    }

    pub fn add_light_paths(&self, count: u64) {
        if count > 0 {
            self.light_paths.fetch_add(count, Ordering::Relaxed);
        }
    }

    /// Moves the sums into `film`.
    pub fn add_to(&self, film: &mut Film) {
        for (pixel, sums) in film.splats.iter_mut().zip(self.sums.chunks_exact(3)) {
            for (total, sum) in pixel.iter_mut().zip(sums) {
                *total = total.saturating_add(sum.load(Ordering::Relaxed));
            }
        }
        film.light_paths += self.light_paths.load(Ordering::Relaxed);
        film.splats_dropped += self.dropped.load(Ordering::Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splats_add_in_fixed_point_and_saturate() {
        let mut film = Film::new(2, 1);
        let sums = SplatSums::new(2);
        sums.add(1, Color::new(0.5, 1e-9, -3.0));
        sums.add(1, Color::new(0.25, 0.0, 2.0));
        sums.add(0, Color::gray(1e30));
        sums.add(0, Color::gray(1e30));
        sums.add_light_paths(4);
        sums.add_to(&mut film);
        let image = film.to_image();
        // (0.5 + 0.25) / 4 light paths; negative counts as 0.
        assert!((image.pixels[1].r - 0.1875).abs() < 1e-6);
        assert!(image.pixels[1].g.abs() < 1e-6 && (image.pixels[1].b - 0.5).abs() < 1e-6);
        assert!(image.pixels[0].r.is_finite() && image.pixels[0].r > 1e12);
    }

    #[test]
    fn non_finite_samples_are_dropped_and_counted() {
        let mut p = PixelSum::default();
        p.add(Color::gray(1.0), None);
        p.add(Color::new(f64::NAN, 0.0, 0.0), None);
        p.add(Color::new(0.0, f64::INFINITY, 0.0), None);
        // Finite, but a f32 output would hold it as infinity.
        p.add(Color::new(0.0, 0.0, 1e300), None);
        p.add(Color::gray(3.0), None);
        assert_eq!(p.samples, 2);
        assert_eq!(p.dropped, 3);
        assert_eq!(p.mean(), Color::gray(2.0));
    }

    #[test]
    fn splats_too_large_for_f32_are_dropped_and_counted() {
        let mut film = Film::new(1, 1);
        let sums = SplatSums::new(1);
        sums.add(0, Color::new(f64::NAN, 1.0, 1.0));
        sums.add(0, Color::gray(f64::INFINITY));
        sums.add(0, Color::gray(1e300));
        sums.add(0, Color::gray(2.0));
        sums.add_light_paths(1);
        sums.add_to(&mut film);
        assert_eq!(film.dropped(), 3);
        assert!((film.to_image().pixels[0].r - 2.0).abs() < 1e-6);
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
