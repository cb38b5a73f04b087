//! Hostile and careless scene text (issue 12): each test pins one hole that
//! an attacker or a careless user found, from a panic in rendering to a
//! message that hid what was wrong.

use std::path::Path;

use pathtracer::geometry::Revolution;
use pathtracer::geometry::{CurveKind, Profile};
use pathtracer::limits::{MAX_CONTROL_POINTS, MAX_NESTING, MAX_SHOWN_TOKEN};
use pathtracer::math::{Point3, Ray, Vec3};
use pathtracer::scene::ast::{Block, Document, Item, ItemKind};
use pathtracer::scene::error::{Location, SceneError};
use pathtracer::scene::model::Scene;
use pathtracer::scene::{LoadOptions, build, parse};

const HEAD: &str = "PerspectiveCamera { center 0 1 8 direction 0 0 -1 up 0 1 0 angle 30 \
                    width 32 height 32 }\nMaterials { Material { diffuseColor 1 0 0 } }\n";

fn load(text: &str) -> Result<Scene, String> {
    let file = Path::new("hostile.txt");
    let document = parse(text, file).map_err(|e| e.to_string())?;
    build(&document, file, &LoadOptions::default()).map_err(|e| e.to_string())
}

fn warnings(scene: &Scene) -> Vec<String> {
    scene.warnings.iter().map(|w| w.to_string()).collect()
}

fn profile(kind: CurveKind, controls: &[[f64; 2]]) -> Profile {
    Profile {
        kind,
        controls: controls.to_vec(),
    }
}

/// Rays from all around at the surface (and through the axis and the
/// degenerate pieces): every one must return, and any hit be finite and in range.
fn shoot_around(surface: &Revolution) -> usize {
    let mut hits = 0;
    for i in 0..24 {
        for j in 0..24 {
            let angle = i as f64 / 24.0 * std::f64::consts::TAU;
            let height = -1.0 + j as f64 / 8.0;
            let origin = Point3::new(5.0 * angle.cos(), height, 5.0 * angle.sin());
            for target in [
                Point3::new(0.0, height, 0.0),
                Point3::new(-1.0, 0.0, 0.0),
                Point3::new(0.0, 1.0, 0.3),
            ] {
                let ray = Ray::new(origin, target - origin, 0.0);
                if let Some(hit) = surface.intersect(&ray, 1e-9, f64::INFINITY) {
                    assert!(hit.t.is_finite() && hit.t > 0.0, "{hit:?}");
                    hits += 1;
                }
            }
        }
    }
    // Straight down and up the axis.
    for direction in [Vec3::y(), -Vec3::y()] {
        let ray = Ray::new(Point3::new(0.0, -direction.y * 5.0, 0.0), direction, 0.0);
        let _ = surface.intersect(&ray, 1e-9, f64::INFINITY);
    }
    hits
}

#[test]
fn a_bspline_with_four_equal_points_renders_without_panic() {
    let equal = [[-1.0, 0.0]; 4];
    let mut controls = equal.to_vec();
    controls.push([-1.0, 2.0]);
    let surface = Revolution::new(&profile(CurveKind::Bspline, &controls)).expect("usable");
    assert!(shoot_around(&surface) > 0, "the cylinder part is hit");
    // The same degenerate pieces in other places and shapes of profile.
    let mut middle = vec![[0.5, -1.0], [1.0, 0.0]];
    middle.extend_from_slice(&[[1.0, 0.5]; 4]);
    middle.extend_from_slice(&[[0.0, 1.0], [0.0, 1.0]]);
    for controls in [
        middle,
        vec![[1.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 0.0]],
        vec![[0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [1.0, 1.0]],
    ] {
        if let Some(surface) = Revolution::new(&profile(CurveKind::Bspline, &controls)) {
            shoot_around(&surface);
        }
    }
    for controls in [vec![[1.0, 0.0], [1.0, 0.0]], vec![[1.0, 0.0], [1.0, 2.0]]] {
        if let Some(surface) = Revolution::new(&profile(CurveKind::Bezier, &controls)) {
            shoot_around(&surface);
        }
    }
    // Through the scene file: a warning at the first of the four points.
    let scene = load(&format!(
        "{HEAD}Group {{\nRevSurface {{ profile BsplineCurve {{ controls [ -1 0 0 ] [ -1 0 0 ] \
         [ -1 0 0 ] [ -1 0 0 ] [ -1 2 0 ] }} }} }}"
    ))
    .expect("builds");
    let warnings = warnings(&scene);
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("hostile.txt:4:46") && w.contains("equal")),
        "{warnings:?}"
    );
}

