//! Tests of LeafTriangles: nearest and any hit against brute force, bit for bit.

use super::*;
use crate::geometry::triangle::intersect_vertices;
use crate::math::Vec3;
use crate::rng::Rng;

/// A bumpy grid of triangles (every inner edge and vertex shared), a
/// few random ones, and an invalid entry that must never be reported.
fn triangles(rng: &mut Rng) -> Vec<Option<[Point3; 3]>> {
    let n = 40;
    let height = |i: usize, j: usize| ((i * 7 + j * 3) % 5) as f64 * 0.01;
    let p =
        |i: usize, j: usize| Point3::new(i as f64 / n as f64, j as f64 / n as f64, height(i, j));
    let mut list = Vec::new();
    for i in 0..n {
        for j in 0..n {
            list.push(Some([p(i, j), p(i + 1, j), p(i + 1, j + 1)]));
            list.push(Some([p(i, j), p(i + 1, j + 1), p(i, j + 1)]));
        }
    }
    list.push(None);
    for _ in 0..300 {
        let a = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64() * 0.5 + 0.1);
        let e = |rng: &mut Rng| Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 0.1;
        list.push(Some([a, a + e(rng), a + e(rng)]));
    }
    list
}

#[test]
fn queries_equal_brute_force_bit_for_bit_on_shared_edges_and_vertices() {
    queries_equal_brute_force(false);
}

#[test]
fn single_precision_vertices_give_the_same_answers_bit_for_bit() {
    queries_equal_brute_force(true);
}

/// Nearest and any hit of [`triangles`] (vertices rounded to f32 when
/// `single`, which the tree then keeps in f32) against testing every
/// triangle with `geometry::triangle`.
fn queries_equal_brute_force(single: bool) {
    let mut rng = Rng::new(31, 32);
    let mut list = triangles(&mut rng);
    if single {
        for t in list.iter_mut().flatten() {
            *t = t.map(|p| p.map(|c| c as f32 as f64));
        }
    }
    let tree = LeafTriangles::build(list.len(), |i| list[i]);
    assert_eq!(tree.is_single_precision(), single);
    assert_eq!(tree.len(), list.len() - 1);
    let valid: Vec<(u32, [Point3; 3])> = list
        .iter()
        .enumerate()
        .filter_map(|(i, t)| t.map(|t| (i as u32, t)))
        .collect();
    let mut hits = 0;
    for k in 0..5000 {
        // Aim at vertices, edge points and random points of the grid.
        let (_, t) = valid[(rng.next_f64() * valid.len() as f64) as usize];
        let s = rng.next_f64();
        let target = match k % 3 {
            0 => t[1],
            1 => t[0] + (t[2] - t[0]) * s,
            _ => Point3::new(rng.next_f64(), rng.next_f64(), 0.02),
        };
        let origin = Point3::new(rng.next_f64() * 3.0 - 1.0, rng.next_f64() * 3.0 - 1.0, 1.5);
        let ray = Ray::new(origin, target - origin, 0.0);
        let t_max = if k % 4 == 0 {
            1.0 + rng.next_f64()
        } else {
            f64::INFINITY
        };
        let brute = valid
            .iter()
            .filter_map(|(i, [a, b, c])| {
                intersect_vertices(a, b, c, &ray, 0.0, t_max).map(|h| (h.0, *i))
            })
            .min_by(|x, y| x.0.total_cmp(&y.0));
        let found = tree.intersect(&ray, 0.0, t_max);
        assert_eq!(
            found.map(|h| h.t.to_bits()),
            brute.map(|b| b.0.to_bits()),
            "{ray:?}"
        );
        assert_eq!(tree.occluded(&ray, 0.0, t_max), brute.is_some());
        if let Some(hit) = found {
            hits += 1;
            let vertices = tree.vertices(hit.slot, hit.index).expect("slot holds it");
            assert_eq!(Some(vertices), list[hit.index as usize]);
            let [a, b, c] = vertices;
            let again = intersect_vertices(&a, &b, &c, &ray, 0.0, t_max).expect("hit");
            assert_eq!((again.1, again.2), (hit.b1, hit.b2));
            // Another triangle's index at that slot is looked up elsewhere.
            assert_eq!(tree.vertices(hit.slot, hit.index + 1), None);
        }
    }
    assert!(hits > 2000, "{hits} hits");
}

