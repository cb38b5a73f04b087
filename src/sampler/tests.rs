//! Properties of the samplers: stratification, range, decorrelation,
//! determinism and convergence on a smooth integrand.

use super::sobol::sobol;
use super::*;

/// Asserts that the 2^k points hit every elementary interval of area 2^-k
/// (every 2^j by 2^(k-j) grid) exactly once.
fn assert_stratified(points: &[[f64; 2]], label: &str) {
    let n = points.len();
    assert!(n.is_power_of_two());
    let k = n.trailing_zeros();
    for j in 0..=k {
        let columns = 1usize << j;
        let rows = 1usize << (k - j);
        let mut count = vec![0u32; n];
        for p in points {
            let column = (p[0] * columns as f64) as usize;
            let row = (p[1] * rows as f64) as usize;
            count[row * columns + column] += 1;
        }
        assert!(
            count.iter().all(|&c| c == 1),
            "{label}: {n} points not stratified in the {columns}x{rows} grid"
        );
    }
}

fn sobol_points(pixel: u64, seed: u64, n: u64, first_dimension: u32) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let mut sampler = Sampler::new(SamplerKind::Sobol, pixel, i, seed);
            for _ in 0..first_dimension {
                sampler.next_f64();
            }
            sampler.next_2d()
        })
        .collect()
}

#[test]
fn unscrambled_first_pair_is_a_zero_two_sequence() {
    for k in 0..=10 {
        let n = 1u32 << k;
        let points: Vec<[f64; 2]> = (0..n)
            .map(|i| [sobol(i, 0) as f64, sobol(i, 1) as f64].map(|x| x / 4294967296.0))
            .collect();
        assert_stratified(&points, &format!("raw Sobol' 2^{k}"));
        // Every aligned block of 2^k points is a (0, k, 2)-net as well.
        let block: Vec<[f64; 2]> = (n..2 * n)
            .map(|i| [sobol(i, 0) as f64, sobol(i, 1) as f64].map(|x| x / 4294967296.0))
            .collect();
        assert_stratified(&block, &format!("raw Sobol' block 2^{k}"));
    }
}

#[test]
fn scrambled_shuffled_pairs_stay_stratified() {
    for (pixel, seed) in [(0, 0), (17, 3), (123_456, 0xfeed)] {
        for first_dimension in [0, 4, 8] {
            for k in 0..=10 {
                let points = sobol_points(pixel, seed, 1 << k, first_dimension);
                let label = format!("pixel {pixel} seed {seed} dims {first_dimension}+ 2^{k}");
                assert_stratified(&points, &label);
            }
        }
    }
}

#[test]
fn values_lie_in_the_unit_interval() {
    let indices = [0, 1, 2, 1023, u32::MAX as u64, 1 << 32, u64::MAX];
    for kind in SamplerKind::ALL {
        for pixel in [0, 1, 99, u64::MAX] {
            for &index in &indices {
                let mut sampler = Sampler::new(kind, pixel, index, 7);
                for _ in 0..64 {
                    let x = sampler.next_f64();
                    assert!((0.0..1.0).contains(&x), "{kind:?} {pixel} {index}: {x}");
                }
            }
        }
    }
    for index in 0..4096 {
        let mut sampler = Sampler::new(SamplerKind::Sobol, 5, index, 1);
        for _ in 0..16 {
            let x = sampler.next_f64();
            assert!((0.0..1.0).contains(&x), "{index}: {x}");
        }
    }
}

#[test]
fn samplers_are_deterministic() {
    for kind in SamplerKind::ALL {
        let mut a = Sampler::new(kind, 42, 9, 1234);
        let mut b = Sampler::new(kind, 42, 9, 1234);
        for _ in 0..40 {
            assert_eq!(a.next_f64().to_bits(), b.next_f64().to_bits());
        }
    }
}

#[test]
fn stream_equals_addressed_samples() {
    for (pixel, index, seed) in [(0, 0, 0), (3, 77, 5), (8, (1 << 32) + 5, 2)] {
        let mut stream = SobolStream::new(pixel, index, seed);
        for dimension in 0..20 {
            assert_eq!(stream.dimension(), dimension);
            let expected = sobol_sample(pixel, index, dimension, seed);
            assert_eq!(stream.next_f64().to_bits(), expected.to_bits());
        }
    }
}

#[test]
fn independent_wraps_the_per_sample_rng() {
    let mut sampler = Sampler::new(SamplerKind::Independent, 4, 5, 6);
    let mut rng = Rng::for_sample(4, 5, 6);
    for _ in 0..10 {
        assert_eq!(sampler.next_f64().to_bits(), rng.next_f64().to_bits());
    }
}

#[test]
fn next_2d_starts_at_an_even_dimension() {
    let mut stream = SobolStream::new(1, 2, 3);
    stream.next_f64();
    let pair = stream.next_2d();
    assert_eq!(stream.dimension(), 4);
    assert_eq!(pair[0], sobol_sample(1, 2, 2, 3));
    assert_eq!(pair[1], sobol_sample(1, 2, 3, 3));
}

