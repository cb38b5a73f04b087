//! A small deterministic random generator, seeded per pixel sample.
//!
//! Every pixel sample owns a generator derived from (pixel, sample index, seed),
//! so an image does not depend on the thread count or on the order of work.

/// PCG-XSH-RR 32-bit output on a 64-bit state (O'Neill, 2014).
#[derive(Clone, Debug)]
pub struct Rng {
    state: u64,
    increment: u64,
}

const MULTIPLIER: u64 = 6364136223846793005;

/// SplitMix64 finaliser: a bijective mix of all input bits.
pub fn mix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

impl Rng {
    /// The generator of one pixel sample.
    pub fn for_sample(pixel_index: u64, sample_index: u64, seed: u64) -> Self {
        let stream = mix64(seed ^ mix64(pixel_index));
        let state = mix64(stream ^ mix64(sample_index.wrapping_add(0x5151)));
        Rng::new(state, stream)
    }

    /// A generator for another stream, derived from this one's state and `salt`.
    pub fn fork(&self, salt: u64) -> Rng {
        Rng::new(
            mix64(self.state ^ salt),
            mix64(self.increment ^ mix64(salt)),
        )
    }

    pub fn new(state: u64, stream: u64) -> Self {
        let mut rng = Rng {
            state: 0,
            increment: (stream << 1) | 1,
        };
        rng.next_u32();
        rng.state = rng.state.wrapping_add(state);
        rng.next_u32();
        rng
    }

    pub fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(MULTIPLIER).wrapping_add(self.increment);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rotation = (old >> 59) as u32;
        xorshifted.rotate_right(rotation)
    }

    /// Uniform in `[0, 1)` with 53 random bits.
    pub fn next_f64(&mut self) -> f64 {
        let high = (self.next_u32() as u64) << 21;
        let low = (self.next_u32() as u64) >> 11;
        ((high | low) as f64) * (1.0 / (1u64 << 53) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_mean_and_range() {
        let mut rng = Rng::for_sample(3, 7, 42);
        let n = 100_000;
        let mut sum = 0.0;
        for _ in 0..n {
            let x = rng.next_f64();
            assert!((0.0..1.0).contains(&x));
            sum += x;
        }
        let mean = sum / n as f64;
        // Standard error of the mean is 1/sqrt(12 n) ~ 0.0009.
        assert!((mean - 0.5).abs() < 0.005, "mean {mean}");
    }

    #[test]
    fn different_samples_give_different_streams() {
        let a: Vec<u32> = (0..4)
            .map(|_| 0)
            .scan(Rng::for_sample(0, 0, 1), |r, _: u32| Some(r.next_u32()))
            .collect();
        let b: Vec<u32> = (0..4)
            .map(|_| 0)
            .scan(Rng::for_sample(0, 1, 1), |r, _: u32| Some(r.next_u32()))
            .collect();
        let c: Vec<u32> = (0..4)
            .map(|_| 0)
            .scan(Rng::for_sample(1, 0, 1), |r, _: u32| Some(r.next_u32()))
            .collect();
        assert_ne!(a, b);
        assert_ne!(a, c);
    }
}
