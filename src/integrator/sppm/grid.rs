//! The hashed grid of one pass's visible points: cells of the largest
//! gathering diameter, each point listed in the (at most eight) cells its
//! sphere overlaps, the cells hashed into a table of about one slot per
//! point. Built by counting sort, one point after another, so the lists
//! are the same for any thread count; queried by many threads at once.

use crate::math::Point3;

/// One visible point to list: its index, position and gathering radius.
#[derive(Clone, Copy, Debug)]
pub struct GridPoint {
    pub index: u32,
    pub point: Point3,
    pub radius: f64,
}

/// Visible points by hashed cell (see the module documentation).
#[derive(Debug, Default)]
pub struct PointGrid {
    /// Side of a cell.
    cell: f64,
    /// Slots minus one (a power of two minus one).
    mask: usize,
    /// Per slot, where its list starts in `entries` (`slots + 1` values).
    starts: Vec<u32>,
    /// The lists of all slots, one after another: point indices.
    entries: Vec<u32>,
}

impl PointGrid {
    /// Lists `points` (keeping the buffers of the previous pass).
    pub fn rebuild(&mut self, points: &[GridPoint]) {
        self.entries.clear();
        self.starts.clear();
        let largest = points.iter().map(|p| p.radius).fold(0.0, f64::max);
        if points.is_empty() || !(largest > 0.0 && largest.is_finite()) {
            self.mask = 0;
            self.starts.extend([0, 0]);
            return;
        }
        self.cell = 2.0 * largest;
        let slots = points.len().next_power_of_two();
        self.mask = slots - 1;
        self.starts.resize(slots + 1, 0);
        // Count, then place: each point once per distinct slot of its cells.
        for point in points {
            let slots = self.slots_of(point);
            for &slot in &slots.list[..slots.len] {
                self.starts[slot + 1] += 1;
            }
        }
        for slot in 0..slots {
            self.starts[slot + 1] += self.starts[slot];
        }
        self.entries.resize(self.starts[slots] as usize, 0);
        let mut next: Vec<u32> = self.starts[..slots].to_vec();
        for point in points {
            // The slots of a point are computed again, as when counting.
            let slots = self.slots_of(point);
            for &slot in &slots.list[..slots.len] {
                self.entries[next[slot] as usize] = point.index;
                next[slot] += 1;
            }
        }
    }

    /// Calls `visit` with every listed point whose cell is that of `at`
    /// (and the others that share its slot): the candidates within reach
    /// of a photon at `at`.
    #[inline]
    pub fn candidates(&self, at: &Point3, mut visit: impl FnMut(u32)) {
        if self.entries.is_empty() {
            return;
        }
        let slot = self.slot(self.cell_of(at));
        let (start, end) = (self.starts[slot] as usize, self.starts[slot + 1] as usize);
        for &index in &self.entries[start..end] {
            visit(index);
        }
    }

    /// The distinct slots of the cells `point`'s sphere overlaps.
    fn slots_of(&self, point: &GridPoint) -> Slots {
        let low = self.cell_of(&point.point.add_scalar(-point.radius));
        let high = self.cell_of(&point.point.add_scalar(point.radius));
        let mut slots = Slots {
            list: [0; 8],
            len: 0,
        };
        for x in low[0]..=high[0].min(low[0] + 1) {
            for y in low[1]..=high[1].min(low[1] + 1) {
                for z in low[2]..=high[2].min(low[2] + 1) {
                    let slot = self.slot([x, y, z]);
                    if !slots.list[..slots.len].contains(&slot) {
                        slots.list[slots.len] = slot;
                        slots.len += 1;
                    }
                }
            }
        }
        slots
    }

    #[inline]
    fn cell_of(&self, p: &Point3) -> [i64; 3] {
        // Saturating casts: points far outside any sensible grid share cells.
        [
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
            (p.z / self.cell).floor() as i64,
        ]
    }

    #[inline]
    fn slot(&self, cell: [i64; 3]) -> usize {
        let hash = (cell[0].wrapping_mul(73_856_093) as u64)
            ^ (cell[1].wrapping_mul(19_349_663) as u64)
            ^ (cell[2].wrapping_mul(83_492_791) as u64);
        (crate::rng::mix64(hash) as usize) & self.mask
    }
}

/// Up to eight distinct slots.
struct Slots {
    list: [usize; 8],
    len: usize,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    #[test]
    fn every_point_within_reach_is_a_candidate_once() {
        let mut rng = Rng::new(3, 4);
        let points: Vec<GridPoint> = (0..500)
            .map(|i| GridPoint {
                index: i,
                point: Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64() * 0.3) * 10.0,
                radius: 0.2 + 0.6 * rng.next_f64(),
            })
            .collect();
        let mut grid = PointGrid::default();
        grid.rebuild(&points);
        for _ in 0..2000 {
            let at = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64() * 0.3) * 10.0;
            let mut found = Vec::new();
            grid.candidates(&at, |i| found.push(i));
            let mut sorted = found.clone();
            sorted.sort_unstable();
            sorted.dedup();
            assert_eq!(sorted.len(), found.len(), "a point listed twice in a slot");
            for p in &points {
                if (p.point - at).norm() <= p.radius {
                    assert!(found.contains(&p.index), "point {} missed", p.index);
                }
            }
        }
    }

    #[test]
    fn an_empty_grid_has_no_candidates() {
        let mut grid = PointGrid::default();
        grid.rebuild(&[]);
        grid.candidates(&Point3::zeros(), |_| panic!("no points"));
    }
}
