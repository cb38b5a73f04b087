//! SAH bins: the box bounds and count of the items whose centroids fall
//! in each of [`BIN_COUNT`] slices per axis, filled in parallel chunks for
//! large nodes (the merge is exact, so the bins do not depend on the
//! chunking).

use super::build::{Bounds, Item};

/// Number of SAH bins per axis.
pub(super) const BIN_COUNT: usize = 16;
/// Nodes over more items than this are binned in parallel chunks of this size.
const PARALLEL_BINNING: usize = 32 * 1024;

/// Box bounds and count of the items of one bin, per axis.
#[derive(Clone, Copy)]
pub(super) struct Bins {
    pub bounds: [[Bounds; BIN_COUNT]; 3],
    pub counts: [[u32; BIN_COUNT]; 3],
}

impl Bins {
    pub fn new() -> Bins {
        Bins {
            bounds: [[Bounds::EMPTY; BIN_COUNT]; 3],
            counts: [[0; BIN_COUNT]; 3],
        }
    }

    fn merge(mut self, other: Bins) -> Bins {
        for axis in 0..3 {
            for b in 0..BIN_COUNT {
                self.bounds[axis][b] = self.bounds[axis][b].union(&other.bounds[axis][b]);
                self.counts[axis][b] += other.counts[axis][b];
            }
        }
        self
    }
}

/// Maps centroids to bins along each axis (scale 0 for a flat axis, which
/// puts everything in bin 0). Nodes of few items use as many bins as items.
pub(super) struct Binning {
    min: [f32; 3],
    pub scale: [f32; 3],
    pub bins: usize,
}

impl Binning {
    pub fn new(centroids: &Bounds, count: usize) -> Binning {
        let bins = count.clamp(2, BIN_COUNT);
        let scale = [0, 1, 2].map(|axis| {
            let extent = centroids.max[axis] - centroids.min[axis];
            if extent > 0.0 && extent.is_finite() {
                bins as f32 / extent
            } else {
                0.0
            }
        });
        Binning {
            min: centroids.min,
            scale,
            bins,
        }
    }

    #[inline]
    pub fn bin(&self, axis: usize, c: f32) -> usize {
        (((c - self.min[axis]) * self.scale[axis]) as usize).min(self.bins - 1)
    }

    fn fill(&self, items: &[Item], bins: &mut Bins) {
        for item in items {
            let c = item.centroid();
            for (axis, &c) in c.iter().enumerate() {
                let b = self.bin(axis, c);
                bins.bounds[axis][b] = bins.bounds[axis][b].union(&item.bounds);
                bins.counts[axis][b] += 1;
            }
        }
    }

    /// [`Binning::fill`] over chunks in parallel for large nodes; the merge
    /// is exact, so the bins do not depend on the chunking.
    pub fn fill_parallel(&self, items: &[Item], bins: &mut Bins) {
        use rayon::prelude::*;
        if items.len() <= PARALLEL_BINNING {
            self.fill(items, bins);
            return;
        }
        *bins = items
            .par_chunks(PARALLEL_BINNING)
            .map(|chunk| {
                let mut bins = Bins::new();
                self.fill(chunk, &mut bins);
                bins
            })
            .reduce(Bins::new, Bins::merge);
    }
}
