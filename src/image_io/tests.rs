//! Round trips, atomic replacement and hostile-input tests for image reading and writing.

use std::fs;
use std::path::{Path, PathBuf};

use super::*;

/// A fresh directory under the system temp dir, removed when dropped.
struct ScratchDirectory(PathBuf);

impl ScratchDirectory {
    fn new(name: &str) -> Self {
        let path =
            std::env::temp_dir().join(format!("pathtracer-image-io-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&path);
        fs::create_dir_all(&path).unwrap();
        ScratchDirectory(path)
    }

    fn join(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }

    /// Names of all entries, sorted.
    fn entries(&self) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(&self.0)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }
}

impl Drop for ScratchDirectory {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.0);
    }
}

/// A 7x5 image (odd width exercises BMP row padding) with distinct values in [0, 1].
fn gradient() -> Image {
    let (width, height) = (7, 5);
    let pixels = (0..width * height)
        .map(|i| {
            let (x, y) = ((i % width) as f64, (i / width) as f64);
            Color::new(x / 6.0, y / 4.0, ((x + y * 7.0) / 34.0 - 0.5).abs())
        })
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

/// Read values must be the truncated quantisation of the written ones.
fn assert_quantised(original: &Image, read: &Image) {
    assert_eq!((read.width, read.height), (original.width, original.height));
    for (a, b) in original.pixels.iter().zip(&read.pixels) {
        for (written, read) in [(a.r, b.r), (a.g, b.g), (a.b, b.b)] {
            let expected = (written.clamp(0.0, 1.0) * 255.0) as u8 as f64 / 255.0;
            assert_eq!(read, expected, "wrote {written}, read {read}");
            assert!(written - read < 1.0 / 255.0 + 1e-12 && read <= written + 1e-12);
        }
    }
}

#[test]
fn bmp_round_trip_within_quantisation() {
    let directory = ScratchDirectory::new("bmp-round-trip");
    let path = directory.join("gradient.bmp");
    let image = gradient();
    write_image(&path, &image, None).unwrap();
    assert_quantised(&image, &read_image(&path).unwrap());
}

#[test]
fn png_round_trip_within_quantisation() {
    let directory = ScratchDirectory::new("png-round-trip");
    let path = directory.join("gradient.PNG");
    let image = gradient();
    write_image(&path, &image, None).unwrap();
    assert_quantised(&image, &read_image(&path).unwrap());
}

#[test]
fn bmp_and_png_store_the_same_bytes_with_gamma() {
    let directory = ScratchDirectory::new("gamma");
    let image = gradient();
    write_image(&directory.join("a.bmp"), &image, Some(2.2)).unwrap();
    write_image(&directory.join("a.png"), &image, Some(2.2)).unwrap();
    let bmp = read_image(&directory.join("a.bmp")).unwrap();
    let png = read_image(&directory.join("a.png")).unwrap();
    assert_eq!(bmp, png);
    let expected = (0.5f64.powf(1.0 / 2.2) * 255.0) as u8 as f64 / 255.0;
    // Pixel (3, 0) has red 3/6 = 0.5.
    assert_eq!(bmp.pixels[3].r, expected);
}

#[test]
fn exposure_and_tone_curve_apply_to_8_bit_outputs_only() {
    let directory = ScratchDirectory::new("tonemap");
    let image = Image {
        width: 3,
        height: 1,
        pixels: vec![
            Color::gray(0.5),
            Color::gray(1.5),
            Color::new(3.0, 0.0, 0.25),
        ],
    };
    let encoding = Encoding {
        exposure: 1.0,
        tonemap: Tonemap::Reinhard,
        gamma: None,
    };
    write_encoded(&directory.join("t.png"), &image, &encoding).unwrap();
    let read = read_image(&directory.join("t.png")).unwrap();
    // 2 * 0.5 = 1 -> 1/2; 2 * 1.5 = 3 -> 3/4; (6, 0, 0.5) -> (6/7, 0, 1/3).
    let byte = |c: f64| (c * 255.0) as u8 as f64 / 255.0;
    assert_eq!(read.pixels[0], Color::gray(byte(0.5)));
    assert_eq!(read.pixels[1], Color::gray(byte(0.75)));
    assert_eq!(
        read.pixels[2],
        Color::new(byte(6.0 / 7.0), 0.0, byte(1.0 / 3.0))
    );
    for hdr in ["t.pfm", "t.exr"] {
        write_encoded(&directory.join(hdr), &image, &encoding).unwrap();
        assert_eq!(
            read_image(&directory.join(hdr)).unwrap(),
            image,
            "{hdr} stays linear"
        );
        assert!(is_hdr(&directory.join(hdr)));
    }
    assert!(!is_hdr(&directory.join("t.bmp")));
    let bad = Encoding {
        exposure: f64::NAN,
        ..encoding
    };
    assert!(write_encoded(&directory.join("bad.bmp"), &image, &bad).is_err());
}

#[test]
fn pfm_round_trip_is_exact_including_hdr_and_orientation() {
    let directory = ScratchDirectory::new("pfm-round-trip");
    let path = directory.join("radiance.pfm");
    let mut image = gradient();
    image.pixels[0] = Color::new(1234.5, -0.25, 1e-6);
    image.pixels[34] = Color::new(0.1, 0.2, 0.3);
    // Values representable in f32 survive exactly.
    for p in &mut image.pixels {
        *p = p.map(|c| c as f32 as f64);
    }
    write_image(&path, &image, Some(2.2)).unwrap();
    assert_eq!(read_image(&path).unwrap(), image);
}

#[test]
fn exr_round_trip_keeps_hdr_values_and_orientation() {
    let directory = ScratchDirectory::new("exr-round-trip");
    let path = directory.join("radiance.exr");
    let mut image = gradient();
    image.pixels[0] = Color::new(1234.5, 0.25, 1e-3);
    image.pixels[34] = Color::new(0.1, 0.2, 0.3);
    for p in &mut image.pixels {
        *p = p.map(|c| c as f32 as f64);
    }
    write_image(&path, &image, None).unwrap();
    assert_eq!(read_image(&path).unwrap(), image);
}

#[test]
fn display_bytes_survive_bmp_and_png_files_and_files_say_their_encoding() {
    let directory = ScratchDirectory::new("display-bytes");
    // Every byte value in every channel, in a 16x16 image of odd channel order.
    let pixels: Vec<[u8; 3]> = (0..=255u8)
        .map(|v| [v, 255 - v, v.rotate_left(3)])
        .collect();
    let bytes = DisplayImage {
        width: 16,
        height: 16,
        pixels,
    };
    for name in ["bytes.png", "bytes.bmp"] {
        let path = directory.join(name);
        bytes.write(&path).unwrap();
        let (image, encoding) = read_image_encoded(&path).unwrap();
        assert_eq!(encoding, PixelValues::Display, "{name}");
        assert_eq!(DisplayImage::from_image(&image), bytes, "{name}");
    }
    for name in ["radiance.pfm", "radiance.exr"] {
        let path = directory.join(name);
        write_image(&path, &gradient(), None).unwrap();
        assert_eq!(
            read_image_encoded(&path).unwrap().1,
            PixelValues::Linear,
            "{name}"
        );
    }
}

#[test]
fn display_image_of_a_render_is_what_the_png_writer_stores() {
    let directory = ScratchDirectory::new("display-of-render");
    let path = directory.join("render.png");
    let mut image = gradient();
    image.pixels[3] = Color::new(7.0, -1.0, f64::NAN);
    write_image(&path, &image, None).unwrap();
    let read = DisplayImage::from_image(&read_image(&path).unwrap());
    assert_eq!(read, DisplayImage::from_image(&image));
    assert_eq!(read.pixels[3], [255, 0, 0]);
}

#[test]
fn pfm_file_stores_rows_bottom_to_top() {
    let directory = ScratchDirectory::new("pfm-layout");
    let path = directory.join("two.pfm");
    let image = Image {
        width: 1,
        height: 2,
        pixels: vec![Color::gray(1.0), Color::gray(2.0)],
    };
    write_image(&path, &image, None).unwrap();
    let bytes = fs::read(&path).unwrap();
    let header = b"PF\n1 2\n-1.0\n";
    assert_eq!(&bytes[..header.len()], header);
    assert_eq!(bytes.len(), header.len() + 24);
    // The first stored row is the bottom one (value 2).
    assert_eq!(
        &bytes[header.len()..header.len() + 4],
        &2.0f32.to_le_bytes()
    );
}

fn pfm_bytes(header: &str, floats: &[f32], big_endian: bool) -> Vec<u8> {
    let mut bytes = header.as_bytes().to_vec();
    for f in floats {
        bytes.extend_from_slice(&if big_endian {
            f.to_be_bytes()
        } else {
            f.to_le_bytes()
        });
    }
    bytes
}

#[test]
fn pfm_reads_grayscale_and_big_endian() {
    let directory = ScratchDirectory::new("pfm-variants");
    let gray = directory.join("gray.pfm");
    fs::write(&gray, pfm_bytes("Pf\n2 1\n1.0\n", &[0.5, 3.0], true)).unwrap();
    let image = read_image(&gray).unwrap();
    assert_eq!(image.pixels, vec![Color::gray(0.5), Color::gray(3.0)]);

    let rgb = directory.join("rgb.pfm");
    fs::write(
        &rgb,
        pfm_bytes("PF 1 2 -2.5\n", &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0], false),
    )
    .unwrap();
    let image = read_image(&rgb).unwrap();
    assert_eq!(image.pixels[0], Color::new(4.0, 5.0, 6.0));
    assert_eq!(image.pixels[1], Color::new(1.0, 2.0, 3.0));
}