#[test]
fn pairs_and_single_values_in_any_order_equal_addressed_samples() {
    let mut rng = Rng::new(7, 8);
    for round in 0..200u64 {
        let (pixel, index, seed) = (round % 13, round * 7 + 1, round % 3);
        let mut stream = SobolStream::new(pixel, index, seed);
        while stream.dimension() < 24 {
            if rng.next_f64() < 0.5 {
                let dimension = stream.dimension();
                let value = stream.next_f64();
                let expected = sobol_sample(pixel, index, dimension, seed);
                assert_eq!(value.to_bits(), expected.to_bits());
            } else {
                // Pairs start at an even dimension among the Sobol' ones.
                let dimension = stream.dimension();
                let first = if dimension < SOBOL_DIMENSIONS {
                    dimension + dimension % 2
                } else {
                    dimension
                };
                let pair = stream.next_2d();
                for (k, value) in pair.into_iter().enumerate() {
                    let expected = sobol_sample(pixel, index, first + k as u32, seed);
                    assert_eq!(value.to_bits(), expected.to_bits(), "{dimension} {k}");
                }
                assert_eq!(stream.dimension(), first + 2);
            }
        }
    }
}

/// Pearson correlation of two equally long series.
fn correlation(xs: &[f64], ys: &[f64]) -> f64 {
    let n = xs.len() as f64;
    let mean_x = xs.iter().sum::<f64>() / n;
    let mean_y = ys.iter().sum::<f64>() / n;
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (x, y) in xs.iter().zip(ys) {
        sxy += (x - mean_x) * (y - mean_y);
        sxx += (x - mean_x) * (x - mean_x);
        syy += (y - mean_y) * (y - mean_y);
    }
    sxy / (sxx * syy).sqrt()
}

fn dimension_series(pixel: u64, seed: u64, dimension: u32, n: u64) -> Vec<f64> {
    (0..n)
        .map(|i| sobol_sample(pixel, i, dimension, seed))
        .collect()
}

#[test]
fn second_group_is_not_correlated_with_the_first() {
    let mut largest: f64 = 0.0;
    for (pixel, seed) in [(0, 0), (5, 1), (1000, 77)] {
        for (a, b) in [(0, 4), (1, 5), (0, 5), (1, 4), (0, 8), (2, 6)] {
            let xs = dimension_series(pixel, seed, a, 4096);
            let ys = dimension_series(pixel, seed, b, 4096);
            let r = correlation(&xs, &ys);
            assert!(
                r.abs() < 0.05,
                "pixel {pixel}: dims {a},{b} correlation {r}"
            );
            largest = largest.max(r.abs());
        }
    }
    println!("largest |correlation| across groups: {largest:.4}");
}

#[test]
fn neighbouring_pixels_are_decorrelated() {
    for (a, b) in [(0, 1), (1, 2), (640, 641), (0, 640)] {
        for dimension in [0, 1, 4] {
            let xs = dimension_series(a, 9, dimension, 4096);
            let ys = dimension_series(b, 9, dimension, 4096);
            assert_ne!(xs[..8], ys[..8]);
            let r = correlation(&xs, &ys);
            assert!(r.abs() < 0.05, "pixels {a},{b} dim {dimension}: {r}");
        }
    }
}

#[test]
fn indices_beyond_two_to_the_32_are_scrambled_anew() {
    let low: Vec<f64> = (0..8).map(|i| sobol_sample(3, i, 0, 1)).collect();
    let high: Vec<f64> = (0..8)
        .map(|i| sobol_sample(3, (1 << 32) + i, 0, 1))
        .collect();
    assert_ne!(low, high);
}

#[test]
fn names_round_trip() {
    for kind in SamplerKind::ALL {
        assert_eq!(SamplerKind::from_name(kind.name()), Some(kind));
    }
    assert_eq!(SamplerKind::from_name("halton"), None);
}

/// RMS error, over 64 seeds, of the 1024-sample estimate of the integral of
/// exp(-(x^2 + y^2)) over the unit square.
fn rms_error(kind: SamplerKind) -> f64 {
    // (integral of exp(-x^2) over [0, 1])^2 = (sqrt(pi) erf(1) / 2)^2.
    let exact = 0.746_824_132_812_427_f64.powi(2);
    let samples = 1024;
    let seeds = 64;
    let mut sum_squared = 0.0;
    for seed in 0..seeds {
        let mut sum = 0.0;
        for index in 0..samples {
            let [x, y] = Sampler::new(kind, 11, index, seed).next_2d();
            sum += (-(x * x + y * y)).exp();
        }
        let error = sum / samples as f64 - exact;
        sum_squared += error * error;
    }
    (sum_squared / seeds as f64).sqrt()
}

#[test]
fn sobol_converges_faster_than_independent_on_a_smooth_integrand() {
    let independent = rms_error(SamplerKind::Independent);
    let sobol = rms_error(SamplerKind::Sobol);
    println!("RMS error at 1024 spp: independent {independent:.3e}, sobol {sobol:.3e}");
    assert!(
        sobol * 5.0 < independent,
        "independent {independent}, sobol {sobol}"
    );
}
