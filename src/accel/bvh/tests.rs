//! Tests of the BVH: traversal against brute force, degenerate boxes, leaf order.

use super::*;
use crate::math::{Point3, Vec3, inverse_direction};
use crate::rng::Rng;

fn random_boxes(rng: &mut Rng, count: usize) -> Vec<Aabb> {
    (0..count)
        .map(|_| {
            let c = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 10.0;
            let e = Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 0.5;
            Aabb {
                min: c - e,
                max: c + e,
            }
        })
        .collect()
}

/// Boxes as primitives: the "hit" is the entry distance.
fn nearest(bvh: &Bvh, boxes: &[Aabb], ray: &Ray) -> Option<f64> {
    let inverse = inverse_direction(&ray.direction);
    let t = bvh.traverse(ray, 0.0, f64::INFINITY, |i, t_max| {
        boxes[i].hit_distance(&ray.origin, &inverse, 0.0, t_max)
    });
    t.is_finite().then_some(t)
}

/// The nearest box hit by testing every box.
fn brute_nearest(boxes: &[Aabb], ray: &Ray) -> Option<f64> {
    let inverse = inverse_direction(&ray.direction);
    boxes
        .iter()
        .filter_map(|b| b.hit_distance(&ray.origin, &inverse, 0.0, f64::INFINITY))
        .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))))
}

#[test]
fn traversal_equals_brute_force_on_random_boxes() {
    let mut rng = Rng::new(1, 2);
    for count in [0, 1, 2, 7, 300] {
        let boxes = random_boxes(&mut rng, count);
        let bvh = Bvh::build(&boxes);
        assert_eq!(bvh.len(), count);
        for _ in 0..500 {
            let origin = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 14.0
                - Vec3::repeat(2.0);
            let mut direction =
                Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) - Vec3::repeat(0.5);
            // Some axis-parallel rays (zero components: infinite inverse).
            if rng.next_f64() < 0.3 {
                direction.x = 0.0;
                direction.z = 0.0;
            }
            let ray = Ray::new(origin, direction, 0.0);
            let inverse = inverse_direction(&direction);
            let brute = brute_nearest(&boxes, &ray);
            assert_eq!(nearest(&bvh, &boxes, &ray), brute);
            let any = bvh.any(&ray, 0.0, f64::INFINITY, |i| {
                boxes[i]
                    .hit_distance(&origin, &inverse, 0.0, f64::INFINITY)
                    .is_some()
            });
            assert_eq!(any, brute.is_some());
        }
    }
}

#[test]
fn leaf_order_reports_slots_of_the_original_order_in_groups() {
    let mut rng = Rng::new(8, 9);
    let boxes = random_boxes(&mut rng, 200);
    let bvh = Bvh::build(&boxes);
    for width in [1, 4] {
        let (ordered, slots) = Bvh::build_in_leaf_order(&boxes, width, 1.0);
        assert_eq!(slots.len() % width, 0);
        let mut seen: Vec<u32> = slots.iter().copied().filter(|&i| i != u32::MAX).collect();
        seen.sort_unstable();
        assert_eq!(seen, (0..200).collect::<Vec<u32>>());
        // Padding slots hold an empty box, which nothing enters.
        let permuted: Vec<Aabb> = slots
            .iter()
            .map(|&i| boxes.get(i as usize).copied().unwrap_or_else(Aabb::empty))
            .collect();
        let mut starts = Vec::new();
        for _ in 0..300 {
            let origin = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 12.0;
            let direction =
                Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) - Vec3::repeat(0.5);
            let ray = Ray::new(origin, direction, 0.0);
            assert_eq!(
                nearest(&bvh, &boxes, &ray),
                nearest(&ordered, &permuted, &ray)
            );
            // Every leaf the traversal tests was prefetched when its
            // parent's test hit it.
            let prefetched = std::cell::RefCell::new(Vec::new());
            let visited = starts.len();
            ordered.traverse_leaves(
                &ray,
                0.0,
                f64::INFINITY,
                |first, count, _| {
                    starts.push((first, count));
                    None
                },
                |first| prefetched.borrow_mut().push(first),
            );
            let prefetched = prefetched.into_inner();
            assert!(
                starts[visited..]
                    .iter()
                    .all(|(first, _)| prefetched.contains(first))
            );
        }
        assert!(
            starts
                .iter()
                .all(|&(first, count)| first % width == 0 && (1..=4).contains(&count))
        );
    }
}

#[test]
fn identical_boxes_and_invalid_boxes() {
    let unit = Aabb {
        min: Point3::zeros(),
        max: Point3::repeat(1.0),
    };
    let mut boxes = vec![unit; 1000];
    boxes.push(Aabb::empty());
    boxes.push(Aabb {
        min: Point3::repeat(f64::NAN),
        max: Point3::repeat(1.0),
    });
    let bvh = Bvh::build(&boxes);
    assert_eq!(bvh.len(), 1000);
    let ray = Ray::new(Point3::new(0.5, 0.5, -1.0), Vec3::z(), 0.0);
    let mut visited = 0;
    bvh.traverse(&ray, 0.0, f64::INFINITY, |_, _| {
        visited += 1;
        None
    });
    assert_eq!(visited, 1000);
}

