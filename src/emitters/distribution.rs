//! A discrete distribution over table entries, proportional to given weights,
//! sampled by binary search over its cumulative sums (O(log n)).

/// Picks index `i` with probability `weights[i] / sum(weights)`.
#[derive(Clone, Debug)]
pub struct Distribution {
    /// Normalised cumulative sums: `cdf[i] = (w_0 + ... + w_i) / total`.
    cdf: Vec<f64>,
    /// `w_i / total`.
    pmf: Vec<f64>,
    /// The last index with a positive weight (guards rounding at `u` near 1).
    last_positive: usize,
}

impl Distribution {
    /// `None` when no weight is positive and finite. Negative, NaN and infinite
    /// weights count as zero.
    pub fn new(weights: &[f64]) -> Option<Distribution> {
        let clean = |w: f64| if w.is_finite() && w > 0.0 { w } else { 0.0 };
        let total: f64 = weights.iter().map(|&w| clean(w)).sum();
        if !(total > 0.0 && total.is_finite()) {
            return None;
        }
        let mut running = 0.0;
        let mut cdf = Vec::with_capacity(weights.len());
        let mut pmf = Vec::with_capacity(weights.len());
        let mut last_positive = 0;
        for (index, &w) in weights.iter().enumerate() {
            let w = clean(w);
            if w > 0.0 {
                last_positive = index;
            }
            running += w;
            cdf.push(running / total);
            pmf.push(w / total);
        }
        Some(Distribution {
            cdf,
            pmf,
            last_positive,
        })
    }

    pub fn len(&self) -> usize {
        self.pmf.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pmf.is_empty()
    }

    /// The index for a uniform `u` in [0, 1), and its probability. Entries of
    /// zero weight are never returned.
    pub fn sample(&self, u: f64) -> (usize, f64) {
        let index = self
            .cdf
            .partition_point(|&c| c <= u)
            .min(self.last_positive);
        (index, self.pmf[index])
    }

    /// The probability of `index` (0 out of range).
    pub fn pmf(&self, index: usize) -> f64 {
        self.pmf.get(index).copied().unwrap_or(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frequencies_follow_the_weights_and_skip_zeros() {
        let weights = [0.0, 1.0, 0.0, 3.0, 0.0];
        let distribution = Distribution::new(&weights).unwrap();
        let n = 100_000;
        let mut counts = [0usize; 5];
        for i in 0..n {
            let (index, pmf) = distribution.sample((i as f64 + 0.5) / n as f64);
            assert_eq!(pmf, distribution.pmf(index));
            counts[index] += 1;
        }
        assert_eq!(counts[0] + counts[2] + counts[4], 0);
        assert!((counts[3] as f64 / n as f64 - 0.75).abs() < 1e-3);
        // Rounding at the top end never picks a trailing zero-weight entry.
        assert_eq!(distribution.sample(1.0 - f64::EPSILON / 4.0).0, 3);
        assert_eq!(distribution.sample(1.0).0, 3);
        assert!((0..5).map(|i| distribution.pmf(i)).sum::<f64>() - 1.0 < 1e-12);
    }

    #[test]
    fn no_positive_weight_is_no_distribution() {
        assert!(Distribution::new(&[]).is_none());
        assert!(Distribution::new(&[0.0, -1.0, f64::NAN]).is_none());
    }
}
