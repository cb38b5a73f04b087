//! `pathtracer view` following its files: a saved scene restarts the
//! render, a broken one shows its located error and keeps the last image,
//! a changed mesh restarts it too, warnings are listed, the save button
//! writes the image (for the page's own origin only), and fifty quick saves
//! leave one render whose image is the last save's, with threads and memory
//! flat.

mod common;

use std::path::Path;
use std::time::{Duration, Instant};

use common::{Answer, Viewer, command_in, finish, fresh_dir};
use half::f16;
use pathtracer::image_io::read_image;

const WAIT: Duration = Duration::from_secs(60);

/// A lamp above a ball of `color`, 32x24 (the tutorial's second scene).
fn ball(color: &str, radius: &str) -> String {
    format!(
        "PerspectiveCamera {{\n center 0 5 18.7\n direction 0 0 -1\n up 0 1 0\n angle 40\n \
         width 32\n height 24\n}}\nBackground {{ color 0 0 0 }}\nMaterials {{\n numMaterials 2\n \
         Material {{ color {color} diffusionRate 1 }}\n Material {{ color 0 0 0 emission 40 40 40 }}\n}}\n\
         Group {{\n numObjects 2\n MaterialIndex 0\n Sphere {{ center 0 4 0 radius {radius} }}\n \
         MaterialIndex 1\n Sphere {{ center 0 11 2 radius 1 }}\n}}\n"
    )
}

/// A field in a status JSON, as text up to the next comma.
fn field(status: &Answer, name: &str) -> String {
    let text = status.text();
    let key = format!("\"{name}\": ");
    text.split(&key)
        .nth(1)
        .map(|rest| rest.split([',', '}']).next().unwrap_or("").to_string())
        .unwrap_or_default()
}

/// Waits for render number `render` to be done.
fn rendered(viewer: &Viewer, render: u64) -> Answer {
    viewer.wait_for("/status", WAIT, |a| {
        field(a, "render").parse::<u64>().is_ok_and(|r| r >= render) && field(a, "done") == "true"
    })
}

/// The film's pixels (after its 16-byte header), as f32.
fn values(film: &Answer) -> Vec<f32> {
    film.body[16..]
        .chunks(2)
        .map(|b| f16::from_le_bytes([b[0], b[1]]).to_f32())
        .collect()
}

#[test]
fn a_saved_scene_restarts_and_a_broken_one_shows_its_error_over_the_last_image() {
    let dir = fresh_dir("view-edit");
    let scene = dir.join("scene.txt");
    std::fs::write(&scene, ball("0.8 0.8 0.8", "3")).expect("write");
    let viewer = Viewer::start(&dir, &scene, &["--spp", "8", "-o", "saved.png"]);
    rendered(&viewer, 1);
    let white = viewer.get("/film");
    std::fs::write(&scene, ball("0.8 0.1 0.1", "3")).expect("write");
    rendered(&viewer, 2);
    let red = viewer.get("/film");
    let (white, red_values) = (values(&white), values(&red));
    // Clipped at 1, as shown: the lamp in view does not outweigh the ball.
    let sum = |v: &[f32], c: usize| v.iter().skip(c).step_by(3).map(|x| x.min(1.0)).sum::<f32>();
    assert!(sum(&white, 1) > 2.0 * sum(&red_values, 1), "green fell");
    assert!((sum(&white, 0) - sum(&red_values, 0)).abs() < 0.2 * sum(&white, 0));
    // Broken: the located error, and the last good film kept.
    std::fs::write(&scene, ball("0.8 0.1 0.1", "x")).expect("write");
    let broken = viewer.wait_for("/status", WAIT, |a| field(a, "error") != "null");
    assert!(
        broken
            .text()
            .contains("scene.txt:18:31: expected a number after 'radius'"),
        "{}",
        broken.text()
    );
    assert_eq!(viewer.get("/film").body, red.body);
    // Mended, with a warning the page lists.
    let warned =
        ball("0.8 0.1 0.1", "3").replace("diffusionRate 1", "diffusionRate 1 bogusField 2");
    std::fs::write(&scene, warned).expect("write");
    let mended = rendered(&viewer, 3);
    assert_eq!(field(&mended, "error"), "null");
    assert!(
        mended
            .text()
            .contains("unknown field 'bogusField' in Material"),
        "{}",
        mended.text()
    );
    // The save button: the page's origin only.
    let port = viewer.port;
    let post = |origin: &str| {
        viewer.request(&format!(
            "POST /save?exposure=1&gamma=2.2 HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n{origin}\r\n"
        ))
    };
    assert_eq!(post("").code, 403);
    assert_eq!(post("Origin: http://evil.example\r\n").code, 403);
    assert!(!dir.join("saved.png").exists());
    let saved = post(&format!("Origin: http://127.0.0.1:{port}\r\n"));
    assert_eq!(saved.code, 200, "{}", saved.text());
    let image = read_image(&dir.join("saved.png")).expect("a whole PNG");
    assert_eq!((image.width, image.height), (32, 24));
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .expect("dir")
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains("tmp"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
}

#[test]
fn a_changed_mesh_restarts_the_render() {
    let dir = fresh_dir("view-mesh");
    let triangle = |x: f64| format!("v -{x} -1 0\nv {x} -1 0\nv 0 1 0\nf 1 2 3\n");
    std::fs::write(dir.join("tri.obj"), triangle(0.5)).expect("write");
    let scene = dir.join("scene.txt");
    std::fs::write(
        &scene,
        "PerspectiveCamera {\n center 0 0 5\n direction 0 0 -1\n up 0 1 0\n angle 40\n width 32\n \
         height 24\n}\nBackground { color 0 0 0 }\nMaterials {\n numMaterials 1\n \
         Material { color 0 0 0 emission 1 1 1 }\n}\nGroup {\n numObjects 1\n MaterialIndex 0\n \
         TriangleMesh { obj_file tri.obj }\n}\n",
    )
    .expect("write");
    let viewer = Viewer::start(&dir, &scene, &["--spp", "4"]);
    rendered(&viewer, 1);
    let narrow: f32 = values(&viewer.get("/film")).iter().sum();
    std::fs::write(dir.join("tri.obj"), triangle(1.5)).expect("write");
    rendered(&viewer, 2);
    let wide: f32 = values(&viewer.get("/film")).iter().sum();
    assert!(wide > 2.0 * narrow, "narrow {narrow}, wide {wide}");
}

/// Threads and resident memory of process `pid`, from /proc.
fn threads_and_memory(pid: u32) -> (usize, u64) {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).expect("/proc");
    let value = |key: &str| {
        status
            .lines()
            .find_map(|l| l.strip_prefix(key))
            .and_then(|v| v.split_whitespace().next())
            .and_then(|v| v.parse::<u64>().ok())
            .expect("a /proc field")
    };
    (value("Threads:") as usize, value("VmRSS:") * 1024)
}

