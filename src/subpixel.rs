//! The original's pixel filter: a 2x2 grid of sub-pixels, each sampled with
//! smallpt's tent filter. Each sample picks its sub-pixel and its offset
//! from the same two uniform numbers: per axis, the lower or upper half of
//! the number chooses the sub-pixel column (row), and the number rescaled
//! within that half draws the tent-distributed offset, of at most half a
//! pixel, from the sub-pixel centre. Every sample thus has the film density
//! [`filter_density`] (the mean of the four sub-pixel tents), whatever the
//! number of samples, which light tracing needs to splat onto the right
//! pixels with the right weight. The original visits the sub-pixels in
//! turn; the expected image is the same, and drawing them from the
//! sampler's stratified numbers spreads the first samples of a pixel over
//! the whole pixel (3% less error at 4 samples per pixel on `sample_rec`,
//! docs/performance.md).

/// Film position (in pixels, `y` up from the bottom edge) of a sample of
/// pixel (`x`, `y`), from two uniform numbers in `[0, 1)`.
pub fn film_position(x: usize, y: usize, u: [f64; 2]) -> (f64, f64) {
    (x as f64 + axis_offset(u[0]), y as f64 + axis_offset(u[1]))
}

/// Offset within the pixel along one axis: sub-pixel `0` for `u < 1/2`,
/// else `1`, at its centre plus a tent offset drawn from `u` rescaled to
/// `[0, 1)` within its half.
fn axis_offset(u: f64) -> f64 {
    let (sub, rescaled) = if u < 0.5 {
        (0.0, 2.0 * u)
    } else {
        (1.0, 2.0 * u - 1.0)
    };
    (0.5 + sub + tent(rescaled)) * 0.5
}

/// smallpt's tent filter: maps a uniform number in [0, 1) to an offset in
/// (-1, 1) with a triangular density.
pub fn tent(u: f64) -> f64 {
    let r = 2.0 * u;
    if r < 1.0 {
        r.sqrt() - 1.0
    } else {
        1.0 - (2.0 - r).sqrt()
    }
}

/// Density of a sub-pixel's offset along one axis, `d` pixels from its
/// centre: the tent of half-width 1/2.
fn tent_density(d: f64) -> f64 {
    (2.0 * (1.0 - 2.0 * d.abs())).max(0.0)
}

/// The density over the film (per square pixel) of the positions at which
/// pixel (`x`, `y`) samples: the mean of its four sub-pixel tents.
pub fn filter_density(x: usize, y: usize, film_x: f64, film_y: f64) -> f64 {
    let axis = |pixel: usize, position: f64| {
        let offset = position - pixel as f64;
        tent_density(offset - 0.25) + tent_density(offset - 0.75)
    };
    0.25 * axis(x, film_x) * axis(y, film_y)
}

/// The pixels (at most 2x2) whose filter covers film position
/// (`film_x`, `film_y`) in a `width` x `height` film, with their densities.
pub fn covering_pixels(
    width: usize,
    height: usize,
    film_x: f64,
    film_y: f64,
) -> impl Iterator<Item = (usize, usize, f64)> {
    // Sub-pixel footprints reach 1/4 pixel beyond their pixel.
    // An empty range for positions that are not finite.
    let range = |position: f64, size: usize| {
        let finite = position.is_finite();
        let first = (position - 1.25).ceil().max(0.0) as i64;
        let last = (position + 0.25).floor().min(size as f64 - 1.0) as i64;
        if finite { first..last + 1 } else { 0..0 }
    };
    let xs = range(film_x, width);
    range(film_y, height)
        .flat_map(move |y| xs.clone().map(move |x| (x, y)))
        .filter_map(move |(x, y)| {
            let (x, y) = (usize::try_from(x).ok()?, usize::try_from(y).ok()?);
            let density = filter_density(x, y, film_x, film_y);
            (density > 0.0).then_some((x, y, density))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tent_is_triangular_on_minus_one_to_one() {
        let n = 100_000;
        let mut near_zero = 0;
        for i in 0..n {
            let d = tent((i as f64 + 0.5) / n as f64);
            assert!(d > -1.0 && d < 1.0);
            if d.abs() < 0.5 {
                near_zero += 1;
            }
        }
        // A triangle on (-1, 1) puts 3/4 of its mass within 1/2 of the centre.
        let fraction = near_zero as f64 / n as f64;
        assert!((fraction - 0.75).abs() < 0.001, "{fraction}");
    }

    #[test]
    fn filter_density_integrates_to_one_and_matches_the_sample_positions() {
        // Integral over the film, by a fine grid.
        let steps = 400;
        let h = 3.0 / steps as f64;
        let mut integral = 0.0;
        for i in 0..steps {
            for j in 0..steps {
                let fx = 4.0 + (i as f64 + 0.5) * h;
                let fy = 6.0 + (j as f64 + 0.5) * h;
                integral += filter_density(5, 7, fx, fy) * h * h;
            }
        }
        assert!((integral - 1.0).abs() < 1e-3, "{integral}");
        // A histogram of sampled positions follows the density.
        let n = 200_000;
        let mut inside = 0;
        for k in 0..n {
            let u = [(k as f64 * 0.618_034) % 1.0, (k as f64 * 0.754_878) % 1.0];
            let (fx, fy) = film_position(5, 7, u);
            if (5.0..6.0).contains(&fx) && (7.0..8.0).contains(&fy) {
                inside += 1;
            }
        }
        let mut expected = 0.0;
        for i in 0..steps {
            for j in 0..steps {
                let fx = 5.0 + (i as f64 + 0.5) / steps as f64;
                let fy = 7.0 + (j as f64 + 0.5) / steps as f64;
                expected += filter_density(5, 7, fx, fy) / (steps * steps) as f64;
            }
        }
        let fraction = inside as f64 / n as f64;
        assert!(
            (fraction - expected).abs() < 0.005,
            "{fraction} vs {expected}"
        );
    }

    #[test]
    fn covering_pixels_are_exactly_those_with_positive_density() {
        let (width, height) = (6, 4);
        for i in 0..200 {
            let fx = -1.0 + 8.0 * (i as f64 * 0.618_034 % 1.0);
            let fy = -1.0 + 6.0 * (i as f64 * 0.754_878 % 1.0);
            let listed: Vec<(usize, usize)> = covering_pixels(width, height, fx, fy)
                .map(|(x, y, _)| (x, y))
                .collect();
            assert!(listed.len() <= 4);
            for y in 0..height {
                for x in 0..width {
                    let positive = filter_density(x, y, fx, fy) > 0.0;
                    assert_eq!(positive, listed.contains(&(x, y)), "{fx} {fy} {x} {y}");
                }
            }
        }
        assert_eq!(covering_pixels(6, 4, f64::NAN, 1.0).count(), 0);
    }
}
