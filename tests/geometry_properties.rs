//! Properties of the geometry core: BVH equals brute force on real meshes, spawned
//! rays do not re-hit their surface, Newton revolution hits agree with a fine
//! tessellation, transforms are exact, and degenerate rays produce no NaN.

use std::path::Path;
use std::sync::Arc;

use pathtracer::geometry::curve::Point2;
use pathtracer::geometry::triangle::intersect_vertices;
use pathtracer::geometry::{Curve, Mesh, Plane, Revolution, Shape, Sphere, Transform};
use pathtracer::math::{Aabb, Matrix, Point3, Ray, Vec3, offset_origin};
use pathtracer::rng::Rng;
use pathtracer::scene::model::{CurveKind, MeshData, Profile};
use pathtracer::world::{Primitive, World};

const BUNNY: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../shared/reference/meshes/bunny.obj"
);
const BUNNY_1K: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../shared/reference/cambrian-pathtracer/mesh/bunny_1k.obj"
);

fn load_mesh(path: &str) -> Option<Arc<MeshData>> {
    if !Path::new(path).exists() {
        println!("skipped: ../shared not found ({path})");
        return None;
    }
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj(path, &options).expect("reference OBJ loads");
    let mut data = MeshData::default();
    for model in models {
        let mesh = model.mesh;
        let base = data.positions.len() as u32;
        data.positions.extend(
            mesh.positions
                .chunks(3)
                .map(|p| Point3::new(p[0] as f64, p[1] as f64, p[2] as f64)),
        );
        data.triangles.extend(
            mesh.indices
                .chunks(3)
                .map(|t| [base + t[0], base + t[1], base + t[2]]),
        );
    }
    Some(Arc::new(data))
}

