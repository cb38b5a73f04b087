//! SAH bins: the box bounds and count of the items whose centroids fall
//! in each of [`BIN_COUNT`] slices per axis, filled in parallel chunks for
//! large nodes (the merge is exact, so the bins do not depend on the
//! chunking).

use super::binary_tree::{Bounds, Item};
use wide::f32x4;

/// Number of SAH bins per axis.
pub(super) const BIN_COUNT: usize = 16;
/// Nodes over more items than this are binned in parallel chunks of this size.
const PARALLEL_BINNING: usize = 32 * 1024;

/// Box bounds and count of the items of one bin, per axis.
#[derive(Clone, Copy)]
pub(super) struct Bins {
    boxes: [[Box4; BIN_COUNT]; 3],
    pub counts: [[u32; BIN_COUNT]; 3],
}

impl Bins {
    pub fn new() -> Bins {
        Bins {
            boxes: [[Box4::EMPTY; BIN_COUNT]; 3],
            counts: [[0; BIN_COUNT]; 3],
        }
    }

    /// The boxes of the bins along `axis`.
    pub fn bounds(&self, axis: usize) -> [Bounds; BIN_COUNT] {
        self.boxes[axis].map(|b| b.bounds())
    }

    fn merge(mut self, other: Bins) -> Bins {
        for axis in 0..3 {
            for b in 0..BIN_COUNT {
                self.boxes[axis][b] = self.boxes[axis][b].union(&other.boxes[axis][b]);
                self.counts[axis][b] += other.counts[axis][b];
            }
        }
        self
    }
}

/// A bin's box as two 4-lane vectors (the fourth lane repeats the first),
/// so that adding an item is one vector min and max, and the next item's
/// update of the same bin reads whole stored vectors (three-lane boxes
/// are stored with masked stores, which do not forward to a later load).
#[derive(Clone, Copy)]
struct Box4 {
    min: f32x4,
    max: f32x4,
}

impl Box4 {
    const EMPTY: Box4 = Box4 {
        min: f32x4::INFINITY,
        max: f32x4::NEG_INFINITY,
    };

    #[inline(always)]
    fn new(b: &Bounds) -> Box4 {
        Box4 {
            min: f32x4::new([b.min[0], b.min[1], b.min[2], b.min[0]]),
            max: f32x4::new([b.max[0], b.max[1], b.max[2], b.max[0]]),
        }
    }

    /// Lane by lane as [`Bounds::union`] (`a < b ? a : b`, and the same
    /// for the max: `fast_min` and `fast_max` are exactly that).
    #[inline(always)]
    fn union(&self, other: &Box4) -> Box4 {
        Box4 {
            min: self.min.fast_min(other.min),
            max: self.max.fast_max(other.max),
        }
    }

    fn bounds(&self) -> Bounds {
        let (min, max) = (self.min.to_array(), self.max.to_array());
        Bounds {
            min: [min[0], min[1], min[2]],
            max: [max[0], max[1], max[2]],
        }
    }
}

/// Maps centroids to bins along each axis (scale 0 for a flat axis, which
/// puts everything in bin 0). Nodes of few items use as many bins as items.
pub(super) struct Binning {
    min: [f32; 3],
    pub scale: [f32; 3],
    pub bins: usize,
    /// `bins - 1`, as a float.
    last: f32,
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
            last: (bins - 1) as f32,
        }
    }

    /// The bin of centroid coordinate `c`: the slice it falls in, the
    /// last for the far end (and beyond), the first for NaN.
    #[inline]
    pub fn bin(&self, axis: usize, c: f32) -> usize {
        // Clamped as a float first (`max` takes 0 for NaN), so that the
        // conversion needs no saturation of its own.
        let position = ((c - self.min[axis]) * self.scale[axis])
            .max(0.0)
            .min(self.last);
        position as u8 as usize
    }

    fn fill(&self, items: &[Item], bins: &mut Bins) {
        for item in items {
            let c = item.centroid();
            let item_box = Box4::new(&item.bounds);
            for (axis, &c) in c.iter().enumerate() {
                let b = self.bin(axis, c);
                bins.boxes[axis][b] = bins.boxes[axis][b].union(&item_box);
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
