//! The split's weights: over the choice of channel or wavelength, a split
//! path brings in expectation what the spectral transport gives.

use super::*;
use crate::color::Color;

/// The mean over `n` stratified choices `u` of the split throughput times
/// `factor(c)`.
fn mean_after_split(dispersion: Dispersion, throughput: Color, c: Color, n: usize) -> Color {
    let mut sum = Color::BLACK;
    for i in 0..n {
        let u = (i as f64 + 0.5) / n as f64;
        let mut state = PathSpectrum::Rgb;
        let mut t = throughput;
        state.split(&dispersion, u, &mut t);
        assert!(!state.is_rgb());
        sum += t * state.factor(c);
    }
    sum / n as f64
}

fn close(a: Color, b: Color, tolerance: f64) -> bool {
    (a.r - b.r).abs() < tolerance && (a.g - b.g).abs() < tolerance && (a.b - b.b).abs() < tolerance
}

#[test]
fn a_channel_split_keeps_the_rgb_product_in_expectation() {
    let throughput = Color::new(0.8, 0.5, 0.2);
    let c = Color::new(0.3, 0.9, 0.6);
    let mean = mean_after_split(Dispersion::YUZC19, throughput, c, 3);
    assert!(close(mean, throughput * c, 1e-12), "{mean:?}");
}

#[test]
fn a_wavelength_split_of_a_colour_times_grey_keeps_it_in_expectation() {
    // s_β · s_grey = g s_β, and ∫ c̃ s_β = β: exact for any β.
    let throughput = Color::new(0.8, 0.5, 0.2);
    let cauchy = Dispersion::Cauchy { a: 1.5, b: 0.01 };
    let mean = mean_after_split(cauchy, throughput, Color::gray(0.7), 100_000);
    assert!(close(mean, throughput * 0.7, 1e-4), "{mean:?}");
    // Two colours multiply as spectra: red times blue is not black.
    let red_blue = mean_after_split(
        cauchy,
        Color::new(1.0, 0.0, 0.0),
        Color::new(0.0, 0.0, 1.0),
        100_000,
    );
    assert!(
        red_blue.r.abs() + red_blue.g.abs() + red_blue.b.abs() > 1e-3,
        "{red_blue:?}"
    );
}

#[test]
fn a_split_path_keeps_its_choice() {
    let mut state = PathSpectrum::Rgb;
    let mut t = Color::WHITE;
    state.split(&Dispersion::Cauchy { a: 1.5, b: 0.01 }, 0.25, &mut t);
    let chosen = state;
    let before = t;
    state.split(&Dispersion::Cauchy { a: 1.5, b: 0.01 }, 0.9, &mut t);
    assert_eq!((state, t), (chosen, before));
    let PathSpectrum::Wavelength { nm, .. } = state else {
        panic!("{state:?}")
    };
    assert!((nm - (LAMBDA_MIN + 0.25 * (LAMBDA_MAX - LAMBDA_MIN))).abs() < 1e-9);
}

#[test]
fn cauchy_indices_fall_with_the_wavelength() {
    // Cambrian's glass: A + B·10⁶/λ² with λ in nm.
    let d = Dispersion::Cauchy {
        a: 2.385,
        b: 0.0117,
    };
    let at = |nm: f64| {
        let state = PathSpectrum::Wavelength {
            nm,
            basis: basis::basis(nm),
            sensor: Color::BLACK,
        };
        d.ior(&state)
    };
    assert!((at(500.0) - (2.385 + 0.0117e6 / 250_000.0)).abs() < 1e-12);
    assert!(at(400.0) > at(500.0) && at(500.0) > at(700.0));
    assert_eq!(Dispersion::YUZC19.ior(&PathSpectrum::Channel(2)), 1.6726);
}

#[test]
fn a_cambrian_camera_sample_keeps_its_wavelength_and_multiplies_as_rgb() {
    let (spectrum, throughput) = PathSpectrum::cambrian(0.5, 0.5);
    let nm = 380.0 + 0.5 * 370.0;
    assert_eq!(spectrum, PathSpectrum::Tinted { nm });
    assert_eq!(throughput, cambrian::weight(nm));
    // The glass sees Cauchy's index there; colours multiply channel by
    // channel; a split never replaces the camera's wavelength.
    let glass = Dispersion::Cauchy {
        a: 2.385,
        b: 0.0117,
    };
    assert_eq!(glass.ior(&spectrum), Dispersion::cauchy(2.385, 0.0117, nm));
    let c = Color::new(0.2, 0.4, 0.8);
    assert_eq!(spectrum.factor(c), c);
    let mut split = spectrum;
    let mut t = throughput;
    split.split(&glass, 0.9, &mut t);
    assert_eq!((split, t), (spectrum, throughput));
}