fn random_unit(rng: &mut Rng) -> Vec3 {
    let z = 2.0 * rng.next_f64() - 1.0;
    let phi = 2.0 * std::f64::consts::PI * rng.next_f64();
    let r = (1.0 - z * z).max(0.0).sqrt();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

fn random_in_box(rng: &mut Rng, b: &Aabb) -> Point3 {
    let e = b.extent();
    b.min
        + Vec3::new(
            e.x * rng.next_f64(),
            e.y * rng.next_f64(),
            e.z * rng.next_f64(),
        )
}

/// A ray from outside the box towards a random point inside it.
fn ray_at_box(rng: &mut Rng, b: &Aabb) -> Ray {
    let size = b.extent().norm();
    let origin = b.centroid() + random_unit(rng) * size * 1.5;
    let target = random_in_box(rng, b);
    Ray::new(origin, target - origin, rng.next_f64())
}

#[test]
fn mesh_bvh_equals_brute_force_on_reference_meshes() {
    for path in [BUNNY_1K, BUNNY] {
        let Some(data) = load_mesh(path) else { return };
        let mesh = Mesh::new(Arc::clone(&data));
        let bounds = mesh.bounds().expect("non-empty mesh");
        let mut rng = Rng::new(7, 11);
        let (mut hits, rays) = (0, 2500);
        for i in 0..rays {
            let mut ray = ray_at_box(&mut rng, &bounds);
            if i % 10 == 0 {
                // Axis-parallel rays through the box.
                let axis = i / 10 % 3;
                ray.direction = Vec3::zeros();
                ray.direction[axis] = 1.0;
                ray.origin[axis] = bounds.min[axis] - 1.0;
            }
            let brute = data
                .triangles
                .iter()
                .filter_map(|t| {
                    let p = t.map(|i| data.positions[i as usize]);
                    intersect_vertices(&p[0], &p[1], &p[2], &ray, 0.0, f64::INFINITY)
                })
                .map(|(t, _, _)| t)
                .fold(f64::INFINITY, f64::min);
            let found = mesh.intersect(&ray, 0.0, f64::INFINITY);
            assert_eq!(
                found.map_or(f64::INFINITY, |h| h.t),
                brute,
                "{path} ray {i}"
            );
            assert_eq!(mesh.occluded(&ray, 0.0, f64::INFINITY), brute.is_finite());
            // A shortened ray must agree too (the any-hit path honours t_max).
            let half = brute * 0.999;
            assert!(!mesh.occluded(&ray, 0.0, half) || !brute.is_finite());
            hits += brute.is_finite() as usize;
        }
        println!("{path}: {hits}/{rays} rays hit, BVH == brute force");
        assert!(hits > rays / 10, "test rays should mostly hit the mesh");
    }
}

#[test]
fn world_bvh_equals_linear_scan() {
    let mut rng = Rng::new(3, 5);
    let mut primitives = Vec::new();
    for i in 0..300 {
        let center = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 20.0;
        let shape = if i % 2 == 0 {
            Shape::Sphere(Sphere::new(center, 0.2 + rng.next_f64(), Vec3::zeros()))
        } else {
            let v = [0, 1, 2].map(|_| center + random_unit(&mut rng) * 1.5);
            Shape::Triangle(pathtracer::geometry::Triangle::new(v))
        };
        primitives.push(Primitive {
            shape,
            transform: None,
            material: i,
        });
    }
    primitives.push(Primitive {
        shape: Shape::Plane(Plane::new(Vec3::y(), -1.0).unwrap()),
        transform: None,
        material: 999,
    });
    let world = World::from_primitives(primitives.clone());
    let bounds = world.bounds();
    for _ in 0..3000 {
        let ray = ray_at_box(&mut rng, &bounds);
        let linear = primitives
            .iter()
            .filter_map(|p| p.intersect(&ray, 1e-9, f64::INFINITY).map(|h| h.t))
            .fold(f64::INFINITY, f64::min);
        let hit = world.intersect(&ray, 1e-9, f64::INFINITY);
        assert_eq!(hit.map_or(f64::INFINITY, |h| h.t), linear);
        assert_eq!(
            world.occluded(&ray, 1e-9, f64::INFINITY),
            linear.is_finite()
        );
    }
}

fn transform(matrix: Matrix) -> Option<Box<Transform>> {
    let inverse = matrix.try_inverse().expect("invertible");
    Some(Box::new(Transform::new(matrix, inverse)))
}

fn vase() -> Profile {
    Profile {
        kind: CurveKind::Bezier,
        controls: vec![
            [0.0, 0.0],
            [2.2, 0.0],
            [3.0, 1.5],
            [1.2, 3.0],
            [0.8, 4.0],
            [1.6, 5.0],
            [2.0, 5.6],
        ],
    }
}

/// The B-spline wine glass of cambrian-pathtracer/testcases/bspline.txt.
fn wine_glass() -> Profile {
    let controls = [
        [0.0, -0.459543],
        [0.0, -0.459544],
        [0.0, -0.459545],
        [-0.351882, -0.426747],
        [-0.848656, -0.278898],
        [-1.112097, 0.084005],
        [-1.164785, 1.105511],
        [-0.991667, 2.328629],
        [-1.029301, 2.503360],
        [-1.088800, 2.345600],
        [-1.278000, 1.162800],
        [-1.214800, 0.055200],
        [-0.915600, -0.381200],
        [-0.380400, -0.622000],
        [-0.144000, -0.968400],
        [-0.096800, -1.480000],
        [-0.128400, -2.112400],
        [-0.317200, -2.202800],
        [-0.994400, -2.262800],
        [-1.214800, -2.323200],
        [-1.199200, -2.398400],
        [-1.057600, -2.458800],
        [-0.711200, -2.458800],
        [0.000000, -2.458800],
        [0.000000, -2.458801],
        [0.000000, -2.458802],
    ];
    Profile {
        kind: CurveKind::Bspline,
        controls: controls.to_vec(),
    }
}

/// Shapes under transforms of very different scales, for the self-intersection test.
fn spawn_test_primitives() -> Vec<(String, Primitive)> {
    let bunny = load_mesh(BUNNY_1K).map(Mesh::new).map(Arc::new);
    let sphere = Shape::Sphere(Sphere::new(Point3::new(0.3, -0.2, 0.1), 1.0, Vec3::zeros()));
    let revolution = Shape::Revolution(Arc::new(Revolution::new(&vase()).unwrap()));
    let glass = Shape::Revolution(Arc::new(Revolution::new(&wine_glass()).unwrap()));
    let plane = Shape::Plane(Plane::new(Vec3::new(0.2, 1.0, -0.3), 0.7).unwrap());
    let scales: [(&str, Matrix); 5] = [
        ("identity", Matrix::identity()),
        ("scale 1e-3", Matrix::new_scaling(1e-3)),
        ("scale 1e3", Matrix::new_scaling(1e3)),
        (
            "translate 1e5",
            Matrix::new_translation(&Vec3::new(1e5, -1e5, 1e5)),
        ),
        (
            "non-uniform",
            Matrix::new_nonuniform_scaling(&Vec3::new(2.0, 0.5, 1.0))
                * Matrix::from_euler_angles(0.3, 0.5, 0.1),
        ),
    ];
    let mut shapes = vec![
        ("sphere", sphere),
        ("plane", plane),
        ("vase", revolution),
        ("glass", glass),
    ];
    if let Some(mesh) = bunny {
        shapes.push((
            "bunny",
            Shape::Mesh {
                mesh,
                smooth: false,
            },
        ));
    }
    let mut out = Vec::new();
    for (name, shape) in &shapes {
        for (label, matrix) in &scales {
            out.push((
                format!("{name}, {label}"),
                Primitive {
                    shape: shape.clone(),
                    transform: transform(*matrix),
                    material: 0,
                },
            ));
        }
    }
    out
}

#[test]
fn spawned_rays_do_not_rehit_their_surface() {
    let mut rng = Rng::new(21, 4);
    for (name, primitive) in spawn_test_primitives() {
        let world = World::from_primitives(vec![primitive.clone()]);
        // Aim at the bounds (planes: at a box around a point of the plane).
        let target = primitive.bounds().unwrap_or_else(|| {
            let hit = world
                .intersect(
                    &Ray::new(Point3::new(0.0, 1e7, 0.0), -Vec3::y(), 0.0),
                    0.0,
                    f64::INFINITY,
                )
                .expect("plane below");
            Aabb::from_point(hit.point).expanded(5.0)
        });
        let size = target.extent().norm();
        let (mut trials, mut failures) = (0, 0);
        for _ in 0..2000 {
            let ray = ray_at_box(&mut rng, &target);
            let Some(hit) = world.intersect(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            assert!((hit.geometric_normal.norm() - 1.0).abs() < 1e-9, "{name}");
            // Both sides: reflection (towards the ray) and transmission.
            for side in [-1.0, 1.0] {
                let mut direction = random_unit(&mut rng);
                if direction.dot(&hit.geometric_normal) * side < 0.0 {
                    direction = -direction;
                }
                let origin = offset_origin(&hit.point, &hit.geometric_normal, &direction);
                let spawned = Ray::new(origin, direction, ray.time);
                trials += 1;
                if let Some(again) = world.intersect(&spawned, 0.0, f64::INFINITY)
                    && again.t < 1e-7 * size
                {
                    failures += 1;
                }
            }
        }
        println!("{name}: {failures} self-hits in {trials} spawned rays");
        assert!(trials > 500, "{name}: too few hits ({trials})");
        assert_eq!(failures, 0, "{name}: spawned rays re-hit their surface");
    }
}

/// Roots of `qa x^2 + 2 qb x + qc = 0` (stable form).
fn quadratic_roots(qa: f64, qb: f64, qc: f64) -> [f64; 2] {
    if qa == 0.0 {
        return [-qc / (2.0 * qb), f64::NAN];
    }
    let discriminant = qb * qb - qa * qc;
    if discriminant < 0.0 {
        return [f64::NAN; 2];
    }
    let root = -(qb + discriminant.sqrt().copysign(qb));
    [root / qa, qc / root]
}

/// Nearest hit of a ray with the surface swept by the segment a-b of the (x, y)
/// profile: an exact cone frustum. Steep segments are solved for t (s is linear in
/// y), flat ones for s (t is linear in s), so that neither divides by a tiny number.
fn frustum_hit(a: Point2, b: Point2, ray: &Ray) -> Option<f64> {
    let (o, d) = (ray.origin, ray.direction);
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    // r(t)^2 = ra t^2 + 2 rb t + rc.
    let ra = d.x * d.x + d.z * d.z;
    let rb = o.x * d.x + o.z * d.z;
    let rc = o.x * o.x + o.z * o.z;
    let mut hits = [(f64::NAN, f64::NAN); 2]; // (t, s)
    if dy.abs() >= dx.abs() {
        // s = alpha + beta t, x = p + q t.
        let (alpha, beta) = ((o.y - a.y) / dy, d.y / dy);
        let (p, q) = (a.x + dx * alpha, dx * beta);
        let roots = quadratic_roots(ra - q * q, rb - p * q, rc - p * p);
        hits = roots.map(|t| (t, alpha + beta * t));
    } else if d.y != 0.0 {
        // t = alpha + beta s.
        let (alpha, beta) = ((a.y - o.y) / d.y, dy / d.y);
        let roots = quadratic_roots(
            ra * beta * beta - dx * dx,
            ra * alpha * beta + rb * beta - a.x * dx,
            ra * alpha * alpha + 2.0 * rb * alpha + rc - a.x * a.x,
        );
        hits = roots.map(|s| (alpha + beta * s, s));
    }
    hits.into_iter()
        .filter(|&(t, s)| t > 0.0 && t.is_finite() && (0.0..=1.0).contains(&s))
        .map(|(t, _)| t)
        .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))))
}

