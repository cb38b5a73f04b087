//! The wide tree's nodes: `W` children in 128 bytes (two cache lines),
//! made by `collapse` from the binary tree. Child boxes are quantised to 8 bits per
//! plane on a grid of the node: per axis an origin and a power-of-two step
//! chosen so that every plane `origin + q step` (`q` in 0..=255) is an f32
//! computed exactly; mins are rounded down and maxes up, so a child's grid
//! box always contains its f64 box and no hit is lost.

use bytemuck::{Pod, Zeroable};

use super::binary_tree::Bounds;

/// Children per node, tested as one 8-lane vector (`ray8`): on the 871k
/// dragon 7.5 node visits per closest-hit query instead of 11.1 with 4.
pub(super) const W: usize = 8;
/// Padding of a node to 128 bytes.
const UNUSED: usize = 128 - 16 - 6 * W - 5 * W;
const _: () = assert!(std::mem::size_of::<Node>() == 128);

/// Largest leaf a node entry holds (`count` is one byte); larger leaves,
/// which only a build forced at its depth limit makes, become nodes over
/// parts of them.
pub(super) const MAX_COUNT: usize = u8::MAX as usize;

/// Biased f32 exponent of an axis without a finite grid (a child box
/// reaching beyond the f32 range): its step is `+inf`, every plane is
/// `0 * inf` (NaN) or `inf`, which the slab test treats as no bound.
const UNBOUNDED: u8 = u8::MAX;

/// `W` children: their boxes on the node's grid, and where each leads.
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
#[repr(C, align(64))]
pub(super) struct Node {
    /// Lowest grid plane per axis, a multiple of the step.
    pub origin: [f32; 3],
    /// Grid step per axis, `2^(exponent - 127)` (the f32 bits of the step
    /// shifted down by 23).
    pub exponent: [u8; 3],
    /// Bit `i`: child `i` exists.
    pub valid: u8,
    /// `min x, min y, min z, max x, max y, max z` of each child in grid
    /// steps from the origin. Empty slots have `min = 255`, `max = 0`.
    pub planes: [[u8; W]; 6],
    /// Interior child: its node. Leaf: its first entry.
    pub child: [u32; W],
    /// Leaf: its number of entries (at least 1); 0 for interior children
    /// and empty slots.
    pub count: [u8; W],
    unused: [u8; UNUSED],
}

impl Node {
    const EMPTY: Node = Node {
        origin: [0.0; 3],
        exponent: [127; 3],
        valid: 0,
        planes: [
            [u8::MAX; W],
            [u8::MAX; W],
            [u8::MAX; W],
            [0; W],
            [0; W],
            [0; W],
        ],
        child: [0; W],
        count: [0; W],
        unused: [0; UNUSED],
    };

    /// The grid step of `axis`.
    #[inline(always)]
    pub fn step(&self, axis: usize) -> f32 {
        f32::from_bits((self.exponent[axis] as u32) << 23)
    }

    /// The f32 box of child `i`, planes as the traversal computes them
    /// (an unbounded axis, whose min planes are NaN, from -inf to inf).
    #[cfg(test)]
    pub fn child_box(&self, i: usize) -> ([f32; 3], [f32; 3]) {
        let plane =
            |row: usize, k: usize| self.planes[row][i] as f32 * self.step(k) + self.origin[k];
        let low = [0, 1, 2].map(|k| plane(k, k));
        (
            low.map(|p| if p.is_nan() { f32::NEG_INFINITY } else { p }),
            [0, 1, 2].map(|k| plane(3 + k, k)),
        )
    }
}

/// The largest f32 not above `v`.
pub(super) fn round_down(v: f64) -> f32 {
    let f = v as f32;
    if f as f64 > v { f.next_down() } else { f }
}

/// The smallest f32 not below `v`.
pub(super) fn round_up(v: f64) -> f32 {
    let f = v as f32;
    if (f as f64) < v { f.next_up() } else { f }
}

/// The grid of one axis over `[low, high]` (f32 values, `low <= high`):
/// the biased exponent of the step and the origin, or `None` when the
/// range is not finite.
///
/// With step `2^e`, the origin `floor(low / 2^e) 2^e` and every plane up
/// to `origin + 255 2^e` are integers times `2^e` below `2^24 2^e` in
/// magnitude, so each is an f32 and `q * step + origin` is computed
/// exactly. The step is the smallest power of two that also makes the 255
/// steps reach `high`.
pub(super) fn grid(low: f32, high: f32) -> Option<(u8, f32)> {
    if !(low.is_finite() && high.is_finite()) {
        return None;
    }
    let (low, high) = (low as f64, high as f64);
    // Smallest normal step: planes near zero stay exact (subnormal
    // multiples of 2^-126 are f32 values too).
    let mut exponent: i32 = -126;
    let fits = |e: i32| {
        let step = 2f64.powi(e);
        let origin = (low / step).floor() * step;
        let top = origin + 255.0 * step;
        let limit = (1u64 << 24) as f64 * step;
        (top >= high && origin.abs() < limit && top.abs() < limit && top <= f32::MAX as f64)
            .then_some(origin)
    };
    // Start near the answer: the step is at least (high - low) / 255 and
    // at least |value| / 2^24.
    let span = (high - low) / 255.0;
    let magnitude = low.abs().max(high.abs()) / (1u64 << 24) as f64;
    let need = span.max(magnitude);
    if need > 0.0 {
        exponent = exponent.max(need.log2().floor() as i32 - 1);
    }
    // Up to 2^119, 255 steps stay below the f32 range.
    while exponent <= 119 {
        if let Some(origin) = fits(exponent) {
            return Some(((exponent + 127) as u8, origin as f32));
        }
        exponent += 1;
    }
    None
}

/// A node with the given child boxes (at most `W`, f32 planes that contain
/// the primitives' f64 boxes) on its grid; targets
/// are set by the caller.
pub(super) fn quantise(boxes: &[Bounds]) -> Node {
    let mut node = Node::EMPTY;
    let low: [[f32; 3]; W] = std::array::from_fn(|i| boxes.get(i).map_or([0.0; 3], |b| b.min));
    let high: [[f32; 3]; W] = std::array::from_fn(|i| boxes.get(i).map_or([0.0; 3], |b| b.max));
    for k in 0..3 {
        let lowest = (0..boxes.len())
            .map(|i| low[i][k])
            .fold(f32::INFINITY, f32::min);
        let highest = (0..boxes.len())
            .map(|i| high[i][k])
            .fold(f32::NEG_INFINITY, f32::max);
        let Some((exponent, origin)) = grid(lowest, highest) else {
            node.exponent[k] = UNBOUNDED;
            node.origin[k] = 0.0;
            for i in 0..boxes.len() {
                node.planes[k][i] = 0;
                node.planes[3 + k][i] = u8::MAX;
            }
            continue;
        };
        node.exponent[k] = exponent;
        node.origin[k] = origin;
        let step = node.step(k) as f64;
        for i in 0..boxes.len() {
            // Exact: differences of f32 values in f64, divided by a power
            // of two.
            let q_low = ((low[i][k] as f64 - origin as f64) / step).floor();
            let q_high = ((high[i][k] as f64 - origin as f64) / step).ceil();
            node.planes[k][i] = q_low.clamp(0.0, 255.0) as u8;
            node.planes[3 + k][i] = q_high.clamp(0.0, 255.0) as u8;
        }
    }
    node.valid = ((1u32 << boxes.len()) - 1) as u8;
    node
}
