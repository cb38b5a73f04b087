//! The look-alike criterion: whether our render of a scene looks like the
//! image another renderer wrote for it, at thumbnail scale, where the noise
//! of either render and a pixel of framing do not count.
//!
//! Both images are 8-bit display values (ours as written to PNG or BMP,
//! theirs as read). Each is box-resampled ([`box_resize`]: the mean of the
//! source pixels under each target pixel, fractional coverage at the edges,
//! values kept unrounded) to [`LOOKALIKE_WIDTH`] pixels wide and the
//! reference's aspect ratio: `round(32 h / w)` rows of the reference's `w x h`.
//! Per pixel, the absolute differences of the three channels are taken; the
//! images look the same when their mean over pixels and channels is at most
//! [`MEAN_LIMIT`] and the 95th percentile (nearest rank: the
//! `ceil(0.95 n)`-th smallest of the `n` values) of the per-pixel largest
//! channel difference is at most [`P95_LIMIT`]. An image whose aspect ratio
//! differs from the reference's is stretched to it, and the result says so.

use std::fmt;

use super::resample::box_resize;
use crate::image_io::DisplayImage;
use crate::limits::MAX_ASPECT_RATIO;

/// The width both images are resampled to.
pub const LOOKALIKE_WIDTH: usize = 32;

/// The largest mean absolute channel difference (0-255 scale) of images that
/// look the same.
pub const MEAN_LIMIT: f64 = 4.0;

/// The largest 95th percentile of the per-pixel largest channel difference
/// (0-255 scale) of images that look the same.
pub const P95_LIMIT: f64 = 12.0;

/// The percentile of the per-pixel largest channel difference that is judged.
pub const PERCENTILE: f64 = 0.95;

/// The criterion's figures and verdict for one pair.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lookalike {
    /// Mean absolute channel difference over pixels and channels.
    pub mean: f64,
    /// 95th percentile of the per-pixel largest channel difference.
    pub p95: f64,
    /// `mean <= MEAN_LIMIT && p95 <= P95_LIMIT`.
    pub same: bool,
    /// The size both images were compared at.
    pub width: usize,
    pub height: usize,
    /// The test image's aspect ratio differs from the reference's by more
    /// than rounding a height to whole pixels explains (half a pixel of each
    /// image's height); it was stretched to the reference's.
    pub aspect_differs: bool,
    /// The sizes of the images as given, test first.
    pub test_size: (usize, usize),
    pub reference_size: (usize, usize),
}

/// Applies the criterion to `test` against `reference`, of any sizes.
pub fn lookalike(test: &DisplayImage, reference: &DisplayImage) -> Result<Lookalike, String> {
    test.validate("test")?;
    reference.validate("reference")?;
    for (name, image) in [("test", test), ("reference", reference)] {
        let (long, short) = (image.width.max(image.height), image.width.min(image.height));
        if long > MAX_ASPECT_RATIO.saturating_mul(short) {
            return Err(format!(
                "the {name} image is {}x{}, longer than {MAX_ASPECT_RATIO} times its width or \
                 height (limits::MAX_ASPECT_RATIO): the look-alike criterion does not compare it",
                image.width, image.height
            ));
        }
    }
    let width = LOOKALIKE_WIDTH;
    let height = ((width * reference.height) as f64 / reference.width as f64)
        .round()
        .max(1.0) as usize;
    let a = box_resize(test, width, height);
    let b = box_resize(reference, width, height);
    let mut sum = 0.0;
    let mut largest: Vec<f64> = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(p, q)| {
            let d = [0, 1, 2].map(|c| (p[c] - q[c]).abs());
            sum += d[0] + d[1] + d[2];
            d[0].max(d[1]).max(d[2])
        })
        .collect();
    let mean = sum / (3 * largest.len()) as f64;
    largest.sort_by(f64::total_cmp);
    let rank = (PERCENTILE * largest.len() as f64).ceil() as usize;
    let p95 = largest[rank.clamp(1, largest.len()) - 1];
    let aspect = |image: &DisplayImage| image.height as f64 / image.width as f64;
    let rounding = 0.5 / test.width as f64 + 0.5 / reference.width as f64;
    Ok(Lookalike {
        mean,
        p95,
        same: mean <= MEAN_LIMIT && p95 <= P95_LIMIT,
        width,
        height,
        aspect_differs: (aspect(test) - aspect(reference)).abs() > rounding,
        test_size: (test.width, test.height),
        reference_size: (reference.width, reference.height),
    })
}

impl Lookalike {
    /// `same` or `different`.
    pub fn verdict(&self) -> &'static str {
        if self.same { "same" } else { "different" }
    }

    /// The note printed when the aspect ratios differ, if they do.
    pub fn aspect_note(&self) -> Option<String> {
        self.aspect_differs.then(|| {
            format!(
                "aspect ratios differ ({}x{} against a {}x{} reference): compared at {}x{}, the reference's aspect",
                self.test_size.0,
                self.test_size.1,
                self.reference_size.0,
                self.reference_size.1,
                self.width,
                self.height
            )
        })
    }
}

