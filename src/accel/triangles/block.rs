//! Blocks of four triangles, vertices stored row by row (one column per
//! lane) in f32 or f64, and the four Möller–Trumbore tests of a block run
//! side by side in f64.

use bytemuck::{Pod, Zeroable};

use crate::math::{Point3, Ray};

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

/// What the queries read of a block.
pub(super) trait Block: Pod {
    /// The vertex rows in f64.
    fn coords(&self) -> [[f64; LANES]; 9];
    fn original(&self) -> &[u32; LANES];
}

impl Block for Block32 {
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
pub(super) fn rows<C: Copy + Default>(
    lanes: &Lanes,
    convert: impl Fn(f64) -> C,
) -> [[C; LANES]; 9] {
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
pub(super) fn originals(lanes: &Lanes) -> [u32; LANES] {
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

/// One f64 per lane.
type Lane = [f64; LANES];

#[inline(always)]
fn lanes(f: impl FnMut(usize) -> f64) -> Lane {
    std::array::from_fn(f)
}

#[inline(always)]
fn sub(a: Lane, b: Lane) -> Lane {
    lanes(|i| a[i] - b[i])
}

/// nalgebra's cross product, lane by lane.
#[inline(always)]
fn cross(a: [Lane; 3], b: [Lane; 3]) -> [Lane; 3] {
    [
        lanes(|i| a[1][i] * b[2][i] - a[2][i] * b[1][i]),
        lanes(|i| a[2][i] * b[0][i] - a[0][i] * b[2][i]),
        lanes(|i| a[0][i] * b[1][i] - a[1][i] * b[0][i]),
    ]
}

/// nalgebra's dot product (`(x + y) + z`), lane by lane.
#[inline(always)]
fn dot(a: [Lane; 3], b: [Lane; 3]) -> Lane {
    lanes(|i| a[0][i] * b[0][i] + a[1][i] * b[1][i] + a[2][i] * b[2][i])
}

/// `geometry::triangle::intersect_edges` on each lane, without its early
/// returns: every operation and comparison is the same, so each lane's
/// answer is too.
#[inline(always)]
pub(super) fn test(rows: &[[f64; LANES]; 9], ray: &Ray, t_min: f64, t_max: f64) -> LaneHits {
    let o = [ray.origin.x, ray.origin.y, ray.origin.z].map(|c| [c; LANES]);
    let d = [ray.direction.x, ray.direction.y, ray.direction.z].map(|c| [c; LANES]);
    let p0 = [rows[0], rows[1], rows[2]];
    let edge1 = [
        sub(rows[3], p0[0]),
        sub(rows[4], p0[1]),
        sub(rows[5], p0[2]),
    ];
    let edge2 = [
        sub(rows[6], p0[0]),
        sub(rows[7], p0[1]),
        sub(rows[8], p0[2]),
    ];
    let p = cross(d, edge2);
    let determinant = dot(edge1, p);
    let inverse = lanes(|i| 1.0 / determinant[i]);
    let s = [sub(o[0], p0[0]), sub(o[1], p0[1]), sub(o[2], p0[2])];
    let b1 = lanes(|i| dot(s, p)[i] * inverse[i]);
    let q = cross(s, edge1);
    let b2 = lanes(|i| dot(d, q)[i] * inverse[i]);
    let t = lanes(|i| dot(edge2, q)[i] * inverse[i]);
    // The tests of `intersect_edges` but two that the others imply (a zero
    // determinant makes `b1` infinite or NaN; `b2 >= 0` and `b1 + b2 <= 1`
    // give `b1 <= 1`, rounding being monotonic), each a whole lane array
    // so that they compile to vector compares, combined without branches.
    let finite = lanes(|i| determinant[i] * 0.0);
    let sum = lanes(|i| b1[i] + b2[i]);
    let tests: [[bool; LANES]; 6] = [
        std::array::from_fn(|i| finite[i] == 0.0),
        std::array::from_fn(|i| b1[i] >= 0.0),
        std::array::from_fn(|i| b2[i] >= 0.0),
        std::array::from_fn(|i| sum[i] <= 1.0),
        std::array::from_fn(|i| t[i] > t_min),
        std::array::from_fn(|i| t[i] < t_max),
    ];
    let hit: [bool; LANES] = std::array::from_fn(|i| tests.iter().all(|test| test[i]));
    let mask = (0..LANES).fold(0, |mask, i| mask | (hit[i] as u32) << i);
    LaneHits { mask, t, b1, b2 }
}