#[test]
fn newton_revolution_agrees_with_fine_tessellation() {
    const SEGMENTS: usize = 2000;
    const RAYS: usize = 20_000;
    for (name, profile) in [
        ("vase (Bezier)", vase()),
        ("wine glass (B-spline)", wine_glass()),
    ] {
        let surface = Revolution::new(&profile).unwrap();
        let curve = Curve::new(&profile).unwrap();
        let points: Vec<Point2> = (0..=SEGMENTS)
            .map(|i| curve.evaluate(i as f64 / SEGMENTS as f64).0)
            .collect();
        let bounds = surface.bounds();
        let scale = bounds.extent().norm();
        let mut rng = Rng::new(99, 1);
        let (mut hit_miss, mut distance, mut hits, mut worst) = (0, 0, 0, 0.0f64);
        for _ in 0..RAYS {
            let mut ray = ray_at_box(&mut rng, &bounds);
            ray.direction = ray.direction.normalize();
            let reference = points
                .windows(2)
                .filter_map(|w| frustum_hit(w[0], w[1], &ray))
                .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))));
            let newton = surface.intersect(&ray, 0.0, f64::INFINITY).map(|h| h.t);
            match (reference, newton) {
                (Some(a), Some(b)) => {
                    hits += 1;
                    worst = worst.max((a - b).abs());
                    if (a - b).abs() > 1e-3 * scale {
                        distance += 1;
                    }
                }
                (None, None) => {}
                _ => hit_miss += 1,
            }
        }
        let rate = (hit_miss + distance) as f64 / RAYS as f64;
        println!(
            "{name}: {hits} hits of {RAYS} rays; hit/miss mismatches {hit_miss}, \
             |dt| > 1e-3 * size: {distance}; disagreement rate {:.4}%; \
             largest |dt| among agreeing hits {worst:.2e}",
            rate * 100.0
        );
        assert!(hits > RAYS / 4, "{name}: rays should mostly hit");
        assert!(rate < 1e-3, "{name}: disagreement rate {rate}");
    }
}

