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
            let brute = boxes
                .iter()
                .filter_map(|b| b.hit_distance(&origin, &inverse, 0.0, f64::INFINITY))
                .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))));
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
fn leaf_order_reports_positions_of_the_original_order() {
    let mut rng = Rng::new(8, 9);
    let boxes = random_boxes(&mut rng, 200);
    let bvh = Bvh::build(&boxes);
    let (ordered, order) = bvh.clone().into_leaf_order();
    let permuted: Vec<Aabb> = order.iter().map(|&i| boxes[i as usize]).collect();
    for _ in 0..300 {
        let origin = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 12.0;
        let direction =
            Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) - Vec3::repeat(0.5);
        let ray = Ray::new(origin, direction, 0.0);
        assert_eq!(
            nearest(&bvh, &boxes, &ray),
            nearest(&ordered, &permuted, &ray)
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
