//! What `pathtracer compare` reports of two images: the pixel metrics, FLIP
//! and the look-alike criterion, as text and as JSON, with the error map.
//!
//! Images of different sizes get only the look-alike criterion (the others
//! compare pixel by pixel). FLIP compares display values: it is given for
//! images that hold them (8- or 16-bit files) and not for linear radiance
//! (PFM, EXR), whose error map is then the largest channel difference. The
//! look-alike criterion takes 8-bit values: a file's own bytes, or for
//! linear radiance the bytes `render -o x.png` would write for it.

use std::fmt;

use super::error_map::ErrorMap;
use super::flip::flip;
use super::lookalike::{Lookalike, lookalike};
use super::{Comparison, compare, json_number};
use crate::image_io::{DisplayImage, Image, PixelValues};

/// FLIP's mean, or why there is none.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FlipMean {
    Value {
        mean: f64,
        pixels_per_degree: f64,
    },
    /// One of the images holds linear radiance.
    LinearImage,
    /// The images differ in size.
    SizesDiffer,
}

/// Every figure of one comparison.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// RMSE, relative MSE, PSNR, SSIM; `None` when the sizes differ.
    pub pixels: Option<Comparison>,
    pub flip: FlipMean,
    pub lookalike: Lookalike,
}

/// A report and its per-pixel error map (FLIP where it applies, else the
/// largest channel difference; none for images of different sizes).
#[derive(Clone, Debug)]
pub struct Evaluation {
    pub report: Report,
    pub error_map: Option<ErrorMap>,
}

/// An image and what its values are.
#[derive(Clone, Copy, Debug)]
pub struct Encoded<'a> {
    pub image: &'a Image,
    pub encoding: PixelValues,
}

/// Compares `test` with `reference`, FLIP seen at `pixels_per_degree`.
pub fn evaluate(
    test: Encoded,
    reference: Encoded,
    pixels_per_degree: f64,
) -> Result<Evaluation, String> {
    let test_bytes = DisplayImage::from_image(test.image);
    let reference_bytes = DisplayImage::from_image(reference.image);
    let lookalike = lookalike(&test_bytes, &reference_bytes)?;
    let same_size =
        (test.image.width, test.image.height) == (reference.image.width, reference.image.height);
    if !same_size {
        return Ok(Evaluation {
            report: Report {
                pixels: None,
                flip: FlipMean::SizesDiffer,
                lookalike,
            },
            error_map: None,
        });
    }
    let pixels = compare(test.image, reference.image)?;
    let display =
        test.encoding == PixelValues::Display && reference.encoding == PixelValues::Display;
    let (flip_mean, error_map) = if display {
        let map = flip(&test_bytes, &reference_bytes, pixels_per_degree)?;
        let mean = FlipMean::Value {
            mean: map.mean(),
            pixels_per_degree,
        };
        (mean, map)
    } else {
        let map = ErrorMap::largest_channel_difference(test.image, reference.image)?;
        (FlipMean::LinearImage, map)
    };
    Ok(Evaluation {
        report: Report {
            pixels: Some(pixels),
            flip: flip_mean,
            lookalike,
        },
        error_map: Some(error_map),
    })
}

impl Report {
    /// One JSON object: `rmse`, `rel_mse`, `psnr`, `ssim` (null when the sizes
    /// differ; `psnr` also for identical images), `flip` and `ppd` (null
    /// where FLIP does not apply), and `lookalike` with `mean`, `p95`,
    /// `same`, `aspect_differs`, `width` and `height`.
    pub fn to_json(&self) -> String {
        let pixel = |value: fn(&Comparison) -> f64| {
            self.pixels
                .as_ref()
                .map_or("null".to_string(), |c| json_number(value(c)))
        };
        let (flip, ppd) = match self.flip {
            FlipMean::Value {
                mean,
                pixels_per_degree,
            } => (json_number(mean), json_number(pixels_per_degree)),
            _ => ("null".to_string(), "null".to_string()),
        };
        let l = &self.lookalike;
        format!(
            "{{\"rmse\": {}, \"rel_mse\": {}, \"psnr\": {}, \"ssim\": {}, \"flip\": {flip}, \"ppd\": {ppd}, \
             \"lookalike\": {{\"mean\": {}, \"p95\": {}, \"same\": {}, \"aspect_differs\": {}, \"width\": {}, \"height\": {}}}}}",
            pixel(|c| c.rmse),
            pixel(|c| c.rel_mse),
            pixel(|c| c.psnr),
            pixel(|c| c.ssim),
            json_number(l.mean),
            json_number(l.p95),
            l.same,
            l.aspect_differs,
            l.width,
            l.height
        )
    }
}