#[test]
fn non_uniformly_scaled_sphere_is_an_ellipsoid() {
    let center = Vec3::new(1.0, 2.0, 3.0);
    let matrix = Matrix::new_translation(&center)
        * Matrix::new_nonuniform_scaling(&Vec3::new(2.0, 1.0, 1.0));
    let world = World::from_primitives(vec![Primitive {
        shape: Shape::Sphere(Sphere::new(Point3::zeros(), 1.0, Vec3::zeros())),
        transform: transform(matrix),
        material: 0,
    }]);
    let mut rng = Rng::new(5, 5);
    let mut hits = 0;
    for _ in 0..2000 {
        let ray = ray_at_box(&mut rng, &world.bounds());
        let Some(hit) = world.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        hits += 1;
        let q = hit.point - center;
        let implicit = (q.x / 2.0).powi(2) + q.y * q.y + q.z * q.z;
        assert!(
            (implicit - 1.0).abs() < 1e-9,
            "point off the ellipsoid: {implicit}"
        );
        assert!(
            (ray.at(hit.t) - hit.point).norm() < 1e-9,
            "t is not world t"
        );
        let gradient = Vec3::new(q.x / 4.0, q.y, q.z).normalize();
        assert!((hit.geometric_normal - gradient).norm() < 1e-9);
        assert!(hit.tangent.dot(&hit.geometric_normal).abs() < 1e-9);
    }
    assert!(hits > 500);
}