/// Random small triangles in a unit cube, a third of them sharing edges with
/// their predecessor, and some in axis-aligned planes (flat boxes).
fn random_triangles(rng: &mut Rng, count: usize) -> Vec<[Point3; 3]> {
    let point = |rng: &mut Rng| Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64());
    let mut triangles: Vec<[Point3; 3]> = Vec::new();
    for i in 0..count {
        let a = point(rng);
        let mut t = [
            a,
            a + (point(rng) - Vec3::repeat(0.5)) * 0.2,
            a + (point(rng) - Vec3::repeat(0.5)) * 0.2,
        ];
        if i % 3 == 1 {
            let [p, q, _] = triangles[i - 1];
            t = [q, p, t[2]];
        }
        if i % 5 == 0 {
            let z = t[0].z;
            t.iter_mut().for_each(|p| p.z = z);
        }
        triangles.push(t);
    }
    triangles
}

/// Rays towards random points, triangle vertices and edge points (grazing
/// edges and the faces of flat boxes), some axis-parallel.
fn random_ray(rng: &mut Rng, triangles: &[[Point3; 3]]) -> Ray {
    let origin =
        Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 3.0 - Vec3::repeat(1.0);
    let t = triangles[(rng.next_f64() * triangles.len() as f64) as usize];
    let s = rng.next_f64();
    let target = match (rng.next_f64() * 4.0) as usize {
        0 => t[0],
        1 => t[0] + (t[1] - t[0]) * s,
        2 => Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()),
        _ => (t[0] + t[1] + t[2]) / 3.0,
    };
    let mut origin = origin;
    if rng.next_f64() < 0.2 {
        // Axis-parallel, in the plane of a flat triangle's box face.
        origin = Point3::new(target.x, target.y, -1.0);
        if rng.next_f64() < 0.5 {
            origin = Point3::new(-1.0, target.y, t[0].z);
        }
    }
    Ray::new(origin, target - origin, 0.0)
}

#[test]
fn wide_traversal_finds_exactly_the_brute_force_nearest_triangle() {
    use crate::geometry::triangle::intersect_vertices;
    let mut rng = Rng::new(21, 22);
    for count in [1, 5, 17, 2000] {
        let triangles = random_triangles(&mut rng, count);
        let boxes: Vec<Aabb> = triangles
            .iter()
            .map(|t| t.iter().fold(Aabb::empty(), |b, p| b.include_point(*p)))
            .collect();
        let bvh = Bvh::build(&boxes);
        let mut hits = 0;
        for _ in 0..4000 {
            let ray = random_ray(&mut rng, &triangles);
            let t_max = if rng.next_f64() < 0.5 {
                f64::INFINITY
            } else {
                2.0 * rng.next_f64()
            };
            let test = |i: usize, t_max: f64| {
                let [a, b, c] = &triangles[i];
                intersect_vertices(a, b, c, &ray, 0.0, t_max).map(|h| h.0)
            };
            let brute = (0..count)
                .filter_map(|i| test(i, t_max))
                .fold(f64::INFINITY, f64::min);
            let found = bvh.traverse(&ray, 0.0, t_max, &test);
            let expected = if brute.is_finite() { brute } else { t_max };
            assert_eq!(found.to_bits(), expected.to_bits(), "{ray:?}");
            let any = bvh.any(&ray, 0.0, t_max, |i| test(i, t_max).is_some());
            assert_eq!(any, brute.is_finite());
            hits += brute.is_finite() as usize;
        }
        assert!(hits > 500, "{hits} hits");
    }
}

#[test]
fn the_tree_is_the_same_for_any_thread_count() {
    let mut rng = Rng::new(5, 6);
    // Large enough for parallel subtrees and parallel binning.
    let boxes = random_boxes(&mut rng, 40_000);
    let build = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        pool.install(|| Bvh::build(&boxes))
    };
    let (one, three) = (build(1), build(3));
    assert_eq!(one.indices, three.indices);
    assert_eq!(one.nodes.len(), three.nodes.len());
    for (a, b) in one.nodes.iter().zip(three.nodes.iter()) {
        assert_eq!(a, b);
    }
}