#[test]
fn fifty_quick_saves_leave_one_render_of_the_last_scene_and_memory_flat() {
    if !Path::new("/proc/self/status").exists() {
        println!("skipped: no /proc to read threads and memory from");
        return;
    }
    let dir = fresh_dir("view-saves");
    let scene = dir.join("scene.txt");
    let grey = |i: usize| format!("0.{:02} 0.5 0.5", 10 + i);
    std::fs::write(&scene, ball(&grey(0), "3")).expect("write");
    // A film of 160x120 is about 2 MB: fifty kept would be 100 MB.
    let size = ["--width", "160", "--height", "120", "--spp", "64"];
    let viewer = Viewer::start(&dir, &scene, &size);
    rendered(&viewer, 1);
    let pid = viewer.child.id();
    let (threads, memory) = threads_and_memory(pid);
    // Some saves come faster than the scene settles, some after a render
    // has restarted (and is stopped part way by the next).
    for i in 1..=50 {
        std::fs::write(&scene, ball(&grey(i), "3")).expect("write");
        std::thread::sleep(Duration::from_millis(30 * (i as u64 % 6)));
    }
    // Done, and still the same render a while later: the last save's.
    let last = loop {
        let done = rendered(&viewer, 2);
        std::thread::sleep(Duration::from_millis(300));
        let again = viewer.get("/status");
        if field(&again, "render") == field(&done, "render") && field(&again, "done") == "true" {
            break again;
        }
    };
    let renders: u64 = field(&last, "render").parse().expect("a number");
    assert!((2..=51).contains(&renders), "{renders} renders");
    println!("50 saves: {renders} renders in all");
    let film = viewer.get("/film");
    let ran = finish(command_in(
        &dir,
        &[
            &["render", "scene.txt", "-o", "last.pfm", "--quiet"],
            &size[..],
        ]
        .concat(),
    ));
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    let expected = read_image(&dir.join("last.pfm")).expect("the render");
    let served = values(&film);
    for (i, pixel) in expected.pixels.iter().enumerate() {
        for (c, want) in [pixel.r, pixel.g, pixel.b].into_iter().enumerate() {
            let got = served[i * 3 + c] as f64;
            assert!(
                (got - want).abs() <= want.abs() / 1024.0 + 1e-7,
                "pixel {i} channel {c}: served {got}, the last scene renders {want}"
            );
        }
    }
    // Worker pools of earlier renders gone, memory where it was.
    let started = Instant::now();
    let (mut now_threads, mut now_memory) = threads_and_memory(pid);
    while now_threads > threads + 2 && started.elapsed() < Duration::from_secs(10) {
        std::thread::sleep(Duration::from_millis(100));
        (now_threads, now_memory) = threads_and_memory(pid);
    }
    assert!(
        now_threads <= threads + 2,
        "threads {threads} -> {now_threads}"
    );
    assert!(
        now_memory <= memory + 16 * 1024 * 1024,
        "resident memory {memory} -> {now_memory} bytes"
    );
}
