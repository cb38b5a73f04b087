//! `view --display HOST:PORT`: the film streamed to the tev image viewer
//! over its TCP protocol, as pbrt-v4's `--display-server` does.
//!
//! The protocol (tev's IPC, version 3 of its update packet): each packet is
//! its total length as a little-endian u32 (these 4 bytes included), a type
//! byte, then the payload; strings end with a zero byte, integers are
//! little-endian. Used here:
//! - close image (type 2): the name;
//! - create image (type 4): grab focus (a byte), the name, width, height
//!   and channel count (i32), then each channel's name;
//! - update image (type 6): grab focus, the name, the channel count (i32),
//!   each channel's name, the tile's x, y, width and height (i32), each
//!   channel's offset and then each channel's stride (i64, in values),
//!   then the tile's values (f32), row by row.
//!
//! Tiles are at most [`TILE`] pixels square, so that no packet is large.

use std::io::Write;
use std::net::{TcpStream, ToSocketAddrs};
use std::sync::Arc;
use std::time::{Duration, Instant};

use crate::image_io::Image;

use super::board::Board;

/// The side of the tiles an image is sent in.
pub const TILE: usize = 128;

/// The least time between two images sent.
pub const MIN_INTERVAL: Duration = Duration::from_millis(250);

const CHANNELS: [&str; 3] = ["R", "G", "B"];

/// A packet of `kind` whose payload `fill` writes.
fn packet(kind: u8, fill: impl FnOnce(&mut Vec<u8>)) -> Vec<u8> {
    let mut bytes = vec![0, 0, 0, 0, kind];
    fill(&mut bytes);
    let length = bytes.len() as u32;
    bytes[..4].copy_from_slice(&length.to_le_bytes());
    bytes
}

fn put_string(bytes: &mut Vec<u8>, text: &str) {
    // A zero byte inside would end the string early: none in names here.
    bytes.extend(text.bytes().filter(|&b| b != 0));
    bytes.push(0);
}

pub fn close_image(name: &str) -> Vec<u8> {
    packet(2, |bytes| put_string(bytes, name))
}

pub fn create_image(name: &str, width: usize, height: usize) -> Vec<u8> {
    packet(4, |bytes| {
        bytes.push(0);
        put_string(bytes, name);
        for value in [width, height, CHANNELS.len()] {
            bytes.extend_from_slice(&(value as i32).to_le_bytes());
        }
        for channel in CHANNELS {
            put_string(bytes, channel);
        }
    })
}

/// The update packets of every tile of `image`.
pub fn update_image(name: &str, image: &Image) -> Vec<Vec<u8>> {
    let mut packets = Vec::new();
    for y0 in (0..image.height).step_by(TILE) {
        for x0 in (0..image.width).step_by(TILE) {
            let (width, height) = (TILE.min(image.width - x0), TILE.min(image.height - y0));
            packets.push(packet(6, |bytes| {
                bytes.push(0);
                put_string(bytes, name);
                bytes.extend_from_slice(&(CHANNELS.len() as i32).to_le_bytes());
                for channel in CHANNELS {
                    put_string(bytes, channel);
                }
                for value in [x0, y0, width, height] {
                    bytes.extend_from_slice(&(value as i32).to_le_bytes());
                }
                for offset in 0..CHANNELS.len() as i64 {
                    bytes.extend_from_slice(&offset.to_le_bytes());
                }
                for _ in CHANNELS {
                    bytes.extend_from_slice(&(CHANNELS.len() as i64).to_le_bytes());
                }
                for y in y0..y0 + height {
                    for pixel in &image.pixels[y * image.width + x0..y * image.width + x0 + width] {
                        for value in [pixel.r, pixel.g, pixel.b] {
                            bytes.extend_from_slice(&(value as f32).to_le_bytes());
                        }
                    }
                }
            }));
        }
    }
    packets
}

