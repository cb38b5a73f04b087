//! Sample generators for pixel samples: independent random numbers, or an
//! Owen-scrambled Sobol' sequence (Burley 2020, "Practical Hash-based Owen
//! Scrambling", JCGT 9(4)).
//!
//! A [`Sampler`] is created for one pixel sample from (pixel index, sample
//! index, seed) and hands out one value per dimension, in order. The Sobol'
//! sampler groups dimensions by four: group `g` holds dimensions `4g..4g+3`,
//! which are the four Sobol' dimensions of [`sobol`], each Owen-scrambled with
//! its own seed, at a sample index shuffled by a nested uniform scramble seeded
//! per (pixel, group). Shuffling decorrelates the groups from each other while
//! keeping every power-of-two prefix of a pixel's samples stratified.

pub mod owen;
pub mod sobol;

#[cfg(test)]
mod tests;

use crate::rng::{Rng, mix64};
use owen::{laine_karras_permutation, laine_karras_permutation4};

/// Which sample generator a render uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SamplerKind {
    /// Independent uniform random numbers ([`Rng::for_sample`]).
    #[default]
    Independent,
    /// Shuffled, Owen-scrambled Sobol' points ([`SobolStream`]).
    Sobol,
}

impl SamplerKind {
    pub const ALL: [SamplerKind; 2] = [SamplerKind::Independent, SamplerKind::Sobol];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            SamplerKind::Independent => "independent",
            SamplerKind::Sobol => "sobol",
        }
    }

    /// Parses a command-line name, as returned by [`SamplerKind::name`].
    pub fn from_name(name: &str) -> Option<SamplerKind> {
        SamplerKind::ALL
            .into_iter()
            .find(|kind| kind.name() == name)
    }
}

/// The sample values of one pixel sample, one dimension after another.
#[derive(Clone, Debug)]
pub enum Sampler {
    Independent(Rng),
    Sobol(SobolStream),
}

impl Sampler {
    pub fn new(kind: SamplerKind, pixel_index: u64, sample_index: u64, seed: u64) -> Sampler {
        match kind {
            SamplerKind::Independent => {
                Sampler::Independent(Rng::for_sample(pixel_index, sample_index, seed))
            }
            SamplerKind::Sobol => Sampler::Sobol(SobolStream::new(pixel_index, sample_index, seed)),
        }
    }

    /// The value of the next dimension, in `[0, 1)`.
    #[inline]
    pub fn next_f64(&mut self) -> f64 {
        match self {
            Sampler::Independent(rng) => rng.next_f64(),
            Sampler::Sobol(stream) => stream.next_f64(),
        }
    }

    /// An independent sampler for a second path of the same pixel sample
    /// (told apart by `salt`): its own Sobol' sequence over the pixel's
    /// samples, or its own random stream. Deterministic, like this one.
    pub fn fork(&self, salt: u64) -> Sampler {
        match self {
            Sampler::Independent(rng) => Sampler::Independent(rng.fork(salt)),
            Sampler::Sobol(stream) => Sampler::Sobol(stream.fork(salt)),
        }
    }

    /// The values of the next two dimensions. The Sobol' sampler first skips
    /// to an even dimension, so that the pair is one of the stratified pairs
    /// (0, 1), (2, 3), (4, 5), ...
    #[inline]
    pub fn next_2d(&mut self) -> [f64; 2] {
        match self {
            Sampler::Independent(rng) => [rng.next_f64(), rng.next_f64()],
            Sampler::Sobol(stream) => stream.next_2d(),
        }
    }
}

/// Salt that keeps the Sobol' seeds apart from those of [`Rng::for_sample`].
const SOBOL_DOMAIN: u64 = 0x50B0_1D0E_5EED_0001;

/// Per-pixel seed of the Sobol' sampler.
fn pixel_seed(pixel_index: u64, seed: u64) -> u64 {
    mix64(seed ^ mix64(pixel_index ^ SOBOL_DOMAIN))
}

