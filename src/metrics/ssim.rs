//! Structural similarity (Wang, Bovik, Sheikh and Simoncelli, 2004) on luminance.
//!
//! Each image is reduced to Rec. 709 luminance after clamping every channel to
//! [0, 1] (so L = 1). Local statistics use the paper's 11x11 Gaussian window with
//! sigma = 1.5, applied as two separable 1-D passes. Near the border the window is
//! cut to the image and renormalised to unit weight, so every pixel gets a value
//! and images smaller than the window still compare; the result is the mean of
//! the SSIM map over all pixels. Constants: K1 = 0.01, K2 = 0.03.

use crate::image_io::Image;

const RADIUS: usize = 5;
const SIGMA: f64 = 1.5;
const C1: f64 = 0.01 * 0.01;
const C2: f64 = 0.03 * 0.03;

/// Mean SSIM of two images of equal size (checked by the caller).
pub(super) fn mean_ssim(a: &Image, b: &Image) -> f64 {
    let (width, height) = (a.width, a.height);
    let clamped_luminance = |image: &Image| -> Vec<f64> {
        image
            .pixels
            .iter()
            .map(|p| {
                p.map(|c| if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) })
                    .luminance()
            })
            .collect()
    };
    let x = clamped_luminance(a);
    let y = clamped_luminance(b);
    let filter = SeparableGaussian::new(width, height);
    let square = |v: &[f64]| -> Vec<f64> { v.iter().map(|s| s * s).collect() };
    let product: Vec<f64> = x.iter().zip(&y).map(|(p, q)| p * q).collect();

    let mu_x = filter.apply(&x);
    let mu_y = filter.apply(&y);
    let mean_xx = filter.apply(&square(&x));
    let mean_yy = filter.apply(&square(&y));
    let mean_xy = filter.apply(&product);

    let mut sum = 0.0;
    for i in 0..width * height {
        let (mx, my) = (mu_x[i], mu_y[i]);
        let variance_x = mean_xx[i] - mx * mx;
        let variance_y = mean_yy[i] - my * my;
        let covariance = mean_xy[i] - mx * my;
        sum += ((2.0 * mx * my + C1) * (2.0 * covariance + C2))
            / ((mx * mx + my * my + C1) * (variance_x + variance_y + C2));
    }
    sum / (width * height) as f64
}

/// A normalised Gaussian blur whose window is cut at the border and renormalised.
struct SeparableGaussian {
    width: usize,
    height: usize,
    kernel: [f64; 2 * RADIUS + 1],
    /// 1 / (sum of the kernel weights inside the image), per column and per row.
    column_normaliser: Vec<f64>,
    row_normaliser: Vec<f64>,
}

impl SeparableGaussian {
    fn new(width: usize, height: usize) -> Self {
        let mut kernel = [0.0; 2 * RADIUS + 1];
        for (i, weight) in kernel.iter_mut().enumerate() {
            let d = i as f64 - RADIUS as f64;
            *weight = (-d * d / (2.0 * SIGMA * SIGMA)).exp();
        }
        let total: f64 = kernel.iter().sum();
        kernel.iter_mut().for_each(|w| *w /= total);
        let normaliser = |length: usize| -> Vec<f64> {
            (0..length)
                .map(|center| {
                    let (first, last) = window(center, length);
                    let inside: f64 = (first..=last).map(|j| kernel[j + RADIUS - center]).sum();
                    1.0 / inside
                })
                .collect()
        };
        SeparableGaussian {
            width,
            height,
            kernel,
            column_normaliser: normaliser(width),
            row_normaliser: normaliser(height),
        }
    }

    /// Blurs a `width x height` row-major map.
    fn apply(&self, input: &[f64]) -> Vec<f64> {
        let (width, height) = (self.width, self.height);
        let mut horizontal = vec![0.0; width * height];
        for (source, target) in input
            .chunks_exact(width)
            .zip(horizontal.chunks_exact_mut(width))
        {
            for (x, value) in target.iter_mut().enumerate() {
                let (first, last) = window(x, width);
                let taps = &self.kernel[first + RADIUS - x..=last + RADIUS - x];
                let sum: f64 = taps
                    .iter()
                    .zip(&source[first..=last])
                    .map(|(k, s)| k * s)
                    .sum();
                *value = sum * self.column_normaliser[x];
            }
        }
        // Vertical pass, one output row at a time, accumulating whole input rows.
        let mut output = vec![0.0; width * height];
        for (y, target) in output.chunks_exact_mut(width).enumerate() {
            let (first, last) = window(y, height);
            for j in first..=last {
                let weight = self.kernel[j + RADIUS - y] * self.row_normaliser[y];
                let source = &horizontal[j * width..(j + 1) * width];
                for (t, s) in target.iter_mut().zip(source) {
                    *t += weight * s;
                }
            }
        }
        output
    }
}

/// The inclusive index range of the window around `center`, cut to `0..length`.
fn window(center: usize, length: usize) -> (usize, usize) {
    (
        center.saturating_sub(RADIUS),
        (center + RADIUS).min(length - 1),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Color;

    #[test]
    fn blur_preserves_constants_at_the_border() {
        let filter = SeparableGaussian::new(13, 4);
        let blurred = filter.apply(&[0.7; 52]);
        assert!(blurred.iter().all(|v| (v - 0.7).abs() < 1e-12));
    }

    #[test]
    fn separable_blur_equals_the_direct_cut_window() {
        let (width, height) = (17, 9);
        let input: Vec<f64> = (0..width * height)
            .map(|i| ((i * 7919) % 101) as f64 / 100.0)
            .collect();
        let filter = SeparableGaussian::new(width, height);
        let blurred = filter.apply(&input);
        let weight = |d: f64| (-d * d / (2.0 * SIGMA * SIGMA)).exp();
        for y in 0..height {
            for x in 0..width {
                let (mut sum, mut total) = (0.0, 0.0);
                for j in y.saturating_sub(RADIUS)..(y + RADIUS + 1).min(height) {
                    for i in x.saturating_sub(RADIUS)..(x + RADIUS + 1).min(width) {
                        let w = weight(i as f64 - x as f64) * weight(j as f64 - y as f64);
                        sum += w * input[j * width + i];
                        total += w;
                    }
                }
                assert!((blurred[y * width + x] - sum / total).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn blur_of_an_impulse_sums_to_one_in_the_interior() {
        let filter = SeparableGaussian::new(21, 21);
        let mut impulse = vec![0.0; 21 * 21];
        impulse[10 * 21 + 10] = 1.0;
        let blurred = filter.apply(&impulse);
        assert!((blurred.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert_eq!(blurred[0], 0.0);
    }

    #[test]
    fn constant_images_follow_the_luminance_term() {
        let image = |v: f64| Image {
            width: 4,
            height: 3,
            pixels: vec![Color::gray(v); 12],
        };
        let (a, b) = (0.2, 0.6);
        let expected = (2.0 * a * b + C1) / (a * a + b * b + C1);
        assert!((mean_ssim(&image(a), &image(b)) - expected).abs() < 1e-9);
    }
}
