//! Hash-based nested uniform (Owen) scrambling of 32-bit binary fractions,
//! after Burley 2020, "Practical Hash-based Owen Scrambling" (JCGT 9(4)).

/// The Laine–Karras permutation with the constants of Burley's paper. Every
/// output bit depends only on the seed and on the input bits at or below it, so
/// on bit-reversed values it is a nested uniform scramble.
pub fn laine_karras_permutation(mut x: u32, seed: u32) -> u32 {
    x = x.wrapping_add(seed);
    x ^= x.wrapping_mul(0x6c50_b47c);
    x ^= x.wrapping_mul(0xb82f_1e52);
    x ^= x.wrapping_mul(0xc7af_e638);
    x ^= x.wrapping_mul(0x8d22_f6e6);
    x
}

/// [`laine_karras_permutation`] of four values at once, each with its own
/// seed (written lane by lane so that it compiles to vector code).
#[inline]
pub fn laine_karras_permutation4(x: [u32; 4], seed: [u32; 4]) -> [u32; 4] {
    let mut x: [u32; 4] = std::array::from_fn(|i| x[i].wrapping_add(seed[i]));
    for constant in [0x6c50_b47c, 0xb82f_1e52, 0xc7af_e638, 0x8d22_f6e6u32] {
        for lane in &mut x {
            *lane ^= lane.wrapping_mul(constant);
        }
    }
    x
}

/// Owen-scrambles the binary fraction `x`: each bit is flipped or kept according
/// to a hash of the seed and all more significant bits. The map is a bijection
/// that keeps every elementary interval intact, so it preserves stratification.
pub fn nested_uniform_scramble(x: u32, seed: u32) -> u32 {
    laine_karras_permutation(x.reverse_bits(), seed).reverse_bits()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    #[test]
    fn scramble_keeps_shared_leading_bits_together() {
        let mut rng = Rng::new(5, 9);
        for _ in 0..10_000 {
            let x = rng.next_u32();
            let y = rng.next_u32();
            let seed = rng.next_u32();
            let shared = (x ^ y).leading_zeros();
            let scrambled = nested_uniform_scramble(x, seed) ^ nested_uniform_scramble(y, seed);
            assert!(
                scrambled.leading_zeros() >= shared,
                "{x:#x} {y:#x} {seed:#x}"
            );
        }
    }

    #[test]
    fn scramble_is_a_bijection_on_an_aligned_block() {
        let seed = 0xdead_beef;
        let prefix = 0xabcd_0000u32;
        let mut seen = vec![false; 1 << 16];
        let mut scrambled_prefix = None;
        for low in 0..(1u32 << 16) {
            let y = nested_uniform_scramble(prefix | low, seed);
            assert_eq!(*scrambled_prefix.get_or_insert(y >> 16), y >> 16);
            assert!(!seen[(y & 0xffff) as usize]);
            seen[(y & 0xffff) as usize] = true;
        }
    }

    #[test]
    fn different_seeds_scramble_differently() {
        let a: Vec<u32> = (0..16)
            .map(|i| nested_uniform_scramble(i << 28, 1))
            .collect();
        let b: Vec<u32> = (0..16)
            .map(|i| nested_uniform_scramble(i << 28, 2))
            .collect();
        assert_ne!(a, b);
    }
}