/// Each lane of a block answers as `intersect_edges` does, bit for bit,
/// on random, degenerate (zero area, a ray in the plane) and non-finite
/// triangles and rays.
#[test]
fn block_lanes_equal_the_scalar_test_bit_for_bit() {
    use super::block::{LANES, test};
    use crate::geometry::triangle::intersect_edges;
    let mut rng = Rng::new(41, 42);
    let special = [0.0, -0.0, 1.0, 0.5, f64::INFINITY, f64::NAN, 1e-300, 1e300];
    let value = |rng: &mut Rng| {
        if rng.next_f64() < 0.1 {
            special[(rng.next_f64() * special.len() as f64) as usize]
        } else {
            rng.next_f64() * 2.0 - 1.0
        }
    };
    let mut hits = 0;
    for k in 0..20_000 {
        let mut rows = [[0.0; LANES]; 9];
        for row in rows.iter_mut() {
            for c in row.iter_mut() {
                *c = value(&mut rng);
            }
        }
        if k % 7 == 0 {
            // Lane 1 degenerate: its third vertex on its first edge.
            for axis in 0..3 {
                rows[6 + axis][1] = (rows[axis][1] + rows[3 + axis][1]) * 0.5;
            }
        }
        let origin = Point3::new(value(&mut rng), value(&mut rng), value(&mut rng) - 2.0);
        let direction = if k % 11 == 0 {
            // In the plane z = 0 of lane 2, made flat.
            rows[2][2] = 0.0;
            rows[5][2] = 0.0;
            rows[8][2] = 0.0;
            Vec3::new(value(&mut rng), value(&mut rng), 0.0)
        } else {
            Vec3::new(value(&mut rng), value(&mut rng), 1.0 + rng.next_f64())
        };
        let ray = Ray::new(origin, direction, 0.0);
        let t_max = if k % 3 == 0 { 1.5 } else { f64::INFINITY };
        let lanes = test(&rows, &ray, 1e-9, t_max);
        for lane in 0..LANES {
            let p = |v: usize| {
                Point3::new(
                    rows[3 * v][lane],
                    rows[3 * v + 1][lane],
                    rows[3 * v + 2][lane],
                )
            };
            let scalar = intersect_edges(&p(0), &(p(1) - p(0)), &(p(2) - p(0)), &ray, 1e-9, t_max);
            assert_eq!(
                lanes.mask & (1 << lane) != 0,
                scalar.is_some(),
                "{rows:?} {ray:?}"
            );
            if let Some((t, b1, b2)) = scalar {
                hits += 1;
                assert_eq!(
                    [t, b1, b2].map(f64::to_bits),
                    [lanes.t[lane], lanes.b1[lane], lanes.b2[lane]].map(f64::to_bits)
                );
            }
        }
    }
    assert!(hits > 1000, "{hits} hits");
}

/// The tree's nearest and any hit by W-Solaris's single-precision test
/// equal that test's on every triangle, bit for bit.
#[test]
fn single_precision_queries_equal_brute_force() {
    use crate::geometry::single_precision;
    let mut rng = Rng::new(51, 52);
    let mut list = triangles(&mut rng);
    for t in list.iter_mut().flatten() {
        *t = t.map(|p| p.map(|c| c as f32 as f64));
    }
    let tree = LeafTriangles::build(list.len(), |i| list[i]);
    let valid: Vec<[Point3; 3]> = list.iter().flatten().copied().collect();
    let mut hits = 0;
    for k in 0..3000 {
        let t = valid[(rng.next_f64() * valid.len() as f64) as usize];
        let target = if k % 2 == 0 {
            t[0] + (t[1] - t[0]) * rng.next_f64()
        } else {
            Point3::new(rng.next_f64(), rng.next_f64(), 0.02)
        };
        let origin = Point3::new(rng.next_f64() * 3.0 - 1.0, rng.next_f64() * 3.0 - 1.0, 1.5);
        let ray = Ray::new(origin, (target - origin).normalize(), 0.0);
        let brute = valid
            .iter()
            .filter_map(|v| single_precision::triangle(v, &ray, 0.0, f64::INFINITY))
            .map(|h| h.0)
            .min_by(f64::total_cmp);
        let found = tree.intersect_single_precision(&ray, 0.0, f64::INFINITY);
        assert_eq!(
            found.map(|h| h.t.to_bits()),
            brute.map(f64::to_bits),
            "{ray:?}"
        );
        assert_eq!(
            tree.occluded_single_precision(&ray, 0.0, f64::INFINITY),
            brute.is_some()
        );
        hits += usize::from(found.is_some());
    }
    assert!(hits > 1500, "{hits} hits");
}
