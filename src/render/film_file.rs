//! Film files: a [`Film`]'s raw sums in an OpenEXR file, exact, with the
//! [`JobHeader`] of the part as header attributes, so that parts rendered
//! by separate processes merge to the bytes of one render.
//!
//! One layer of the image's full size, ZIP-compressed, every channel of
//! 32-bit unsigned integers: a wide sum is split into words, word 0 the
//! least significant. Per pixel:
//! `sum.R.0`..`sum.R.3` (and `G`, `B`: the camera samples' fixed-point sum,
//! an `i128` with 32 fractional bits, two's complement), `squares.0`..`3`
//! (the sum of squared luminances, `u128`, 32 fractional bits), `samples`,
//! `dropped`, `fireflies`, `saturated`, `splat.R.0`..`splat.R.1` (and `G`,
//! `B`: light tracing's sums, `u64`, 20 fractional bits), and `R`, `G`, `B`
//! (32-bit floats: the part's own image, for a viewer). The attributes
//! `pathtracer.<field>` hold the header's fields as text, and
//! `pathtracer.light_subpaths` the number of light subpaths. Pixels outside
//! a part's crop hold no camera samples, but every pixel holds the splats
//! of the part's light subpaths, wherever they landed.

use std::collections::HashMap;
use std::io::Cursor;
use std::path::Path;

use exr::prelude::{
    AnyChannel, AnyChannels, AttributeValue, Encoding, FlatSamples, Image, Layer, LayerAttributes,
    ReadChannels, ReadLayers, SmallVec, Text, WritableImage, read,
};

use exr::meta::MetaData;

use crate::film::{Film, PixelSum};
use crate::fixed_sum::{FixedColor, FixedSquares};
use crate::limits::{MemoryBudget, read_within};
use crate::render::job::JobHeader;

/// Written in every film file; a reader refuses other versions.
const FORMAT_VERSION: &str = "1";
const ATTRIBUTE_PREFIX: &str = "pathtracer.";
const CHANNEL_NAMES: [&str; 3] = ["R", "G", "B"];

/// The bytes of the `.exr` file of `film` and `header` (`path` names it in
/// messages).
pub fn encode_film(path: &Path, film: &Film, header: &JobHeader) -> Result<Vec<u8>, String> {
    let mut channels: Vec<AnyChannel<FlatSamples>> = Vec::new();
    let mut words = |name: String, count: usize, word: &dyn Fn(usize, usize) -> u32| {
        for index in 0..count {
            let values = (0..film.pixels.len()).map(|p| word(p, index)).collect();
            let name = if count == 1 {
                name.clone()
            } else {
                format!("{name}.{index}")
            };
            channels.push(AnyChannel::new(name.as_str(), FlatSamples::U32(values)));
        }
    };
    let pixels = &film.pixels;
    for (channel, name) in CHANNEL_NAMES.iter().enumerate() {
        words(format!("sum.{name}"), 4, &|p, w| {
            word_of(pixels[p].sum.channels[channel] as u128, w)
        });
        words(format!("splat.{name}"), 2, &|p, w| {
            word_of(film.splats[p][channel] as u128, w)
        });
    }
    words("squares".to_string(), 4, &|p, w| {
        word_of(pixels[p].sum_of_squares.total, w)
    });
    words("samples".to_string(), 1, &|p, _| pixels[p].samples);
    words("dropped".to_string(), 1, &|p, _| pixels[p].dropped);
    words("fireflies".to_string(), 1, &|p, _| pixels[p].fireflies);
    words("saturated".to_string(), 1, &|p, _| pixels[p].saturated);
    let preview = film.to_image();
    for (channel, name) in CHANNEL_NAMES.iter().enumerate() {
        let values = preview
            .pixels
            .iter()
            .map(|c| [c.r, c.g, c.b][channel] as f32)
            .collect();
        channels.push(AnyChannel::new(*name, FlatSamples::F32(values)));
    }

    let mut attributes = LayerAttributes::named("film");
    let mut fields = header.fields();
    fields.push(("version", FORMAT_VERSION.to_string()));
    fields.push(("light_subpaths", film.light_paths.to_string()));
    fields.push(("splats_dropped", film.splats_dropped.to_string()));
    for (name, value) in fields {
        attributes.other.insert(
            text(&format!("{ATTRIBUTE_PREFIX}{name}")),
            AttributeValue::Text(text(&value)),
        );
    }
    let layer = Layer::new(
        (film.width, film.height),
        attributes,
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(SmallVec::from_vec(channels)),
    );
    let mut bytes = Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        .to_buffered(&mut bytes)
        .map_err(|e| format!("{}: cannot encode the film: {e}", path.display()))?;
    Ok(bytes.into_inner())
}