#[test]
fn malformed_pfm_files_give_errors_not_panics() {
    let directory = ScratchDirectory::new("pfm-malformed");
    let full = pfm_bytes("PF\n3 2\n-1.0\n", &[0.5; 18], false);
    let mut cases: Vec<(String, Vec<u8>)> = (0..full.len())
        .map(|n| (format!("truncated to {n} bytes"), full[..n].to_vec()))
        .collect();
    for header in [
        "PF\n0 2\n-1.0\n",
        "PF\n3 0\n-1.0\n",
        "PF\n-3 2\n-1.0\n",
        "PF\n99999999999999999999 2\n-1.0\n",
        "PF\n32768 32768\n-1.0\n",
        "PF\n40000 1\n-1.0\n",
        "PF\n3 2\n0.0\n",
        "PF\n3 2\nnan\n",
        "PF\n3 2\nabc\n",
        "PF\n3 2\n-1.0",
        "PX\n3 2\n-1.0\n",
        "PF\n3 2 1 -1.0\n",
    ] {
        cases.push((
            header.escape_debug().to_string(),
            pfm_bytes(header, &[0.5; 18], false),
        ));
    }
    let mut long_header = b"PF\n".to_vec();
    long_header.extend(std::iter::repeat_n(b'1', 1000));
    cases.push(("long header".to_string(), long_header));
    for (name, bytes) in cases {
        let path = directory.join("bad.pfm");
        fs::write(&path, &bytes).unwrap();
        // A truncation that leaves no "PF" signature falls to the LDR decoder; it must fail too.
        assert!(read_image(&path).is_err(), "accepted: {name}");
    }
}