/// Connects to tev at `address` (`HOST:PORT`).
pub fn connect(address: &str) -> Result<TcpStream, String> {
    let failed = |why: String| {
        format!(
            "--display {address}: cannot connect to tev ({why}; tev listens on 127.0.0.1:14158 by default)"
        )
    };
    let targets = address
        .to_socket_addrs()
        .map_err(|e| failed(e.to_string()))?;
    let mut last = "no address".to_string();
    for target in targets {
        match TcpStream::connect_timeout(&target, Duration::from_secs(5)) {
            Ok(stream) => {
                let _ = stream.set_write_timeout(Some(Duration::from_secs(10)));
                return Ok(stream);
            }
            Err(e) => last = e.to_string(),
        }
    }
    Err(failed(last))
}

/// Starts the thread that sends each new image on `board` to tev over
/// `stream`, as the image `name`; it stops (with a warning) when tev goes.
pub fn start(board: Arc<Board>, mut stream: TcpStream, name: String) -> Result<(), String> {
    std::thread::Builder::new()
        .name("preview-tev".to_string())
        .spawn(move || {
            let (mut seen, mut sent_frame, mut size) = (0, 0, None);
            loop {
                let Some(posted) = board.after(seen, Duration::from_secs(3600)) else {
                    continue;
                };
                seen = posted.generation;
                let (Some(image), frame) = (posted.image, posted.status.frame) else {
                    continue;
                };
                if frame == sent_frame {
                    continue;
                }
                sent_frame = frame;
                let started = Instant::now();
                let mut packets = Vec::new();
                if size != Some((image.width, image.height)) {
                    if size.is_some() {
                        packets.push(close_image(&name));
                    }
                    packets.push(create_image(&name, image.width, image.height));
                    size = Some((image.width, image.height));
                }
                packets.extend(update_image(&name, &image));
                if let Err(e) = packets.iter().try_for_each(|p| stream.write_all(p)) {
                    crate::stderr_line!("warning: tev went away ({e}): no longer streaming to it");
                    return;
                }
                std::thread::sleep(MIN_INTERVAL.saturating_sub(started.elapsed()));
            }
        })
        .map(|_| ())
        .map_err(|e| format!("cannot start the tev thread: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Color;

    fn i32_at(bytes: &[u8], at: usize) -> i32 {
        i32::from_le_bytes(bytes[at..at + 4].try_into().unwrap())
    }

    #[test]
    fn packets_carry_their_length_type_and_fields() {
        let create = create_image("a", 300, 2);
        assert_eq!(i32_at(&create, 0) as usize, create.len());
        assert_eq!(create[4], 4);
        assert_eq!(&create[5..8], &[0, b'a', 0]);
        assert_eq!(
            (i32_at(&create, 8), i32_at(&create, 12), i32_at(&create, 16)),
            (300, 2, 3)
        );
        assert_eq!(&create[20..], b"R\0G\0B\0");
        let close = close_image("a");
        assert_eq!(close, [7, 0, 0, 0, 2, b'a', 0]);
    }

    #[test]
    fn updates_tile_the_image_with_interleaved_values() {
        let image = Image {
            width: 130,
            height: 1,
            pixels: (0..130).map(|i| Color::new(i as f64, 0.5, -1.0)).collect(),
        };
        let tiles = update_image("a", &image);
        assert_eq!(tiles.len(), 2);
        let second = &tiles[1];
        assert_eq!(second[4], 6);
        // grab focus, "a\0", 3 channels, "R\0G\0B\0", then x, y, width, height.
        let at = 5 + 1 + 2 + 4 + 6;
        let field = |i: usize| i32_at(second, at + 4 * i);
        assert_eq!((field(0), field(1), field(2), field(3)), (128, 0, 2, 1));
        let values = at + 16 + 48;
        assert_eq!(second.len(), values + 2 * 3 * 4);
        let value = |i: usize| {
            f32::from_le_bytes(
                second[values + 4 * i..values + 4 * i + 4]
                    .try_into()
                    .unwrap(),
            )
        };
        assert_eq!(
            [value(0), value(1), value(2), value(3)],
            [128.0, 0.5, -1.0, 129.0]
        );
    }
}
