//! Properties of the comparison metrics.

use super::*;
use crate::color::Color;
use crate::rng::Rng;

/// A smooth pattern in [0.2, 0.8] with some structure at several scales.
fn pattern(width: usize, height: usize) -> Image {
    let pixels = (0..width * height)
        .map(|i| {
            let (x, y) = ((i % width) as f64, (i / width) as f64);
            Color::new(
                0.5 + 0.3 * (x * 0.21).sin() * (y * 0.13).cos(),
                0.5 + 0.3 * ((x + y) * 0.05).sin(),
                0.5 + 0.3 * (x * 0.7).cos(),
            )
        })
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

/// Standard normal samples by Box-Muller, from a fixed seed.
fn normals(count: usize, seed: u64) -> Vec<f64> {
    let mut rng = Rng::for_sample(0, 0, seed);
    (0..count)
        .map(|_| {
            let u1 = 1.0 - rng.next_f64();
            let u2 = rng.next_f64();
            (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
        })
        .collect()
}

fn with_noise(image: &Image, noise: &[f64], sigma: f64) -> Image {
    let pixels = image
        .pixels
        .iter()
        .zip(noise.chunks_exact(3))
        .map(|(p, n)| Color::new(p.r + sigma * n[0], p.g + sigma * n[1], p.b + sigma * n[2]))
        .collect();
    Image {
        pixels,
        ..image.clone()
    }
}

#[test]
fn identical_images_are_perfect() {
    let image = pattern(40, 30);
    let c = compare(&image, &image).unwrap();
    assert_eq!(c.rmse, 0.0);
    assert_eq!(c.rel_mse, 0.0);
    assert_eq!(c.psnr, f64::INFINITY);
    assert!((c.ssim - 1.0).abs() < 1e-12, "ssim {}", c.ssim);
    assert!(c.to_json().contains("\"psnr\": null"), "{}", c.to_json());
    assert!(c.to_string().contains("psnr inf dB"), "{c}");
}

#[test]
fn ssim_decreases_monotonically_with_noise() {
    let reference = pattern(64, 48);
    let noise = normals(64 * 48 * 3, 7);
    let mut previous = 1.0;
    for sigma in [0.005, 0.01, 0.02, 0.05, 0.1, 0.2] {
        let ssim = compare(&with_noise(&reference, &noise, sigma), &reference)
            .unwrap()
            .ssim;
        assert!(ssim < previous, "sigma {sigma}: ssim {ssim} >= {previous}");
        assert!(ssim > 0.0);
        previous = ssim;
    }
    assert!(previous < 0.5, "heavy noise still scores {previous}");
}

#[test]
fn ssim_is_symmetric() {
    let reference = pattern(20, 17);
    let noisy = with_noise(&reference, &normals(20 * 17 * 3, 3), 0.05);
    let forward = compare(&noisy, &reference).unwrap().ssim;
    let backward = compare(&reference, &noisy).unwrap().ssim;
    assert!((forward - backward).abs() < 1e-12);
}

#[test]
fn constant_offset_gives_that_rmse_and_psnr() {
    let reference = pattern(33, 21);
    for offset in [0.001, 0.03, 0.25, 2.0] {
        let shifted = Image {
            pixels: reference
                .pixels
                .iter()
                .map(|p| p.map(|c| c + offset))
                .collect(),
            ..reference.clone()
        };
        let c = compare(&shifted, &reference).unwrap();
        assert!(
            (c.rmse - offset).abs() < 1e-12,
            "offset {offset}: rmse {}",
            c.rmse
        );
        let psnr = -20.0 * offset.log10();
        assert!(
            (c.psnr - psnr).abs() < 1e-9,
            "offset {offset}: psnr {}",
            c.psnr
        );
    }
}

#[test]
fn relative_mse_uses_the_documented_epsilon() {
    let black = Image {
        width: 2,
        height: 1,
        pixels: vec![Color::BLACK; 2],
    };
    let gray = Image {
        pixels: vec![Color::gray(0.1); 2],
        ..black.clone()
    };
    let c = compare(&gray, &black).unwrap();
    assert!((c.rel_mse - 0.01 / RELATIVE_MSE_EPSILON).abs() < 1e-12);
    // With the roles swapped, the error is relative to the brighter reference.
    let c = compare(&black, &gray).unwrap();
    assert!((c.rel_mse - 0.01 / (0.01 + RELATIVE_MSE_EPSILON)).abs() < 1e-12);
}

#[test]
fn hdr_values_count_in_linear_space_but_are_clamped_for_ssim() {
    let reference = pattern(16, 16);
    let brighter = Image {
        pixels: reference
            .pixels
            .iter()
            .map(|p| p.map(|c| c + 5.0))
            .collect(),
        ..reference.clone()
    };
    let white = Image {
        pixels: vec![Color::WHITE; 256],
        ..reference.clone()
    };
    // Both clamp to white, so SSIM sees no difference, while RMSE does.
    let c = compare(&brighter, &white).unwrap();
    assert!((c.ssim - 1.0).abs() < 1e-12);
    assert!(c.rmse > 4.0);
}

#[test]
fn size_mismatch_and_inconsistent_images_are_rejected() {
    let a = pattern(10, 8);
    let b = pattern(8, 10);
    let error = compare(&a, &b).unwrap_err();
    assert!(error.contains("10x8") && error.contains("8x10"), "{error}");
    let mut broken = a.clone();
    broken.pixels.pop();
    assert!(compare(&broken, &a).is_err());
    assert!(compare(&a, &broken).is_err());
}

#[test]
fn tiny_images_compare() {
    let a = pattern(1, 1);
    let c = compare(&a, &a).unwrap();
    assert!((c.ssim - 1.0).abs() < 1e-12);
}

#[test]
fn json_is_a_flat_object_with_the_four_numbers() {
    let c = Comparison {
        rmse: 0.5,
        rel_mse: 1e-7,
        psnr: 6.02,
        ssim: f64::NAN,
    };
    assert_eq!(
        c.to_json(),
        "{\"rmse\": 0.5, \"rel_mse\": 1e-7, \"psnr\": 6.02, \"ssim\": null}"
    );
}