fn assert_finite_hit(world: &World, ray: &Ray, what: &str) {
    if let Some(hit) = world.intersect(ray, 0.0, f64::INFINITY) {
        let values = [hit.t, hit.uv[0], hit.uv[1]];
        let vectors = [
            hit.point,
            hit.geometric_normal,
            hit.shading_normal,
            hit.tangent,
        ];
        assert!(
            values.iter().all(|v| v.is_finite())
                && vectors.iter().all(|v| v.iter().all(|c| c.is_finite())),
            "{what}: non-finite hit {hit:?} for {ray:?}"
        );
        assert!((hit.geometric_normal.norm() - 1.0).abs() < 1e-9, "{what}");
        assert!((hit.shading_normal.norm() - 1.0).abs() < 1e-9, "{what}");
    }
    let _ = world.occluded(ray, 0.0, f64::INFINITY);
}

#[test]
fn axis_parallel_and_grazing_rays_give_no_nan() {
    use pathtracer::geometry::{Disk, Rectangle, Triangle};
    let shapes = vec![
        Shape::Sphere(Sphere::new(Point3::zeros(), 1.0, Vec3::zeros())),
        Shape::Plane(Plane::new(Vec3::y(), 0.0).unwrap()),
        Shape::Triangle(Triangle::new([Point3::zeros(), Point3::x(), Point3::y()])),
        Shape::Rectangle(Rectangle::new(Point3::zeros(), Vec3::x(), Vec3::z()).unwrap()),
        Shape::Disk(Disk::new(Point3::zeros(), Vec3::y(), 1.0).unwrap()),
        Shape::Revolution(Arc::new(Revolution::new(&vase()).unwrap())),
        Shape::Revolution(Arc::new(Revolution::new(&wine_glass()).unwrap())),
    ];
    for shape in shapes {
        let world = World::from_primitives(vec![Primitive {
            shape: shape.clone(),
            transform: None,
            material: 0,
        }]);
        let what = format!("{shape:?}").chars().take(40).collect::<String>();
        // Axis-parallel rays from a grid that includes the axis, the box faces and
        // the surface itself (grazing: rays in the plane of flat shapes, tangent
        // to the sphere).
        let coordinates = [-2.5, -1.0, -0.5, 0.0, 0.5, 1.0, 2.2, 5.6];
        for axis in 0..3 {
            for &a in &coordinates {
                for &b in &coordinates {
                    for sign in [-1.0, 1.0] {
                        let mut origin = Point3::zeros();
                        origin[(axis + 1) % 3] = a;
                        origin[(axis + 2) % 3] = b;
                        origin[axis] = -10.0 * sign;
                        let mut direction = Vec3::zeros();
                        direction[axis] = sign;
                        assert_finite_hit(&world, &Ray::new(origin, direction, 0.0), &what);
                        origin[axis] = 0.0;
                        assert_finite_hit(&world, &Ray::new(origin, direction, 0.0), &what);
                    }
                }
            }
        }
    }
}