#[test]
fn the_parallel_collapse_equals_one_depth_first_pass() {
    let mut rng = Rng::new(7, 8);
    let boxes = random_boxes(&mut rng, 20_000);
    // A whole tree; leaves forced at depth 3 and at the root (too large
    // for a node entry: nodes over runs of them).
    for max_depth in [MAX_DEPTH, 3, 0] {
        let items = boxes
            .iter()
            .enumerate()
            .map(|(i, b)| binary_tree::Item {
                bounds: Bounds::from_aabb(b),
                index: i as u32,
            })
            .collect();
        let settings = Settings {
            leaves: SINGLE,
            max_depth,
        };
        let binary = binary_tree::build(items, settings).nodes;
        let (parallel, depth) = collapse::collapse(&binary);
        let (sequential, sequential_depth) = collapse::collapse_sequentially(&binary);
        // Deep enough that subtrees below the root's children exist.
        let least = if max_depth == MAX_DEPTH { 3 } else { 2 };
        assert!(depth >= least, "{max_depth}: {depth}");
        assert_eq!(depth, sequential_depth);
        assert_eq!(parallel, sequential);
    }
}

#[test]
fn f32_boxes_contain_their_f64_boxes() {
    for v in [0.1, -0.1, 1e-30, 3.0e38, 1.0, -7.3e5, 16_777_217.0] {
        assert!(wide::round_down(v) as f64 <= v && v <= wide::round_up(v) as f64);
    }
}

/// Every item's f64 box inside the f32 box of each child slot above it,
/// from the root down.
fn assert_contained(bvh: &Bvh, boxes: &[Aabb], node: usize, above: &mut Vec<([f32; 3], [f32; 3])>) {
    let n = &bvh.nodes[node];
    for i in 0..wide::W {
        if n.valid & (1 << i) == 0 {
            continue;
        }
        above.push(n.child_box(i));
        if n.count[i] > 0 {
            let first = n.child[i] as usize;
            for k in first..first + n.count[i] as usize {
                let b = &boxes[bvh.indices[k] as usize];
                for (low, high) in above.iter() {
                    for axis in 0..3 {
                        assert!(
                            low[axis] as f64 <= b.min[axis] && b.max[axis] <= high[axis] as f64,
                            "{b:?} not in {low:?}..{high:?}"
                        );
                    }
                }
            }
        } else {
            assert_contained(bvh, boxes, n.child[i] as usize, above);
        }
        above.pop();
    }
}

#[test]
fn quantised_child_boxes_contain_their_items_at_any_scale() {
    let mut rng = Rng::new(3, 4);
    for scale in [1.0, 1e-40, 1e-20, 3e4, 1e30, 2e38, 1e300] {
        for offset in [0.0, 1.0, -7.5e6] {
            let boxes: Vec<Aabb> = random_boxes(&mut rng, 500)
                .iter()
                .map(|b| Aabb {
                    min: b.min * scale + Vec3::repeat(offset),
                    max: b.max * scale + Vec3::repeat(offset),
                })
                .collect();
            let bvh = Bvh::build(&boxes);
            assert_eq!(bvh.len(), 500);
            assert_contained(&bvh, &boxes, 0, &mut Vec::new());
        }
    }
}

#[test]
fn grid_planes_are_exact_f32_values_covering_the_range() {
    let mut rng = Rng::new(10, 11);
    for _ in 0..2000 {
        // From subnormal values to 1e36 (nearer the f32 limit, 255 steps
        // may not fit, and the axis is left unbounded).
        let magnitude = 10f64.powf(rng.next_f64() * 80.0 - 44.0);
        let a = wide::round_down((rng.next_f64() - 0.5) * magnitude);
        let width = magnitude * 10f64.powf(-rng.next_f64() * 9.0) * rng.next_f64();
        let b = wide::round_up(a as f64 + width);
        let (exponent, origin) = wide::grid(a, b).expect("finite range");
        let step = f32::from_bits((exponent as u32) << 23);
        assert!(origin <= a);
        for q in 0..=255u8 {
            let exact = origin as f64 + q as f64 * step as f64;
            assert_eq!((q as f32 * step + origin) as f64, exact, "{a} {b} {q}");
            assert_eq!((q as f32).mul_add(step, origin) as f64, exact);
        }
        assert!(origin as f64 + 255.0 * step as f64 >= b as f64);
    }
    assert_eq!(wide::grid(0.0, f32::INFINITY), None);
    assert_eq!(wide::grid(-f32::MAX, f32::MAX), None);
}

#[test]
fn traversal_equals_brute_force_at_extreme_scales() {
    let mut rng = Rng::new(12, 13);
    for scale in [1e-40, 1e36, 1e300] {
        let boxes: Vec<Aabb> = random_boxes(&mut rng, 300)
            .iter()
            .map(|b| Aabb {
                min: b.min * scale,
                max: b.max * scale,
            })
            .collect();
        let bvh = Bvh::build(&boxes);
        for _ in 0..300 {
            let origin = (Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 14.0
                - Vec3::repeat(2.0))
                * scale;
            let direction =
                Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) - Vec3::repeat(0.5);
            let ray = Ray::new(origin, direction, 0.0);
            let brute = brute_nearest(&boxes, &ray);
            assert_eq!(nearest(&bvh, &boxes, &ray), brute, "{scale}");
        }
    }
}
