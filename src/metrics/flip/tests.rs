//! FLIP against the paper: zero for identical images, the colour pipeline
//! alone for uniform images (computed here from the paper's formulas), local
//! support, and differences that fade with viewing distance.

use super::*;

fn uniform(width: usize, height: usize, rgb: [u8; 3]) -> DisplayImage {
    DisplayImage {
        width,
        height,
        pixels: vec![rgb; width * height],
    }
}

fn pattern(width: usize, height: usize) -> DisplayImage {
    DisplayImage {
        width,
        height,
        pixels: (0..width * height)
            .map(|i| {
                let (x, y) = (i % width, i / width);
                [
                    (x * 9 % 256) as u8,
                    (y * 7 % 256) as u8,
                    ((x ^ y) * 5 % 256) as u8,
                ]
            })
            .collect(),
    }
}

/// sRGB display value to linear (IEC 61966-2-1).
fn linear(value: u8) -> f64 {
    let c = value as f64 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Linear sRGB to CIELAB (D65 white: the XYZ of linear white), then the
/// paper's Hunt adjustment: a and b scaled by 0.01 L.
fn hunt_lab(rgb: [f64; 3]) -> [f64; 3] {
    let m = [
        [0.4124564, 0.3575761, 0.1804375],
        [0.2126729, 0.7151522, 0.0721750],
        [0.0193339, 0.1191920, 0.9503041],
    ];
    let xyz = |c: [f64; 3]| m.map(|row| row[0] * c[0] + row[1] * c[1] + row[2] * c[2]);
    let white = xyz([1.0, 1.0, 1.0]);
    let colour = xyz(rgb);
    let delta: f64 = 6.0 / 29.0;
    let f = |t: f64| {
        if t > delta.powi(3) {
            t.cbrt()
        } else {
            t / (3.0 * delta * delta) + 4.0 / 29.0
        }
    };
    let [fx, fy, fz] = [0, 1, 2].map(|i| f(colour[i] / white[i]));
    let l = 116.0 * fy - 16.0;
    [
        l,
        0.01 * l * 500.0 * (fx - fy),
        0.01 * l * 200.0 * (fy - fz),
    ]
}

/// HyAB: city-block in L, Euclidean in (a, b).
fn hyab(p: [f64; 3], q: [f64; 3]) -> f64 {
    (p[0] - q[0]).abs() + ((p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
}

/// The paper's colour error of two flat colours: HyAB of the Hunt-adjusted
/// colours to the power q_c = 0.7, remapped by p_c = 0.4 and p_t = 0.95 of
/// c_max, the (powered) HyAB between pure green and pure blue.
fn paper_colour_error(a: [u8; 3], b: [u8; 3]) -> f64 {
    let (qc, pc, pt) = (0.7, 0.4, 0.95);
    let cmax = hyab(hunt_lab([0.0, 1.0, 0.0]), hunt_lab([0.0, 0.0, 1.0])).powf(qc);
    let d = hyab(hunt_lab(a.map(linear)), hunt_lab(b.map(linear))).powf(qc);
    if d < pc * cmax {
        pt / (pc * cmax) * d
    } else {
        pt + (d - pc * cmax) / (cmax - pc * cmax) * (1.0 - pt)
    }
}

#[test]
fn identical_images_have_no_error_anywhere() {
    let image = pattern(40, 30);
    let map = flip(&image, &image, DEFAULT_PIXELS_PER_DEGREE).unwrap();
    assert_eq!((map.width, map.height, map.values.len()), (40, 30, 1200));
    assert!(map.values.iter().all(|&v| v == 0.0));
    assert_eq!(map.mean(), 0.0);
}

#[test]
fn flat_images_differ_by_the_papers_colour_error_alone() {
    // Flat images have no edges or points, and filtering keeps them flat,
    // so FLIP is the colour pipeline's value at every pixel.
    let pairs = [
        ([0, 0, 0], [255, 255, 255]),
        ([128, 128, 128], [140, 140, 140]),
        ([200, 30, 30], [30, 200, 30]),
        ([10, 20, 200], [12, 22, 190]),
        ([90, 60, 30], [30, 60, 90]),
    ];
    for (a, b) in pairs {
        let expected = paper_colour_error(a, b);
        let map = flip(
            &uniform(24, 16, a),
            &uniform(24, 16, b),
            DEFAULT_PIXELS_PER_DEGREE,
        )
        .unwrap();
        for &value in &map.values {
            assert!(
                (value - expected).abs() < 2e-3,
                "{a:?} against {b:?}: FLIP {value}, the paper's colour error {expected}"
            );
        }
    }
    // Black against white is past p_c c_max: in [p_t, 1].
    let extreme = paper_colour_error([0, 0, 0], [255, 255, 255]);
    assert!((0.95..=1.0).contains(&extreme), "{extreme}");
}

#[test]
fn values_lie_in_zero_to_one_and_a_change_is_seen_only_near_it() {
    let reference = uniform(64, 64, [120, 120, 120]);
    let mut test = reference.clone();
    test.pixels[32 * 64 + 32] = [255, 0, 0];
    let map = flip(&test, &reference, DEFAULT_PIXELS_PER_DEGREE).unwrap();
    assert!(map.values.iter().all(|v| (0.0..=1.0).contains(v)));
    assert!(
        map.values[32 * 64 + 32] > 0.1,
        "{}",
        map.values[32 * 64 + 32]
    );
    // The widest filter at 67 ppd reaches 10 pixels; beyond, nothing differs.
    for (i, &value) in map.values.iter().enumerate() {
        let (x, y) = ((i % 64) as i64 - 32, (i / 64) as i64 - 32);
        if x.abs().max(y.abs()) > 20 {
            assert_eq!(value, 0.0, "error {value} at offset ({x}, {y})");
        }
    }
    let scrambled = pattern(64, 64);
    let map = flip(&scrambled, &reference, DEFAULT_PIXELS_PER_DEGREE).unwrap();
    assert!(map.values.iter().all(|v| (0.0..=1.0).contains(v)));
}

#[test]
fn fine_detail_fades_with_viewing_distance() {
    // A one-pixel checkerboard against flat grey of its linear mean: the eye
    // blurs it from far away (more pixels per degree), so the difference
    // falls. Measured in the middle, away from the borders' clamped filters.
    let size = 128;
    let checker = DisplayImage {
        width: size,
        height: size,
        pixels: (0..size * size)
            .map(|i| {
                if (i % size + i / size) % 2 == 0 {
                    [60; 3]
                } else {
                    [180; 3]
                }
            })
            .collect(),
    };
    let grey = uniform(size, size, [137, 137, 137]);
    let middle = |ppd: f64| {
        let map = flip(&checker, &grey, ppd).unwrap();
        let mut sum = 0.0;
        for y in 56..72 {
            for x in 56..72 {
                sum += map.values[y * size + x];
            }
        }
        sum / 256.0
    };
    let errors: Vec<f64> = [5.0, 10.0, 20.0, DEFAULT_PIXELS_PER_DEGREE]
        .map(middle)
        .to_vec();
    assert!(errors.windows(2).all(|w| w[0] > w[1]), "{errors:?}");
}

#[test]
fn the_default_viewing_conditions_are_67_pixels_per_degree() {
    let ppd = pixels_per_degree(0.7, 0.7, 3840.0);
    assert!((ppd - 67.02).abs() < 0.01, "{ppd}");
    assert_eq!(ppd.round(), DEFAULT_PIXELS_PER_DEGREE);
}

#[test]
fn mismatched_sizes_and_bad_viewing_conditions_are_errors() {
    let a = uniform(8, 8, [0; 3]);
    let b = uniform(8, 9, [0; 3]);
    assert!(flip(&a, &b, DEFAULT_PIXELS_PER_DEGREE).is_err());
    for ppd in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(flip(&a, &a, ppd).is_err(), "{ppd}");
    }
    let tiny = uniform(1, 1, [10, 20, 30]);
    let map = flip(
        &tiny,
        &uniform(1, 1, [30, 20, 10]),
        DEFAULT_PIXELS_PER_DEGREE,
    )
    .unwrap();
    assert_eq!(map.values.len(), 1);
}
