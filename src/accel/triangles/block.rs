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
    // Lane masks (all ones where true) combined with `&`, not `&&`: no
    // branches, all lanes at once.
    let all = |c: bool| 0u64.wrapping_sub(c as u64);
    let hit: [u64; LANES] = std::array::from_fn(|i| {
        all(determinant[i] != 0.0)
            & all(determinant[i].abs() < f64::INFINITY)
            & all(b1[i] >= 0.0)
            & all(b1[i] <= 1.0)
            & all(b2[i] >= 0.0)
            & all(b1[i] + b2[i] <= 1.0)
            & all(t[i] > t_min)
            & all(t[i] < t_max)
    });
    let mask = (0..LANES).fold(0, |mask, i| mask | ((hit[i] >> 63) as u32) << i);
    LaneHits { mask, t, b1, b2 }
}