impl fmt::Display for Report {
    /// The pixel metrics and FLIP on one line, the look-alike criterion on
    /// the next.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.pixels {
            Some(pixels) => write!(f, "{pixels}")?,
            None => {
                let (t, r) = (self.lookalike.test_size, self.lookalike.reference_size);
                write!(
                    f,
                    "image sizes differ: {}x{} against a {}x{} reference; only the look-alike criterion compares them",
                    t.0, t.1, r.0, r.1
                )?;
            }
        }
        match self.flip {
            FlipMean::Value {
                mean,
                pixels_per_degree,
            } => write!(f, "  flip {mean:.5} ({pixels_per_degree} ppd)")?,
            FlipMean::LinearImage => {
                write!(f, "  flip n/a (linear image; FLIP compares display values)")?
            }
            FlipMean::SizesDiffer => {}
        }
        write!(f, "\n{}", self.lookalike)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Color;

    fn image(width: usize, height: usize, shade: impl Fn(usize) -> f64) -> Image {
        Image {
            width,
            height,
            pixels: (0..width * height)
                .map(|i| Color::gray((shade(i) * 255.0).floor() / 255.0))
                .collect(),
        }
    }

    fn display(image: &Image) -> Encoded<'_> {
        Encoded {
            image,
            encoding: PixelValues::Display,
        }
    }

    #[test]
    fn identical_display_images_have_zero_flip_a_black_map_and_look_the_same() {
        let a = image(16, 12, |i| (i % 7) as f64 / 7.0);
        let evaluation = evaluate(display(&a), display(&a), 67.0).unwrap();
        let report = &evaluation.report;
        assert_eq!(
            report.flip,
            FlipMean::Value {
                mean: 0.0,
                pixels_per_degree: 67.0
            }
        );
        assert!(report.lookalike.same && report.pixels.is_some_and(|p| p.rmse == 0.0));
        let map = evaluation.error_map.unwrap();
        assert!(map.values.iter().all(|&v| v == 0.0));
        assert!(report.to_json().contains("\"flip\": 0.0, \"ppd\": 67.0"));
    }

    #[test]
    fn linear_images_get_no_flip_and_the_largest_channel_difference() {
        let a = image(8, 8, |_| 0.5);
        let b = image(8, 8, |i| if i == 0 { 0.75 } else { 0.5 });
        let linear = Encoded {
            image: &b,
            encoding: PixelValues::Linear,
        };
        let evaluation = evaluate(display(&a), linear, 67.0).unwrap();
        assert_eq!(evaluation.report.flip, FlipMean::LinearImage);
        let map = evaluation.error_map.unwrap();
        assert!((map.values[0] - 0.25).abs() < 0.01 && map.values[1..].iter().all(|&v| v == 0.0));
        assert!(evaluation.report.to_string().contains("flip n/a"));
    }

    #[test]
    fn images_of_different_sizes_get_the_lookalike_criterion_only() {
        let small = image(20, 10, |_| 0.5);
        let large = image(40, 20, |_| 0.5);
        let evaluation = evaluate(display(&small), display(&large), 67.0).unwrap();
        let report = &evaluation.report;
        assert!(report.pixels.is_none() && evaluation.error_map.is_none());
        assert_eq!(report.flip, FlipMean::SizesDiffer);
        assert!(report.lookalike.same && !report.lookalike.aspect_differs);
        let json = report.to_json();
        assert!(json.starts_with(
            "{\"rmse\": null, \"rel_mse\": null, \"psnr\": null, \"ssim\": null, \"flip\": null"
        ));
        assert!(json.ends_with(
            "\"same\": true, \"aspect_differs\": false, \"width\": 32, \"height\": 16}}"
        ));
    }
}
