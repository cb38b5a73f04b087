//! `pathtracer view` over HTTP: the page and the film are served, the film
//! converges to the image `render` makes with the same samples, nothing
//! but the page's own routes is served, a foreign `Host` is refused, and
//! Ctrl-C stops it.

mod common;

use std::io::{BufRead, BufReader, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

use common::{Viewer, command_in, finish, fresh_dir, wait_within};
use half::f16;
use pathtracer::image_io::read_image;

const SIZE: [&str; 4] = ["--width", "32", "--height", "24"];

fn scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/tutorial2_sphere.txt")
}

/// The film of a frame as f32 values (after its 16-byte header).
fn frame_values(body: &[u8]) -> Vec<f32> {
    body[16..]
        .chunks(2)
        .map(|b| f16::from_le_bytes([b[0], b[1]]).to_f32())
        .collect()
}

#[test]
fn the_page_and_a_converged_film_equal_to_renders_are_served() {
    let dir = fresh_dir("view-serves");
    let viewer = Viewer::start(&dir, &scene(), &[&SIZE[..], &["--spp", "16"]].concat());
    let page = viewer.get("/");
    assert_eq!(page.code, 200, "{}", page.head);
    assert!(page.text().contains("<canvas"), "{}", page.text());
    assert!(page.head.contains("text/html"));
    for (path, kind) in [("/view.js", "javascript"), ("/view.css", "text/css")] {
        let answer = viewer.get(path);
        assert_eq!(answer.code, 200, "{path}");
        assert!(answer.head.contains(kind), "{path}: {}", answer.head);
    }
    let status = viewer.wait_for("/status", Duration::from_secs(60), |a| {
        a.text().contains("\"done\": true")
    });
    assert!(status.text().contains("\"spp\": 16,"), "{}", status.text());
    let film = viewer.get("/film");
    assert_eq!(film.code, 200);
    assert_eq!(&film.body[..4], b"PTVF");
    assert_eq!(film.body.len(), 16 + 32 * 24 * 6);
    let width = u32::from_le_bytes(film.body[4..8].try_into().unwrap());
    let height = u32::from_le_bytes(film.body[8..12].try_into().unwrap());
    assert_eq!((width, height), (32, 24));
    // The passes added up to the image of one 16-spp render, to half precision.
    let ran = finish(command_in(
        &dir,
        &[
            &[
                "render",
                scene().to_str().unwrap(),
                "-o",
                "r.pfm",
                "--quiet",
                "--spp",
                "16",
            ],
            &SIZE[..],
        ]
        .concat(),
    ));
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    let rendered = read_image(&dir.join("r.pfm")).expect("the render");
    let served = frame_values(&film.body);
    let mut lit = 0;
    for (i, pixel) in rendered.pixels.iter().enumerate() {
        for (c, expected) in [pixel.r, pixel.g, pixel.b].into_iter().enumerate() {
            let got = served[i * 3 + c] as f64;
            assert!(
                (got - expected).abs() <= expected.abs() / 1024.0 + 1e-7,
                "pixel {i} channel {c}: served {got}, rendered {expected}"
            );
            lit += (expected > 0.01) as usize;
        }
    }
    assert!(lit > 100, "the test scene is dark: {lit} lit channels");
}

#[test]
fn only_the_pages_routes_are_served_and_only_to_our_own_host() {
    let dir = fresh_dir("view-refuses");
    let viewer = Viewer::start(&dir, &scene(), &SIZE);
    for path in [
        "/../../etc/passwd",
        "/%2e%2e/%2e%2e/etc/passwd",
        "/etc/passwd",
        "/view.js/../../Cargo.toml",
        "/testcases/tutorial2_sphere.txt",
    ] {
        let answer = viewer.get(path);
        assert_eq!(answer.code, 404, "{path}");
        assert!(!answer.text().contains("root:"), "{path}");
    }
    let port = viewer.port;
    for host in [
        format!("Host: evil.example:{port}\r\n"),
        format!("Host: 127.0.0.1.evil.example:{port}\r\n"),
        format!("Host: 127.0.0.1:{}\r\n", port.wrapping_add(1)),
        String::new(),
    ] {
        let answer = viewer.request(&format!("GET / HTTP/1.1\r\n{host}\r\n"));
        assert_eq!(answer.code, 403, "{host:?}");
        assert!(!answer.text().contains("<canvas"), "{host:?}");
    }
    let answer = viewer.request(&format!(
        "POST / HTTP/1.1\r\nHost: localhost:{port}\r\n\r\n"
    ));
    assert_eq!(answer.code, 405);
    let answer = viewer.request("\x16\x03\x01 not http\r\n\r\n");
    assert_eq!(answer.code, 400);
}

#[test]
fn events_announce_frames_and_ctrl_c_stops_the_server() {
    let dir = fresh_dir("view-events");
    let mut viewer = Viewer::start(&dir, &scene(), &[&SIZE[..], &["--spp", "100000"]].concat());
    let mut stream = TcpStream::connect(("127.0.0.1", viewer.port)).expect("connect");
    stream
        .set_read_timeout(Some(Duration::from_secs(30)))
        .expect("timeout");
    write!(
        stream,
        "GET /events HTTP/1.1\r\nHost: 127.0.0.1:{}\r\n\r\n",
        viewer.port
    )
    .expect("send");
    let mut lines = BufReader::new(stream).lines();
    let first = lines.next().expect("a line").expect("readable");
    assert!(first.starts_with("HTTP/1.1 200"), "{first}");
    // Events until one announces a frame after the first.
    let mut frames = Vec::new();
    while frames.len() < 2 {
        let line = lines.next().expect("an event").expect("readable");
        if let Some(json) = line.strip_prefix("data: ") {
            let frame = json
                .split("\"frame\": ")
                .nth(1)
                .and_then(|rest| rest.split(',').next())
                .and_then(|n| n.parse::<u64>().ok())
                .expect("a frame number");
            if frame > 0 {
                frames.push(frame);
            }
        }
    }
    assert!(frames[1] > frames[0], "{frames:?}");
    let signalled = Command::new("kill")
        .args(["-INT", &viewer.child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(signalled.success());
    let child = std::mem::replace(
        &mut viewer.child,
        Command::new("true").spawn().expect("a placeholder process"),
    );
    let ran = wait_within(child, Duration::from_secs(10));
    assert_eq!(ran.code, Some(130), "{}", ran.stderr);
    assert!(!ran.stderr.contains("panicked"), "{}", ran.stderr);
    assert!(TcpStream::connect(("127.0.0.1", viewer.port)).is_err());
}