/// Seed of one group of four dimensions. Sample indices at or beyond 2^32 fold
/// their high half into it, so each block of 2^32 samples is scrambled anew.
fn group_seed(pixel_seed: u64, group: u32, sample_index: u64) -> u64 {
    let index_block = sample_index >> 32;
    mix64(pixel_seed ^ mix64((index_block << 32) | group as u64))
}

/// The scrambled values of the four dimensions of a group for one sample, as
/// 53-bit binary fractions.
///
/// The sample index is shuffled by a nested uniform scramble (seeded by the
/// group), the four Sobol' points of the shuffled index are each
/// Owen-scrambled with their own seed. Both scrambles work on bit-reversed
/// values, and the reversed Sobol' tables go from a reversed index to
/// reversed points, so only the index and the four results are reversed.
fn group_values(group_seed: u64, sample_index: u64) -> [u64; sobol::DIMENSIONS] {
    let reversed_shuffled =
        laine_karras_permutation((sample_index as u32).reverse_bits(), group_seed as u32);
    let reversed_points = sobol::sobol_all_reversed(reversed_shuffled);
    let seeds = dimension_seeds(group_seed);
    let scrambled = laine_karras_permutation4(reversed_points, seeds);
    std::array::from_fn(|dimension| {
        let value = scrambled[dimension].reverse_bits();
        // Owen scrambling randomises every digit; the 21 digits below the 32
        // generated ones are drawn from a hash of the scrambled prefix.
        let low = (value ^ seeds[dimension]).wrapping_mul(0x9E37_79B9) >> 11;
        ((value as u64) << 21) | low as u64
    })
}

/// The scrambling seeds of a group's four dimensions: a 32-bit hash
/// (Wellons' lowbias32) of the group seed's high half and the dimension.
fn dimension_seeds(group_seed: u64) -> [u32; sobol::DIMENSIONS] {
    let high = (group_seed >> 32) as u32;
    std::array::from_fn(|dimension| {
        let mut x = high ^ (dimension as u32 + 1).wrapping_mul(0x9E37_79B9);
        x ^= x >> 16;
        x = x.wrapping_mul(0x7feb_352d);
        x ^= x >> 15;
        x = x.wrapping_mul(0x846c_a68b);
        x ^ (x >> 16)
    })
}

/// A 53-bit binary fraction as an `f64` in `[0, 1)` (through `i64`, which
/// converts in one instruction; the bits fit).
#[inline]
fn to_unit(bits: u64) -> f64 {
    debug_assert!(bits < 1 << 53);
    (bits as i64) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// Dimension `dimension` of sample `sample_index` of pixel `pixel_index`: the
/// shuffled Owen-scrambled Sobol' value in `[0, 1)`, addressed directly.
///
/// Sample indices below 2^32 index one scrambled Sobol' sequence; beyond, the
/// index wraps modulo 2^32 and each block of 2^32 samples gets fresh scrambles.
pub fn sobol_sample(pixel_index: u64, sample_index: u64, dimension: u32, seed: u64) -> f64 {
    let pixel_seed = pixel_seed(pixel_index, seed);
    if dimension >= SOBOL_DIMENSIONS {
        return padding_value(padding_seed(pixel_seed, sample_index), dimension);
    }
    let group = dimension / sobol::DIMENSIONS as u32;
    let group_seed = group_seed(pixel_seed, group, sample_index);
    to_unit(group_values(group_seed, sample_index)[dimension as usize % sobol::DIMENSIONS])
}

/// Dimensions drawn from the scrambled Sobol' sequence; later ones (deep
/// bounces, where stratification no longer pays for its cost) are padded with
/// hashed independent values, as padded samplers do.
pub const SOBOL_DIMENSIONS: u32 = 12;

fn padding_seed(pixel_seed: u64, sample_index: u64) -> u64 {
    mix64(pixel_seed ^ mix64(sample_index ^ 0xA5A5_5A5A_0F0F_F0F0))
}

/// A hashed uniform value for a padding dimension (one multiply-xorshift).
fn padding_value(padding_seed: u64, dimension: u32) -> f64 {
    let mut z = padding_seed ^ (dimension as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 32)).wrapping_mul(0xD6E8_FEB8_6659_FD93);
    z = (z ^ (z >> 32)).wrapping_mul(0xD6E8_FEB8_6659_FD93);
    to_unit((z ^ (z >> 32)) >> 11)
}