impl fmt::Display for Lookalike {
    /// `lookalike: mean 2.1, p95 9.0, same`, then the aspect note if any.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "lookalike: mean {:.1}, p95 {:.1}, {}",
            self.mean,
            self.p95,
            self.verdict()
        )?;
        if let Some(note) = self.aspect_note() {
            write!(f, " ({note})")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 32x32 image with structure in every channel, values in [40, 200].
    fn pattern() -> DisplayImage {
        DisplayImage {
            width: 32,
            height: 32,
            pixels: (0..32 * 32)
                .map(|i| {
                    let (x, y) = (i % 32, i / 32);
                    [
                        (40 + x * 5) as u8,
                        (40 + y * 5) as u8,
                        (40 + (x * y) % 160) as u8,
                    ]
                })
                .collect(),
        }
    }

    fn offset(image: &DisplayImage, by: impl Fn(usize) -> i32) -> DisplayImage {
        let mut shifted = image.clone();
        for (i, p) in shifted.pixels.iter_mut().enumerate() {
            *p = p.map(|v| (v as i32 + by(i)).clamp(0, 255) as u8);
        }
        shifted
    }

    #[test]
    fn identical_images_are_the_same_with_zero_and_zero() {
        let image = pattern();
        let result = lookalike(&image, &image).unwrap();
        assert_eq!((result.mean, result.p95, result.same), (0.0, 0.0, true));
        assert!(!result.aspect_differs);
        assert_eq!(result.to_string(), "lookalike: mean 0.0, p95 0.0, same");
    }

    #[test]
    fn an_offset_of_five_in_every_channel_is_not_the_same() {
        let image = pattern();
        let result = lookalike(&offset(&image, |_| 5), &image).unwrap();
        assert_eq!((result.mean, result.p95), (5.0, 5.0));
        assert!(!result.same);
        // Four is still the same, on the limit.
        assert!(lookalike(&offset(&image, |_| -4), &image).unwrap().same);
    }

    #[test]
    fn a_single_very_different_pixel_does_not_change_the_p95() {
        let reference = pattern();
        // Per-pixel differences 0..=9 in turn, so the p95 is a real order statistic.
        let test = offset(&reference, |i| (i % 10) as i32);
        let before = lookalike(&test, &reference).unwrap();
        let mut spoiled = test.clone();
        spoiled.pixels[500] = [255, 0, 255];
        let after = lookalike(&spoiled, &reference).unwrap();
        assert_eq!(before.p95, 9.0);
        assert_eq!(after.p95, before.p95);
        assert!(after.mean > before.mean);
    }

    #[test]
    fn a_larger_render_of_the_same_picture_is_the_same() {
        // Each pixel of the pattern as a 5x5 block: box resampling undoes it exactly.
        let small = pattern();
        let large = DisplayImage {
            width: 160,
            height: 160,
            pixels: (0..160 * 160)
                .map(|i| small.pixels[(i / 160 / 5) * 32 + (i % 160) / 5])
                .collect(),
        };
        let result = lookalike(&large, &small).unwrap();
        assert_eq!((result.mean, result.p95), (0.0, 0.0));
        assert_eq!((result.width, result.height), (32, 32));
    }

    #[test]
    fn a_different_aspect_is_said_and_compared_at_the_references() {
        let reference = DisplayImage {
            width: 64,
            height: 48,
            pixels: vec![[100, 100, 100]; 64 * 48],
        };
        let square = DisplayImage {
            width: 50,
            height: 50,
            pixels: vec![[100, 100, 100]; 50 * 50],
        };
        let result = lookalike(&square, &reference).unwrap();
        assert!(result.aspect_differs && result.same);
        assert_eq!((result.width, result.height), (32, 24));
        assert!(result.to_string().contains("aspect ratios differ"));
        // A height rounded to whole pixels is not a different aspect.
        let rounded = DisplayImage {
            width: 160,
            height: 121,
            pixels: vec![[100, 100, 100]; 160 * 121],
        };
        assert!(!lookalike(&rounded, &reference).unwrap().aspect_differs);
    }

    #[test]
    fn empty_or_inconsistent_images_are_errors() {
        let empty = DisplayImage {
            width: 0,
            height: 0,
            pixels: Vec::new(),
        };
        assert!(lookalike(&empty, &pattern()).is_err());
        let short = DisplayImage {
            width: 4,
            height: 4,
            pixels: vec![[0; 3]; 3],
        };
        assert!(lookalike(&pattern(), &short).is_err());
    }
}
