//! The first four dimensions of the Sobol' sequence, with direction numbers
//! derived at compile time from their primitive polynomials.
//!
//! Dimension 0 is the van der Corput sequence in base 2; dimensions 1..3 use the
//! primitive polynomials x + 1, x^2 + x + 1 and x^3 + x + 1 with initial values
//! m = (1), (1, 3) and (1, 3, 1), as in the Joe–Kuo tables.

/// Number of Sobol' dimensions generated; dimensions beyond repeat them in
/// independently scrambled groups.
pub const DIMENSIONS: usize = 4;

/// Direction numbers `v[k] = m[k] << (31 - k)` of each dimension, bit `k` of the
/// sample index selecting `v[k]`.
pub const DIRECTIONS: [[u32; 32]; DIMENSIONS] = [
    van_der_corput_directions(),
    directions(1, 0b0, &[1]),
    directions(2, 0b1, &[1, 3]),
    directions(3, 0b01, &[1, 3, 1]),
];

const fn van_der_corput_directions() -> [u32; 32] {
    let mut v = [0u32; 32];
    let mut k = 0;
    while k < 32 {
        v[k] = 1 << (31 - k);
        k += 1;
    }
    v
}

/// The standard Sobol' recurrence for a primitive polynomial of `degree` s,
/// `x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1`, whose interior coefficients are
/// the bits of `coefficients` (a_1 the most significant of the s - 1 bits):
/// `m_k = 2 a_1 m_(k-1) ^ 4 a_2 m_(k-2) ^ ... ^ 2^s m_(k-s) ^ m_(k-s)`.
const fn directions(degree: usize, coefficients: u32, initial: &[u32]) -> [u32; 32] {
    let mut m = [0u32; 32];
    let mut k = 0;
    while k < 32 {
        if k < degree {
            m[k] = initial[k];
        } else {
            let mut value = m[k - degree] ^ (m[k - degree] << degree);
            let mut j = 1;
            while j < degree {
                if (coefficients >> (degree - 1 - j)) & 1 == 1 {
                    value ^= m[k - j] << j;
                }
                j += 1;
            }
            m[k] = value;
        }
        k += 1;
    }
    let mut v = [0u32; 32];
    let mut k = 0;
    while k < 32 {
        v[k] = m[k] << (31 - k);
        k += 1;
    }
    v
}

/// Component `dimension` (< [`DIMENSIONS`]) of Sobol' point `index`, as a 32-bit
/// binary fraction.
pub fn sobol(index: u32, dimension: usize) -> u32 {
    let directions = &DIRECTIONS[dimension];
    let mut bits = index;
    let mut value = 0;
    while bits != 0 {
        let k = bits.trailing_zeros();
        value ^= directions[k as usize];
        bits &= bits - 1;
    }
    value
}

/// `REVERSED_TABLES[b][x]`: the XOR of the direction numbers selected by the
/// bits of byte value `x` at byte position `b` of a bit-reversed index, for
/// the four dimensions packed as `[u32; 4]` (16 KiB), themselves
/// bit-reversed: entry bit `m` of the reversed index selects
/// `reverse(v[31 - m])`, and four lookups make a point. Owen scrambling works on
/// bit-reversed values, so a scrambler can go from a reversed index to
/// reversed points without reversing anything in between.
static REVERSED_TABLES: [[[u32; DIMENSIONS]; 256]; 4] = reversed_tables();

const fn reversed_tables() -> [[[u32; DIMENSIONS]; 256]; 4] {
    let mut tables = [[[0u32; DIMENSIONS]; 256]; 4];
    let mut byte = 0;
    while byte < 4 {
        let mut x = 0;
        while x < 256 {
            let mut dimension = 0;
            while dimension < DIMENSIONS {
                let mut value = 0;
                let mut bit = 0;
                while bit < 8 {
                    if (x >> bit) & 1 == 1 {
                        let m = byte * 8 + bit;
                        value ^= DIRECTIONS[dimension][31 - m].reverse_bits();
                    }
                    bit += 1;
                }
                tables[byte][x][dimension] = value;
                dimension += 1;
            }
            x += 1;
        }
        byte += 1;
    }
    tables
}

/// The bit-reversed points of all four dimensions for the index whose
/// bit-reversal is `reversed_index`: `sobol_all(reversed_index.reverse_bits())`
/// with each value reversed, in four table lookups.
#[inline]
pub fn sobol_all_reversed(reversed_index: u32) -> [u32; DIMENSIONS] {
    let mut value = [0u32; DIMENSIONS];
    for (byte, table) in REVERSED_TABLES.iter().enumerate() {
        let entry = &table[((reversed_index >> (8 * byte)) & 0xff) as usize];
        for d in 0..DIMENSIONS {
            value[d] ^= entry[d];
        }
    }
    value
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reversed_tables_give_reversed_points_of_the_reversed_index() {
        for index in [0u32, 1, 7, 12345, 0xdead_beef, u32::MAX, 0x8000_0000] {
            let reversed = sobol_all_reversed(index.reverse_bits());
            for (dimension, value) in reversed.iter().enumerate() {
                assert_eq!(
                    *value,
                    sobol(index, dimension).reverse_bits(),
                    "index {index:#x}, dimension {dimension}"
                );
            }
        }
    }

    #[test]
    fn dimension_zero_is_bit_reversal() {
        for index in [0u32, 1, 2, 3, 12345, u32::MAX] {
            assert_eq!(sobol(index, 0), index.reverse_bits());
        }
    }

    #[test]
    fn dimension_one_matches_the_known_sequence() {
        // Indexed directly (not in Gray-code order).
        let expected = [0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875];
        for (index, &x) in expected.iter().enumerate() {
            assert_eq!(sobol(index as u32, 1) as f64 / 4294967296.0, x);
        }
        assert_eq!(
            DIRECTIONS[1][..4],
            [0x8000_0000, 0xC000_0000, 0xA000_0000, 0xF000_0000]
        );
    }

    #[test]
    fn initial_values_and_recurrence() {
        // x^2 + x + 1: m = 1, 3, then m3 = 2*3 ^ 4*1 ^ 1 = 3, m4 = 2*3 ^ 4*3 ^ 3 = 9.
        let m: Vec<u32> = (0..4).map(|k| DIRECTIONS[2][k] >> (31 - k)).collect();
        assert_eq!(m, [1, 3, 3, 9]);
        // x^3 + x + 1: m = 1, 3, 1, then m4 = 4*3 ^ 8*1 ^ 1 = 5.
        let m: Vec<u32> = (0..4).map(|k| DIRECTIONS[3][k] >> (31 - k)).collect();
        assert_eq!(m, [1, 3, 1, 5]);
    }

    #[test]
    fn every_dimension_is_stratified_in_one_dimension() {
        for dimension in 0..DIMENSIONS {
            for k in 0..=12 {
                let n = 1u32 << k;
                let mut seen = vec![false; n as usize];
                for index in 0..n {
                    let cell = if k == 0 {
                        0
                    } else {
                        sobol(index, dimension) >> (32 - k)
                    };
                    assert!(!seen[cell as usize], "dimension {dimension}, 2^{k}");
                    seen[cell as usize] = true;
                }
            }
        }
    }
}