#[test]
fn a_profile_without_area_is_left_out_with_a_located_warning() {
    assert!(Revolution::new(&profile(CurveKind::Bezier, &[[1.0, 1.0]; 3])).is_none());
    assert!(Revolution::new(&profile(CurveKind::Bezier, &[[0.0, 0.0], [0.0, 2.0]])).is_none());
    for controls in ["[ 1 1 0 ] [ 1 1 0 ]", "[ 0 0 0 ] [ 0 2 0 ] [ 0 3 0 ]"] {
        let scene = load(&format!(
            "{HEAD}Group {{\n  RevSurface {{ profile BezierCurve {{ controls {controls} }} }} }}"
        ))
        .expect("builds");
        let warnings = warnings(&scene);
        assert!(
            warnings.iter().any(|w| w.contains("hostile.txt:4:")
                && w.contains("no area")
                && w.contains("left out")),
            "{warnings:?}"
        );
        let mut leaves = 0;
        scene.root.for_each_leaf(&mut |_| leaves += 1);
        assert_eq!(leaves, 0);
    }
}

#[test]
fn a_token_at_the_end_of_a_very_long_line_is_located_at_its_column() {
    // 20,000 spheres on one line after a line of multi-byte characters, then
    // one more token on the next line: columns count characters from the
    // start of their own line, however long it is.
    let sphere = "Sphere { center 0 0 0 radius 1 } ";
    let line = format!("Group {{ {} }}", sphere.repeat(20_000));
    let text = format!("# 副本 ü\n{line} Tail\nLast");
    let document = parse(&text, Path::new("long.txt")).expect("parses");
    let words: Vec<&Item> = document.items.iter().collect();
    let tail = words[1];
    assert_eq!(tail.word(), Some("Tail"));
    assert_eq!(
        tail.location,
        Location {
            line: 2,
            column: line.chars().count() as u32 + 2
        }
    );
    assert_eq!(words[2].location, Location { line: 3, column: 1 });
    let group = words[0].block().expect("group");
    let last = group.items.last().expect("spheres");
    let expected_column = 9 + 19_999 * sphere.len();
    assert_eq!(last.location.column as usize, expected_column);
}

#[test]
fn a_file_starting_with_a_byte_order_mark_reads_its_camera() {
    let text = format!("\u{feff}{HEAD}Group {{ Sphere {{ center 0 0 0 radius 1 }} }}");
    let scene = load(&text).expect("a BOM is skipped");
    assert!(warnings(&scene).is_empty(), "{:?}", warnings(&scene));
    let document = parse(&text, Path::new("bom.txt")).expect("parses");
    assert_eq!(document.items[0].location, Location { line: 1, column: 1 });
}

#[test]
fn a_five_megabyte_token_is_cut_short_in_messages() {
    let token = "é".repeat(2_500_000);
    let scene = load(&format!(
        "{HEAD}Group {{ {token} 1 Sphere {{ center 0 0 0 radius 1 }} }}"
    ))
    .expect("builds");
    let warnings = warnings(&scene);
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].contains('…'));
    assert!(
        warnings[0].chars().count() < 3 * MAX_SHOWN_TOKEN,
        "{}",
        warnings[0]
    );
    // Errors too: a long word where a list wants a number.
    let error = load(&format!(
        "{HEAD}Group {{ RevSurface {{ profile BezierCurve {{ controls [ 1 {token} ] }} }} }}"
    ))
    .expect_err("not a number");
    assert!(error.contains('…') && error.len() < 400, "{}", error.len());
}

#[test]
fn a_nan_or_infinite_radius_says_a_finite_number_was_expected() {
    for word in ["nan", "inf", "-inf", "NaN"] {
        let error = load(&format!(
            "{HEAD}Group {{ Sphere {{ center 0 0 0 radius {word} }} }}"
        ))
        .expect_err("not a number");
        assert!(
            error.contains(&format!(
                "hostile.txt:3:38: expected a finite number after 'radius', found '{word}'"
            )),
            "{error}"
        );
    }
    let error = load(&format!(
        "{HEAD}Group {{ Sphere {{ center 0 nan 0 radius 1 }} }}"
    ))
    .expect_err("not a number");
    assert!(
        error.contains("expected 3 finite numbers after 'center', found 1 then 'nan'"),
        "{error}"
    );
    let error = load("PerspectiveCamera { width nan height 2 }").expect_err("not a number");
    assert!(
        error.contains("1:27: expected a finite number after 'width', found 'nan'"),
        "{error}"
    );
}

#[test]
fn zero_and_negative_radii_warn_at_the_field() {
    let scene = load(&format!(
        "{HEAD}Group {{\n Sphere {{ center 0 0 0 radius 0 }}\n Disk {{ center 0 0 0 normal 0 1 0 radius -2 }} }}"
    ))
    .expect("builds");
    let warnings = warnings(&scene);
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("hostile.txt:4:24") && w.contains("radius 0")),
        "{warnings:?}"
    );
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("hostile.txt:5:35") && w.contains("negative radius -2")),
        "{warnings:?}"
    );
}

#[test]
fn a_fractional_width_or_material_index_is_an_error() {
    let error = load("PerspectiveCamera { width 32.5 height 32 }").expect_err("fraction");
    assert!(
        error.contains("1:27: expected a whole number after 'width', found 32.5"),
        "{error}"
    );
    let error = load(&format!(
        "{HEAD}Group {{ MaterialIndex 1.5 Sphere {{ center 0 0 0 radius 1 }} }}"
    ))
    .expect_err("fraction");
    assert!(
        error.contains("3:23: expected a whole number after 'MaterialIndex', found 1.5"),
        "{error}"
    );
    // Whole numbers written with a fraction part are fine.
    load("PerspectiveCamera { width 32.0 height 32 }").expect("whole");
}