/// The Sobol' values of one pixel sample, in dimension order; equal to
/// [`sobol_sample`] for dimensions 0, 1, 2, ... but hashing each group once.
#[derive(Clone, Debug)]
pub struct SobolStream {
    pixel_seed: u64,
    sample_index: u64,
    dimension: u32,
    /// The values of the current group of four dimensions.
    values: [u64; sobol::DIMENSIONS],
    /// Seed of the padding dimensions (from `SOBOL_DIMENSIONS` on).
    padding_seed: u64,
}

impl SobolStream {
    pub fn new(pixel_index: u64, sample_index: u64, seed: u64) -> SobolStream {
        SobolStream {
            pixel_seed: pixel_seed(pixel_index, seed),
            sample_index,
            dimension: 0,
            values: [0; sobol::DIMENSIONS],
            padding_seed: 0,
        }
    }

    /// The stream of the same sample index in another sequence (see
    /// [`Sampler::fork`]).
    pub fn fork(&self, salt: u64) -> SobolStream {
        SobolStream {
            pixel_seed: mix64(self.pixel_seed ^ mix64(salt)),
            sample_index: self.sample_index,
            dimension: 0,
            values: [0; sobol::DIMENSIONS],
            padding_seed: 0,
        }
    }

    /// The next dimension consumed by [`SobolStream::next_f64`].
    pub fn dimension(&self) -> u32 {
        self.dimension
    }

    /// The value of the next dimension, in `[0, 1)`. Inline: most calls
    /// read a value of the current group or hash a padding dimension; the
    /// work of starting a group is out of line.
    #[inline]
    pub fn next_f64(&mut self) -> f64 {
        if self.dimension >= SOBOL_DIMENSIONS {
            if self.dimension == SOBOL_DIMENSIONS {
                self.padding_seed = padding_seed(self.pixel_seed, self.sample_index);
            }
            self.dimension = self.dimension.saturating_add(1);
            return padding_value(self.padding_seed, self.dimension - 1);
        }
        let dimension_in_group = self.dimension as usize % sobol::DIMENSIONS;
        if dimension_in_group == 0 {
            self.start_group();
        }
        self.dimension = self.dimension.wrapping_add(1);
        to_unit(self.values[dimension_in_group])
    }

    /// Computes the values of the group that starts at the next dimension.
    #[inline(never)]
    fn start_group(&mut self) {
        let group = self.dimension / sobol::DIMENSIONS as u32;
        let group_seed = group_seed(self.pixel_seed, group, self.sample_index);
        self.values = group_values(group_seed, self.sample_index);
    }

    /// The next two dimensions, starting from an even one. A Sobol' pair
    /// lies within one group of four (pairs start at even dimensions), so
    /// both values are read at once.
    #[inline]
    pub fn next_2d(&mut self) -> [f64; 2] {
        if self.dimension < SOBOL_DIMENSIONS {
            // Skip to an even dimension.
            let first = (self.dimension + 1) & !1;
            self.dimension = first;
            if first < SOBOL_DIMENSIONS {
                let in_group = first as usize % sobol::DIMENSIONS;
                if in_group == 0 {
                    self.start_group();
                }
                self.dimension = first + 2;
                return [
                    to_unit(self.values[in_group]),
                    to_unit(self.values[in_group + 1]),
                ];
            }
        }
        [self.next_f64(), self.next_f64()]
    }
}