#[test]
fn unsupported_extension_fails_without_touching_anything() {
    let directory = ScratchDirectory::new("bad-extension");
    let path = directory.join("image.tiff");
    fs::write(&path, b"keep me").unwrap();
    let error = write_image(&path, &gradient(), None).unwrap_err();
    assert!(error.contains(".bmp, .png, .pfm, .exr"), "{error}");
    assert!(write_image(&directory.join("noextension"), &gradient(), None).is_err());
    assert_eq!(fs::read(&path).unwrap(), b"keep me");
    assert_eq!(directory.entries(), vec!["image.tiff"]);
}

#[test]
fn writing_over_a_directory_fails_and_leaves_no_temporary() {
    let directory = ScratchDirectory::new("over-directory");
    let target = directory.join("occupied.bmp");
    fs::create_dir(&target).unwrap();
    fs::write(target.join("inside"), b"x").unwrap();
    assert!(write_image(&target, &gradient(), None).is_err());
    assert!(target.is_dir());
    assert_eq!(fs::read(target.join("inside")).unwrap(), b"x");
    assert_eq!(directory.entries(), vec!["occupied.bmp"]);
}

#[test]
fn failed_encoding_keeps_the_existing_destination() {
    let directory = ScratchDirectory::new("failed-encoding");
    let path = directory.join("keep.png");
    write_image(&path, &gradient(), None).unwrap();
    let before = fs::read(&path).unwrap();
    // Invalid gamma and inconsistent pixel count both fail before any file is made.
    assert!(write_image(&path, &gradient(), Some(-1.0)).is_err());
    let mut broken = gradient();
    broken.pixels.pop();
    assert!(write_image(&path, &broken, None).is_err());
    assert_eq!(fs::read(&path).unwrap(), before);
    assert_eq!(directory.entries(), vec!["keep.png"]);
}

#[test]
fn successful_write_replaces_file_leaves_no_temporary_and_creates_parents() {
    let directory = ScratchDirectory::new("replace");
    let path = directory.join("nested/deeper/out.bmp");
    write_image(&path, &gradient(), None).unwrap();
    let mut black = gradient();
    black.pixels.fill(Color::BLACK);
    write_image(&path, &black, None).unwrap();
    assert!(
        read_image(&path)
            .unwrap()
            .pixels
            .iter()
            .all(Color::is_black)
    );
    let names: Vec<_> = fs::read_dir(path.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, vec!["out.bmp"]);
}

#[test]
fn reading_garbage_or_missing_files_fails() {
    let directory = ScratchDirectory::new("garbage");
    let path = directory.join("noise.png");
    fs::write(&path, b"\x89PNG\r\n\x1a\nnot really").unwrap();
    assert!(read_image(&path).is_err());
    fs::write(&path, b"").unwrap();
    assert!(read_image(&path).is_err());
    assert!(read_image(Path::new("/nonexistent/dir/x.bmp")).is_err());
}

#[test]
fn reads_the_reference_bmp() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../shared/reference/cambrian-pathtracer/output/scene01.bmp"
    ));
    if !path.exists() {
        println!("skipped: ../shared not found");
        return;
    }
    let image = read_image(path).unwrap();
    assert_eq!((image.width, image.height), (256, 256));
    assert_eq!(image.pixels.len(), 256 * 256);
    assert!(image.pixels.iter().any(|p| !p.is_black()));
    assert!(
        image
            .pixels
            .iter()
            .all(|p| (0.0..=1.0).contains(&p.max_component()))
    );
}

#[test]
fn pfm_with_extra_bytes_is_rejected() {
    let directory = ScratchDirectory::new("pfm-extra");
    let path = directory.join("extra.pfm");
    let mut bytes = pfm_bytes("PF\n1 1\n-1.0\n", &[1.0, 2.0, 3.0], false);
    assert!(pfm::decode(&bytes).is_ok());
    bytes.push(b'\n');
    fs::write(&path, &bytes).unwrap();
    assert!(read_image(&path).is_err());
}