fn bezier_scene(count: usize) -> String {
    let points: String = (0..count)
        .map(|i| {
            format!(
                "[ {} {} 0 ] ",
                1.0 + 0.25 * (i as f64 * 0.01).sin(),
                i as f64 / count as f64
            )
        })
        .collect();
    format!("{HEAD}Group {{\nRevSurface {{ profile BezierCurve {{ controls {points}}} }} }}")
}

#[test]
fn a_bezier_curve_beyond_the_control_point_limit_is_a_located_error() {
    let error = load(&bezier_scene(MAX_CONTROL_POINTS + 1)).expect_err("too many");
    assert!(
        error.contains("hostile.txt:4:") && error.contains("more than 4096 control points"),
        "{error}"
    );
}

#[test]
fn a_bezier_curve_of_the_most_control_points_builds_and_hits_its_surface() {
    let scene = load(&bezier_scene(MAX_CONTROL_POINTS)).expect("builds");
    let mut profile = None;
    scene.root.for_each_leaf(&mut |leaf| {
        if let pathtracer::scene::model::Object::Revolution { profile: p, .. } = leaf {
            profile = Some(p.clone());
        }
    });
    let surface = Revolution::new(&profile.expect("a revolution")).expect("usable");
    let ray = Ray::new(Point3::new(5.0, 0.5, 0.0), -Vec3::x(), 0.0);
    let hit = surface
        .intersect(&ray, 0.0, f64::INFINITY)
        .expect("hits the side");
    let point = surface.surface(&ray, &hit).point;
    let (on_curve, _) = surface.curve().evaluate(hit.u);
    assert!((point.y - on_curve.y).abs() < 1e-7 && (point.x - on_curve.x).abs() < 1e-7);
}

#[test]
fn a_hundred_thousand_nested_groups_are_a_located_error() {
    for opening in ["Group { ", "Transform { "] {
        let text = format!("{HEAD}Group {{ {} }}", opening.repeat(100_000));
        let error = load(&text).expect_err("too deep");
        assert!(
            error.contains("hostile.txt:3:")
                && error.contains(&format!("deeper than {MAX_NESTING}")),
            "{error}"
        );
    }
    // Just within the limit it builds.
    let depth = MAX_NESTING - 2;
    let text = format!(
        "{HEAD}Group {{ {} Sphere {{ center 0 0 0 radius 1 }} {} }}",
        "Transform { Translate 1 0 0 ".repeat(depth),
        "} ".repeat(depth)
    );
    load(&text).expect("builds at the limit");
}

/// `depth` groups each inside the last, made in code (not through the parser).
fn nested_document(depth: usize) -> Document {
    let at = Location { line: 1, column: 1 };
    let mut inner = Item {
        location: at,
        kind: ItemKind::Block(Box::new(Block {
            name: "Group".into(),
            items: Vec::new(),
            close: at,
        })),
    };
    for _ in 0..depth {
        inner = Item {
            location: at,
            kind: ItemKind::Block(Box::new(Block {
                name: "Group".into(),
                items: vec![inner],
                close: at,
            })),
        };
    }
    let camera = parse("PerspectiveCamera { width 2 height 2 }", Path::new("t.txt"))
        .expect("parses")
        .items;
    Document {
        items: camera.into_iter().chain([inner]).collect(),
    }
}

#[test]
fn a_tree_nested_deeper_than_the_limit_in_code_is_an_error_at_build() {
    let file = Path::new("code.txt");
    let deep = build(
        &nested_document(MAX_NESTING + 8),
        file,
        &LoadOptions::default(),
    );
    match deep {
        Err(SceneError::At(diagnostic)) => {
            assert!(diagnostic.message.contains("nested deeper"), "{diagnostic}")
        }
        Err(other) => panic!("{other}"),
        Ok(_) => panic!("a tree deeper than MAX_NESTING builds"),
    }
    assert!(
        build(
            &nested_document(MAX_NESTING - 8),
            file,
            &LoadOptions::default()
        )
        .is_ok()
    );
}
#[test]
fn a_horizontal_ray_hits_a_profile_flatter_than_it_is_steep() {
    // A shallow cone from radius 1 to 3 over a height of 0.1: its frusta are
    // flat, and a ray of exactly zero slope used to get no seeds at all.
    let surface =
        Revolution::new(&profile(CurveKind::Bezier, &[[1.0, 0.0], [3.0, 0.1]])).expect("usable");
    let ray = Ray::new(Point3::new(10.0, 0.05, 0.0), -Vec3::x(), 0.0);
    let hit = surface.intersect(&ray, 0.0, f64::INFINITY).expect("hits");
    assert!((hit.t - 8.0).abs() < 1e-7, "{}", hit.t);
}