/// Reads a film file written from [`encode_film`], within the default
/// memory budget (see [`read_film_within`]).
pub fn read_film(path: &Path) -> Result<(Film, JobHeader), String> {
    read_film_within(path, MemoryBudget::default())
}

/// Reads a film file written from [`encode_film`]: a regular file of at
/// most `budget` bytes (through [`read_within`], so that a pipe or a device
/// is refused, never waited on), whose header's size fits `budget` before
/// anything is decoded.
pub fn read_film_within(path: &Path, budget: MemoryBudget) -> Result<(Film, JobHeader), String> {
    let shown = path.display();
    let bytes = read_within(path, budget.bytes, "the memory budget, --max-memory")?;
    let meta = MetaData::read_from_buffered(Cursor::new(&bytes), false)
        .map_err(|e| format!("{shown}: not a readable film file: {e}"))?;
    for header in meta.headers.iter() {
        let size = header.layer_size;
        budget
            .check_image(size.x() as u64, size.y() as u64)
            .map_err(|e| format!("{shown}: {e}"))?;
    }
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_buffered(Cursor::new(bytes))
        .map_err(|e| format!("{shown}: not a readable film file: {e}"))?;
    let layer = image.layer_data;
    let attributes: HashMap<String, String> = layer
        .attributes
        .other
        .iter()
        .filter_map(|(name, value)| match value {
            AttributeValue::Text(value) => Some((name.to_string(), value.to_string())),
            _ => None,
        })
        .collect();
    let field = |name: &str| {
        attributes
            .get(&format!("{ATTRIBUTE_PREFIX}{name}"))
            .cloned()
    };
    match field("version") {
        Some(version) if version == FORMAT_VERSION => {}
        Some(version) => {
            return Err(format!(
                "{shown}: film format version {version}, this pathtracer reads {FORMAT_VERSION}"
            ));
        }
        None => {
            return Err(format!(
                "{shown}: not a pathtracer film (no version attribute)"
            ));
        }
    }
    let header = JobHeader::from_fields(field).map_err(|e| format!("{shown}: {e}"))?;
    let (width, height) = (layer.size.x(), layer.size.y());
    if (width, height) != (header.width as usize, header.height as usize) {
        return Err(format!(
            "{shown}: the film is {width}x{height}, its header says {}x{}",
            header.width, header.height
        ));
    }
    let light_paths = field("light_subpaths")
        .and_then(|v| v.parse::<u64>().ok())
        .ok_or_else(|| format!("{shown}: no readable 'light_subpaths' attribute"))?;
    let splats_dropped = match field("splats_dropped") {
        None => 0,
        Some(v) => v
            .parse::<u64>()
            .map_err(|_| format!("{shown}: 'splats_dropped' is not a count: '{v}'"))?,
    };
    let count = width * height;
    let channel = |name: &str| -> Result<&[u32], String> {
        let found = layer
            .channel_data
            .list
            .iter()
            .find(|c| c.name.to_string() == name)
            .ok_or_else(|| format!("{shown}: no channel '{name}'"))?;
        match &found.sample_data {
            FlatSamples::U32(values) if values.len() == count => Ok(values),
            _ => Err(format!(
                "{shown}: channel '{name}' is not {count} 32-bit integers"
            )),
        }
    };
    let wide = |name: &str, words: usize| -> Result<Vec<u128>, String> {
        let mut values = vec![0u128; count];
        for word in 0..words {
            for (value, &part) in values.iter_mut().zip(channel(&format!("{name}.{word}"))?) {
                *value |= (part as u128) << (32 * word);
            }
        }
        Ok(values)
    };
    let mut film = Film::try_new(width, height)?;
    let mut sums = Vec::new();
    let mut splats = Vec::new();
    for name in CHANNEL_NAMES {
        sums.push(wide(&format!("sum.{name}"), 4)?);
        splats.push(wide(&format!("splat.{name}"), 2)?);
    }
    let squares = wide("squares", 4)?;
    let samples = channel("samples")?;
    let dropped = channel("dropped")?;
    let fireflies = channel("fireflies")?;
    let saturated = channel("saturated")?;
    for (index, pixel) in film.pixels.iter_mut().enumerate() {
        *pixel = PixelSum {
            sum: FixedColor {
                channels: [0, 1, 2].map(|c| sums[c][index] as i128),
            },
            sum_of_squares: FixedSquares {
                total: squares[index],
            },
            samples: samples[index],
            dropped: dropped[index],
            fireflies: fireflies[index],
            saturated: saturated[index],
            converged: false,
        };
        film.splats[index] = [0, 1, 2].map(|c| splats[c][index] as u64);
    }
    film.light_paths = light_paths;
    film.splats_dropped = splats_dropped;
    Ok((film, header))
}

