//! `pathtracer view --display HOST:PORT`: a stand-in for the tev viewer on
//! a loopback port receives the image created at the render's size and
//! tiles that end as the very image `render` writes; a display nobody
//! listens at is refused before serving.

mod common;

use std::io::Read;
use std::net::{TcpListener, TcpStream};
use std::path::Path;
use std::time::{Duration, Instant};

use common::{Viewer, command_in, finish, fresh_dir};
use pathtracer::image_io::read_image;

const SIZE: [&str; 6] = ["--width", "160", "--height", "130", "--spp", "8"];

fn scene() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/tutorial2_sphere.txt")
}

/// The next packet (type and payload), or `None` when nothing comes.
fn next_packet(stream: &mut TcpStream) -> Option<(u8, Vec<u8>)> {
    let mut length = [0u8; 4];
    stream.read_exact(&mut length).ok()?;
    let length = u32::from_le_bytes(length) as usize;
    assert!((5..1 << 28).contains(&length), "length {length}");
    let mut rest = vec![0u8; length - 4];
    stream.read_exact(&mut rest).expect("a whole packet");
    Some((rest[0], rest[1..].to_vec()))
}

/// Reads a zero-ended string at `at`, moving past it.
fn string(bytes: &[u8], at: &mut usize) -> String {
    let end = bytes[*at..]
        .iter()
        .position(|&b| b == 0)
        .expect("a zero byte")
        + *at;
    let text = String::from_utf8(bytes[*at..end].to_vec()).expect("UTF-8");
    *at = end + 1;
    text
}

fn int(bytes: &[u8], at: &mut usize) -> i64 {
    let value = i32::from_le_bytes(bytes[*at..*at + 4].try_into().unwrap());
    *at += 4;
    value as i64
}

#[test]
fn the_film_reaches_a_tev_listener_as_the_image_render_writes() {
    let dir = fresh_dir("view-tev");
    let listener = TcpListener::bind("127.0.0.1:0").expect("a loopback port");
    let address = listener.local_addr().expect("address").to_string();
    let viewer = Viewer::start(
        &dir,
        &scene(),
        &[&SIZE[..], &["--display", &address]].concat(),
    );
    let (mut stream, _) = listener.accept().expect("view connects");
    stream
        .set_read_timeout(Some(Duration::from_secs(2)))
        .expect("timeout");
    let (kind, create) = next_packet(&mut stream).expect("a first packet");
    assert_eq!(kind, 4, "create image first");
    let mut at = 1;
    let name = string(&create, &mut at);
    assert!(name.contains("tutorial2_sphere.txt"), "{name}");
    let (width, height, channels) = (
        int(&create, &mut at),
        int(&create, &mut at),
        int(&create, &mut at),
    );
    assert_eq!((width, height, channels), (160, 130, 3));
    let names: Vec<String> = (0..3).map(|_| string(&create, &mut at)).collect();
    assert_eq!(names, ["R", "G", "B"]);
    // Tiles until the render is done and nothing more comes.
    let mut pixels = vec![f32::NAN; 160 * 130 * 3];
    let started = Instant::now();
    let mut tiles = 0;
    loop {
        let Some((kind, update)) = next_packet(&mut stream) else {
            let done = viewer.get("/status").text().contains("\"done\": true");
            if done && tiles > 0 {
                break;
            }
            assert!(
                started.elapsed() < Duration::from_secs(60),
                "no end of tiles"
            );
            continue;
        };
        assert_eq!(kind, 6, "only updates after the create");
        let mut at = 1;
        assert_eq!(string(&update, &mut at), name);
        assert_eq!(int(&update, &mut at), 3);
        for channel in ["R", "G", "B"] {
            assert_eq!(string(&update, &mut at), channel);
        }
        let (x, y, w, h) = (
            int(&update, &mut at) as usize,
            int(&update, &mut at) as usize,
            int(&update, &mut at) as usize,
            int(&update, &mut at) as usize,
        );
        assert!(w <= 128 && h <= 128 && x + w <= 160 && y + h <= 130);
        let offsets_and_strides: Vec<i64> = (0..6)
            .map(|i| i64::from_le_bytes(update[at + 8 * i..at + 8 * i + 8].try_into().unwrap()))
            .collect();
        assert_eq!(offsets_and_strides, [0, 1, 2, 3, 3, 3]);
        at += 48;
        assert_eq!(update.len() - at, w * h * 3 * 4);
        for row in 0..h {
            for column in 0..w {
                for c in 0..3 {
                    let i = at + ((row * w + column) * 3 + c) * 4;
                    pixels[((y + row) * 160 + x + column) * 3 + c] =
                        f32::from_le_bytes(update[i..i + 4].try_into().unwrap());
                }
            }
        }
        tiles += 1;
    }
    assert!(tiles >= 4, "{tiles} tiles: 160x130 needs 4 per image");
    let ran = finish(command_in(
        &dir,
        &[
            &[
                "render",
                scene().to_str().unwrap(),
                "-o",
                "r.pfm",
                "--quiet",
            ],
            &SIZE[..],
        ]
        .concat(),
    ));
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    let rendered = read_image(&dir.join("r.pfm")).expect("the render");
    for (i, pixel) in rendered.pixels.iter().enumerate() {
        let expected = [pixel.r as f32, pixel.g as f32, pixel.b as f32];
        assert_eq!(pixels[i * 3..i * 3 + 3], expected, "pixel {i}");
    }
}

#[test]
fn a_display_nobody_listens_at_is_refused_before_serving() {
    let dir = fresh_dir("view-tev-refused");
    // A port just closed: nothing listens there.
    let port = TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a port")
        .port();
    let address = format!("127.0.0.1:{port}");
    let scene = scene();
    let args = ["view", scene.to_str().unwrap(), "--display", &address];
    let ran = finish(command_in(&dir, &args));
    assert_eq!(ran.code, Some(1), "{}", ran.stderr);
    assert!(
        ran.stderr.contains("cannot connect to tev"),
        "{}",
        ran.stderr
    );
    assert!(!ran.stdout.contains("http://"), "{}", ran.stdout);
}
