//! Order-free sums of samples in fixed point: integer additions give the same
//! total in any order and any grouping, so a film rendered in parts (sample
//! ranges, pixel regions, processes) adds up to the film rendered at once.

use crate::color::Color;

/// Fractional bits of a fixed-point sample: each sample is rounded to a
/// multiple of 2^-32 (2.3e-10) before it is added.
pub const FRACTION_BITS: u32 = 32;
const SCALE: f64 = (1u64 << FRACTION_BITS) as f64;

/// The largest magnitude of one sample's channel, 2^30 (about 1.07e9):
/// larger values are clamped to it and the sample counts as saturated. With
/// this bound one sample is below 2^62 in fixed point, so 2^32 samples (the
/// most a `u32` count holds) sum to below 2^94: the `i128` sums cannot
/// overflow, and the squares (below 2^92 each) fit a `u128` sum.
pub const MAX_SAMPLE: f64 = (1u64 << 30) as f64;

/// `value` in fixed point, and whether it had to be clamped (NaN counts as
/// clamped to 0).
fn to_fixed(value: f64) -> (i64, bool) {
    let clamped = value.clamp(-MAX_SAMPLE, MAX_SAMPLE);
    // Exact: |clamped| * 2^32 <= 2^62 fits an i64; NaN converts to 0.
    ((clamped * SCALE).round() as i64, clamped != value)
}

/// The sum of RGB samples, each channel in fixed point.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FixedColor {
    pub channels: [i128; 3],
}

impl FixedColor {
    /// Adds one sample; returns whether a channel was clamped to
    /// [`MAX_SAMPLE`].
    pub fn add(&mut self, color: Color) -> bool {
        let mut saturated = false;
        for (total, value) in self.channels.iter_mut().zip([color.r, color.g, color.b]) {
            let (fixed, clamped) = to_fixed(value);
            *total = total.saturating_add(fixed as i128);
            saturated |= clamped;
        }
        saturated
    }

    /// Adds another sum (of other samples).
    pub fn add_sum(&mut self, other: &FixedColor) {
        for (total, value) in self.channels.iter_mut().zip(other.channels) {
            *total = total.saturating_add(value);
        }
    }

    /// Whether a channel's sum is below zero.
    #[inline]
    pub fn has_negative(&self) -> bool {
        self.channels.iter().any(|&c| c < 0)
    }

    pub fn to_color(&self) -> Color {
        let [r, g, b] = self.channels;
        Color::new(r as f64 / SCALE, g as f64 / SCALE, b as f64 / SCALE)
    }
}

/// The sum of squared values (luminances), in fixed point.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FixedSquares {
    pub total: u128,
}

impl FixedSquares {
    /// Adds `value * value`, the square of `value` rounded to fixed point
    /// (so the square is exact integer arithmetic).
    pub fn add(&mut self, value: f64) {
        let (fixed, _) = to_fixed(value);
        let wide = fixed.unsigned_abs() as u128;
        // Below 2^124, shifted back to FRACTION_BITS fractional bits.
        self.total = self.total.saturating_add((wide * wide) >> FRACTION_BITS);
    }

    pub fn add_sum(&mut self, other: &FixedSquares) {
        self.total = self.total.saturating_add(other.total);
    }

    pub fn to_f64(&self) -> f64 {
        self.total as f64 / SCALE
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    fn samples(count: usize) -> Vec<Color> {
        let mut rng = Rng::new(7, 1);
        (0..count)
            .map(|i| {
                // Values over many magnitudes, as a path tracer's are.
                let scale = 10f64.powi((i % 13) as i32 - 6);
                Color::new(rng.next_f64() * scale, rng.next_f64(), rng.next_f64() * 1e4)
            })
            .collect()
    }

    #[test]
    fn sums_do_not_depend_on_order_or_grouping() {
        let values = samples(1000);
        let mut once = FixedColor::default();
        let mut once_squares = FixedSquares::default();
        for v in &values {
            once.add(*v);
            once_squares.add(v.luminance());
        }
        let mut reversed = FixedColor::default();
        for v in values.iter().rev() {
            reversed.add(*v);
        }
        assert_eq!(once, reversed);
        // Three parts summed separately, then added in another order.
        let mut parts = [FixedColor::default(); 3];
        let mut part_squares = [FixedSquares::default(); 3];
        for (range, (part, squares)) in [0..160, 160..400, 400..1000]
            .into_iter()
            .zip(parts.iter_mut().zip(part_squares.iter_mut()))
        {
            for v in &values[range] {
                part.add(*v);
                squares.add(v.luminance());
            }
        }
        let mut merged = parts[2];
        merged.add_sum(&parts[0]);
        merged.add_sum(&parts[1]);
        assert_eq!(once, merged);
        let mut merged_squares = part_squares[1];
        merged_squares.add_sum(&part_squares[2]);
        merged_squares.add_sum(&part_squares[0]);
        assert_eq!(once_squares, merged_squares);
    }

    #[test]
    fn floating_point_sums_do_depend_on_grouping() {
        // The reason for fixed point: the same three parts in f64 differ.
        let values = samples(1000);
        let once: f64 = values.iter().map(|v| v.b).sum();
        let parts: Vec<f64> = [0..160, 160..400, 400..1000]
            .into_iter()
            .map(|range| values[range].iter().map(|v| v.b).sum())
            .collect();
        assert_ne!(once, parts[2] + parts[0] + parts[1]);
    }

    #[test]
    fn quantisation_is_within_half_a_step_per_sample() {
        let values = samples(1000);
        let mut sum = FixedColor::default();
        let mut exact = 0.0f64;
        for v in &values {
            sum.add(*v);
            exact += v.r;
        }
        let step = 1.0 / SCALE;
        assert!((sum.to_color().r - exact).abs() <= 0.5 * step * values.len() as f64 + 1e-9);
        let mut squares = FixedSquares::default();
        squares.add(3.0);
        squares.add(-0.5);
        assert_eq!(squares.to_f64(), 9.25);
    }

    #[test]
    fn huge_samples_saturate_and_are_counted() {
        let mut sum = FixedColor::default();
        assert!(!sum.add(Color::gray(MAX_SAMPLE)));
        assert!(sum.add(Color::new(1e300, 0.0, -1e300)));
        let color = sum.to_color();
        assert_eq!(color.r, 2.0 * MAX_SAMPLE);
        assert_eq!(color.b, 0.0);
        // The worst case of a u32 count of saturated samples does not overflow.
        let mut worst = FixedColor {
            channels: [(MAX_SAMPLE as i128) << FRACTION_BITS; 3],
        };
        for _ in 0..32 {
            let copy = worst;
            worst.add_sum(&copy);
        }
        assert!(worst.channels[0] < i128::MAX);
        assert_eq!(worst.to_color().r, MAX_SAMPLE * 2f64.powi(32));
    }
}
