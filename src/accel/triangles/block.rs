//! Blocks of four triangles, vertices stored row by row (one column per
//! lane) in f32 or f64, and the four Möller–Trumbore tests of a block run
//! side by side in f64.

use bytemuck::{Pod, Zeroable};

use crate::geometry::single_precision;
use crate::math::{Point3, Ray};
use wide::f64x4;

/// Triangles per block, tested side by side.
pub(super) const LANES: usize = 4;

/// Four triangles with single-precision vertices: rows `p0.x, p0.y, p0.z,
/// p1.x, ... p2.z`, one column per lane, and each lane's index in the
/// caller's list (read with the vertices when it is hit).
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C)]
pub(super) struct Block32 {
    pub coords: [[f32; LANES]; 9],
    pub original: [u32; LANES],
}

/// [`Block32`] with double-precision vertices.
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C)]
pub(super) struct Block64 {
    pub coords: [[f64; LANES]; 9],
    pub original: [u32; LANES],
}

/// How a block is made from its lanes, and what the queries read of it.
pub(super) trait Block: Pod + Send {
    /// The block of `lanes` (unused lanes zero, index `u32::MAX`).
    fn from_lanes(lanes: &Lanes) -> Self;
    /// The vertex rows in f64.
    fn coords(&self) -> [[f64; LANES]; 9];
    fn original(&self) -> &[u32; LANES];
}

impl Block for Block32 {
    fn from_lanes(lanes: &Lanes) -> Self {
        Block32 {
            coords: rows(lanes, |c| c as f32),
            original: originals(lanes),
        }
    }
    #[inline(always)]
    fn coords(&self) -> [[f64; LANES]; 9] {
        self.coords.map(|row| row.map(f64::from))
    }
    #[inline(always)]
    fn original(&self) -> &[u32; LANES] {
        &self.original
    }
}

impl Block for Block64 {
    fn from_lanes(lanes: &Lanes) -> Self {
        Block64 {
            coords: rows(lanes, |c| c),
            original: originals(lanes),
        }
    }
    #[inline(always)]
    fn coords(&self) -> [[f64; LANES]; 9] {
        self.coords
    }
    #[inline(always)]
    fn original(&self) -> &[u32; LANES] {
        &self.original
    }
}

/// The lanes of a block: the caller's index and vertices of each, `None`
/// for an unused lane.
pub(super) type Lanes = [Option<(u32, [Point3; 3])>; LANES];

/// Rows of `lanes`, zero in unused lanes, in the precision `convert` gives.
fn rows<C: Copy + Default>(lanes: &Lanes, convert: impl Fn(f64) -> C) -> [[C; LANES]; 9] {
    let mut rows = [[C::default(); LANES]; 9];
    for (lane, entry) in lanes.iter().enumerate() {
        if let Some((_, vertices)) = entry {
            for (v, p) in vertices.iter().enumerate() {
                for k in 0..3 {
                    rows[3 * v + k][lane] = convert(p[k]);
                }
            }
        }
    }
    rows
}

/// The caller's index of each lane, `u32::MAX` for unused ones.
fn originals(lanes: &Lanes) -> [u32; LANES] {
    lanes.map(|entry| entry.map_or(u32::MAX, |(index, _)| index))
}

/// The four tests of a block: which lanes are hit with `t_min < t < t_max`,
/// and each lane's distance and barycentrics.
pub(super) struct LaneHits {
    pub mask: u32,
    pub t: [f64; LANES],
    pub b1: [f64; LANES],
    pub b2: [f64; LANES],
}

/// One f64 per lane (`wide`'s 4-lane vector: AVX here; each operation
/// rounds as the scalar one does, and none is fused).
type Lane = f64x4;

/// nalgebra's cross product, lane by lane.
#[inline(always)]
fn cross(a: [Lane; 3], b: [Lane; 3]) -> [Lane; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// nalgebra's dot product (`(x + y) + z`), lane by lane.
#[inline(always)]
fn dot(a: [Lane; 3], b: [Lane; 3]) -> Lane {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `geometry::triangle::intersect_edges` on each lane, without its early
/// returns: every operation and comparison is the same, so each lane's
/// answer is too.
#[inline(always)]
pub(super) fn test(rows: &[[f64; LANES]; 9], ray: &Ray, t_min: f64, t_max: f64) -> LaneHits {
    let row = |k: usize| f64x4::new(rows[k]);
    let o = [ray.origin.x, ray.origin.y, ray.origin.z].map(f64x4::splat);
    let d = [ray.direction.x, ray.direction.y, ray.direction.z].map(f64x4::splat);
    let p0 = [row(0), row(1), row(2)];
    let edge1 = [row(3) - p0[0], row(4) - p0[1], row(5) - p0[2]];
    let edge2 = [row(6) - p0[0], row(7) - p0[1], row(8) - p0[2]];
    let p = cross(d, edge2);
    let determinant = dot(edge1, p);
    let inverse = f64x4::splat(1.0) / determinant;
    let s = [o[0] - p0[0], o[1] - p0[1], o[2] - p0[2]];
    let b1 = dot(s, p) * inverse;
    let q = cross(s, edge1);
    let b2 = dot(d, q) * inverse;
    let t = dot(edge2, q) * inverse;
    // The tests of `intersect_edges` but two that the others imply (a zero
    // determinant makes `b1` infinite or NaN; `b2 >= 0` and `b1 + b2 <= 1`
    // give `b1 <= 1`, rounding being monotonic); `d * 0 == 0` is
    // finiteness.
    let zero = f64x4::splat(0.0);
    let hit = (determinant * zero).simd_eq(zero)
        & b1.simd_ge(zero)
        & b2.simd_ge(zero)
        & (b1 + b2).simd_le(f64x4::splat(1.0))
        & t.simd_gt(f64x4::splat(t_min))
        & t.simd_lt(f64x4::splat(t_max));
    LaneHits {
        mask: hit.to_bitmask(),
        t: t.to_array(),
        b1: b1.to_array(),
        b2: b2.to_array(),
    }
}

/// [`test`] by W-Solaris's test in single precision
/// (`geometry::single_precision::triangle`), lane by lane; unused lanes
/// (zero triangles) are never hit.
#[inline(always)]
pub(super) fn test_single_precision(
    rows: &[[f64; LANES]; 9],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> LaneHits {
    let answers: [Option<(f64, f64, f64)>; LANES] = std::array::from_fn(|lane| {
        let vertices: [Point3; 3] = std::array::from_fn(|v| {
            Point3::new(
                rows[3 * v][lane],
                rows[3 * v + 1][lane],
                rows[3 * v + 2][lane],
            )
        });
        single_precision::triangle(&vertices, ray, t_min, t_max)
    });
    let part = |k: usize| answers.map(|a| a.map_or(0.0, |h| [h.0, h.1, h.2][k]));
    LaneHits {
        mask: answers
            .iter()
            .enumerate()
            .fold(0, |mask, (lane, a)| mask | (u32::from(a.is_some()) << lane)),
        t: part(0),
        b1: part(1),
        b2: part(2),
    }
}
