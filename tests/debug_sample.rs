//! `render --debug-sample x,y,i` re-traces one pixel sample alone: the
//! terms it prints add up to the sample's value, and that value is what the
//! sample adds to its pixel in a render (a film given that one sample, and
//! the image the binary writes).

mod common;

use std::path::Path;

use pathtracer::color::Color;
use pathtracer::film::Film;
use pathtracer::image_io::read_image;
use pathtracer::integrator::Integrator;
use pathtracer::integrator::path_log::PathEvent;
use pathtracer::look::Look;
use pathtracer::render::debug_sample::trace_sample;
use pathtracer::render::{RenderSettings, render_into};
use pathtracer::render_scene::RenderScene;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::{LoadOptions, load_scene};

const WIDTH: u32 = 12;
const HEIGHT: u32 = 9;

fn settings(look: Look, integrator: Integrator) -> RenderSettings {
    RenderSettings {
        width: WIDTH,
        height: HEIGHT,
        spp: 4,
        seed: 7,
        threads: Some(2),
        integrator,
        max_depth: look.max_depth,
        sampler: SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look,
        dispersion: None,
    }
}

fn scene_of(file: &str, settings: &RenderSettings) -> RenderScene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("testcases")
        .join(file);
    let options = LoadOptions {
        base: Some(Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()),
        ..LoadOptions::default()
    };
    let scene = load_scene(&path, &options).expect("the test case loads");
    RenderScene::build(scene, &settings.scene())
}

/// Every sample `sample` of every pixel, traced alone, against a film that
/// took only that sample: the terms sum to the value bit for bit, and the
/// film's pixel holds the value (to its fixed point's step).
fn check_every_pixel(file: &str, integrator: Integrator, sample: u32) -> usize {
    let look = Look::ORIGINAL;
    let settings = settings(look, integrator);
    let scene = scene_of(file, &settings);
    let mut film = Film::new(WIDTH as usize, HEIGHT as usize);
    render_into(&scene, &settings, &mut film, sample..sample + 1).expect("renders");
    let mut vertices = 0;
    for row in 0..HEIGHT as usize {
        for x in 0..WIDTH as usize {
            let trace = trace_sample(&scene, &settings, x, row, sample).expect("traces");
            let total = trace.record.total();
            assert_eq!(
                [total.r, total.g, total.b],
                [trace.value.r, trace.value.g, trace.value.b],
                "{file} ({x}, {row}): the terms do not sum to the sample's value"
            );
            let pixel = &film.pixels[row * WIDTH as usize + x];
            assert_eq!(pixel.samples, 1, "{file} ({x}, {row})");
            let in_film = pixel.sum.to_color();
            let difference = largest_difference(in_film, trace.value);
            assert!(
                difference < 1e-9,
                "{file} ({x}, {row}) sample {sample}: film {in_film:?}, traced {:?}",
                trace.value
            );
            vertices += trace
                .record
                .events
                .iter()
                .filter(|e| matches!(e, PathEvent::Hit { .. }))
                .count();
        }
    }
    vertices
}

#[test]
fn a_traced_sample_is_what_the_render_adds_with_the_path_integrator() {
    for file in ["smallpt.txt", "showcase.txt", "tutorial4_cornell.txt"] {
        let vertices = check_every_pixel(file, Integrator::Path, 3);
        assert!(
            vertices > (WIDTH * HEIGHT) as usize,
            "{file}: {vertices} hits logged"
        );
    }
}

#[test]
fn a_traced_sample_is_what_the_render_adds_with_the_original_estimator() {
    let vertices = check_every_pixel("smallpt.txt", Integrator::Original, 1);
    assert!(
        vertices > (WIDTH * HEIGHT) as usize,
        "{vertices} hits logged"
    );
}

#[test]
fn a_traced_sample_is_what_the_render_adds_through_media() {
    // The path integrator through media reports its estimate only.
    check_every_pixel("crosscheck_media.txt", Integrator::Path, 0);
}

fn largest_difference(a: Color, b: Color) -> f64 {
    [a.r - b.r, a.g - b.g, a.b - b.b]
        .iter()
        .fold(0.0, |m: f64, d| m.max(d.abs()))
}

/// The numbers of a printed colour (`r g b` after `prefix`).
fn printed_color(line: &str) -> Color {
    let numbers: Vec<f64> = line
        .split_whitespace()
        .take(3)
        .map(|n| n.parse().expect("a number"))
        .collect();
    Color::new(numbers[0], numbers[1], numbers[2])
}

#[test]
fn the_printed_terms_add_up_to_the_pixel_of_a_one_sample_render() {
    let dir = common::fresh_dir("debug-sample");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/showcase.txt");
    let scene = scene.to_str().expect("a UTF-8 path");
    let base = [
        "render", scene, "--width", "12", "--height", "9", "--seed", "5",
    ];
    let image = dir.join("one.pfm");
    let mut render: Vec<&str> = base.to_vec();
    render.extend([
        "--spp",
        "1",
        "--quiet",
        "-o",
        image.to_str().expect("UTF-8"),
    ]);
    let ran = common::finish(common::command_in(&dir, &render));
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    let image = read_image(&image).expect("the PFM reads");
    for (x, row) in [(6, 4), (2, 7), (10, 1), (5, 5)] {
        let which = format!("{x},{row},0");
        let mut debug: Vec<&str> = base.to_vec();
        debug.extend(["--debug-sample", &which]);
        let ran = common::finish(common::command_in(&dir, &debug));
        assert_eq!(ran.code, Some(0), "{}", ran.stderr);
        let mut sum = Color::BLACK;
        let mut terms = 0;
        let mut value = None;
        for line in ran.stdout.lines() {
            if let Some(rest) = line.trim_start().strip_prefix("+ ") {
                sum += printed_color(rest);
                terms += 1;
            } else if let Some(rest) = line.strip_prefix("sample value: ") {
                value = Some(printed_color(rest));
            }
        }
        let value = value.expect("a sample value line");
        assert!(terms > 0, "{}", ran.stdout);
        assert_eq!(
            [sum.r, sum.g, sum.b],
            [value.r, value.g, value.b],
            "{}",
            ran.stdout
        );
        let pixel = image.pixels[row * 12 + x];
        let difference = largest_difference(pixel, value);
        // The image is f32.
        assert!(
            difference <= 1e-6 * value.max_component().abs().max(1.0),
            "({x}, {row}): image {pixel:?}, printed {value:?}\n{}",
            ran.stdout
        );
    }
}

#[test]
fn a_pixel_outside_the_image_is_refused() {
    let dir = common::fresh_dir("debug-sample-outside");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/smallpt.txt");
    let scene = scene.to_str().expect("a UTF-8 path");
    let args = [
        "render",
        scene,
        "--width",
        "8",
        "--height",
        "6",
        "--debug-sample",
        "8,0,0",
    ];
    let ran = common::finish(common::command_in(&dir, &args));
    assert!(
        ran.refused().contains("outside the 8x6 image"),
        "{}",
        ran.stderr
    );
    let args = ["render", scene, "--debug-sample", "1,2"];
    let ran = common::finish(common::command_in(&dir, &args));
    assert_eq!(ran.code, Some(2), "{}", ran.stderr);
    assert!(ran.stderr.contains("expected x,y,i"), "{}", ran.stderr);
}
