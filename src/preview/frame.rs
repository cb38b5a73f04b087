//! The film as the page receives it: linear RGB in half floats, so that the
//! page applies exposure, tone curve and gamma itself and changing them
//! never re-renders.
//!
//! Layout (little-endian): the 4 bytes `PTVF`, the width, the height and
//! the frame number (see [`super::status::Status::frame`]) as u32, then `width * height` pixels of three IEEE 754 half floats (red,
//! green, blue), row 0 at the top. Values above 65504 become infinity,
//! which every tone curve and the clip handle.

use half::f16;

use crate::image_io::Image;

pub const MAGIC: &[u8; 4] = b"PTVF";

/// Bytes before the pixels.
pub const HEADER_BYTES: usize = 16;

/// The bytes of `image`, frame number `number`, in the layout above.
pub fn encode(image: &Image, number: u64) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(HEADER_BYTES + image.pixels.len() * 6);
    bytes.extend_from_slice(MAGIC);
    bytes.extend_from_slice(&(image.width as u32).to_le_bytes());
    bytes.extend_from_slice(&(image.height as u32).to_le_bytes());
    bytes.extend_from_slice(&(number as u32).to_le_bytes());
    for pixel in &image.pixels {
        for channel in [pixel.r, pixel.g, pixel.b] {
            bytes.extend_from_slice(&f16::from_f64(channel).to_le_bytes());
        }
    }
    bytes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Color;

    #[test]
    fn the_layout_holds_the_size_and_each_channel_as_a_half_float() {
        let image = Image {
            width: 2,
            height: 1,
            pixels: vec![Color::new(1.0, 0.5, 0.0), Color::new(-2.0, 1e6, 0.25)],
        };
        let bytes = encode(&image, 7);
        assert_eq!(bytes.len(), HEADER_BYTES + 2 * 6);
        assert_eq!(&bytes[..4], MAGIC);
        assert_eq!(u32::from_le_bytes(bytes[4..8].try_into().unwrap()), 2);
        assert_eq!(u32::from_le_bytes(bytes[8..12].try_into().unwrap()), 1);
        assert_eq!(u32::from_le_bytes(bytes[12..16].try_into().unwrap()), 7);
        let halves: Vec<u16> = bytes[HEADER_BYTES..]
            .chunks(2)
            .map(|b| u16::from_le_bytes([b[0], b[1]]))
            .collect();
        // 1.0, 0.5, 0, -2, +inf, 0.25 as IEEE 754 binary16.
        assert_eq!(halves, [0x3c00, 0x3800, 0x0000, 0xc000, 0x7c00, 0x3400]);
    }
}