/// Word `index` (32 bits, 0 the least significant) of `value`.
fn word_of(value: u128, index: usize) -> u32 {
    (value >> (32 * index)) as u32
}

/// EXR text holds Latin-1 bytes: other characters become `?`.
fn text(value: &str) -> Text {
    let latin: String = value
        .chars()
        .map(|c| if (c as u32) < 256 { c } else { '?' })
        .collect();
    Text::new_or_none(latin).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Color;
    use crate::film::SplatSums;
    use crate::render::job::Crop;

    fn header(width: u32, height: u32) -> JobHeader {
        JobHeader::from_fields(|name| {
            Some(match name {
                "scene" => "tést.txt".to_string(),
                "clamp" => "none".to_string(),
                "light_paths" => "true".to_string(),
                "width" => width.to_string(),
                "height" => height.to_string(),
                "crop" => Crop::full(width, height).to_string(),
                "samples" => "4..12".to_string(),
                _ => "7".to_string(),
            })
        })
        .unwrap()
    }

    #[test]
    fn a_film_survives_its_file_bit_for_bit() {
        let mut film = Film::new(3, 2);
        film.pixels[0].add(Color::new(1e-9, 123456.75, -2.5), None);
        film.pixels[0].add(Color::new(f64::NAN, 0.0, 0.0), None);
        film.pixels[4].add(Color::gray(1e300), None);
        film.pixels[5].add(Color::new(0.1, 0.2, 0.3), Some(0.1));
        let splats = SplatSums::new(6);
        splats.add(2, Color::new(3.0, 1e6, 0.001));
        splats.add_light_paths(5_000_000_000);
        splats.add_to(&mut film);
        let dir = std::env::temp_dir().join(format!("film-file-{}", std::process::id()));
        let path = dir.join("part.exr");
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(&path, encode_film(&path, &film, &header(3, 2)).unwrap()).unwrap();
        let (read_back, read_header) = read_film(&path).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(read_header, header(3, 2));
        assert_eq!(read_header.scene, "tést.txt");
        assert_eq!(read_back.splats, film.splats);
        assert_eq!(read_back.light_paths, film.light_paths);
        for (a, b) in read_back.pixels.iter().zip(&film.pixels) {
            assert_eq!((a.sum, a.sum_of_squares), (b.sum, b.sum_of_squares));
            assert_eq!(
                (a.samples, a.dropped, a.fireflies, a.saturated),
                (b.samples, b.dropped, b.fireflies, b.saturated)
            );
        }
        assert_eq!(read_back.to_image(), film.to_image());
    }

    #[test]
    fn a_plain_exr_image_is_not_a_film() {
        let dir = std::env::temp_dir().join(format!("film-plain-{}", std::process::id()));
        let path = dir.join("plain.exr");
        let image = crate::image_io::Image {
            width: 2,
            height: 2,
            pixels: vec![Color::gray(0.5); 4],
        };
        crate::image_io::write_image(&path, &image, None).unwrap();
        let error = read_film(&path).unwrap_err();
        let _ = std::fs::remove_dir_all(&dir);
        assert!(error.contains("not a pathtracer film"), "{error}");
    }
}
