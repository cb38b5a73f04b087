//! The page's save button: the image on the board written to the output
//! path with `render`'s rules (the file reserved, refused when it is one the
//! scene reads, encoded whole and renamed into place), in the exposure,
//! tone curve and gamma the page shows.

use std::path::{Path, PathBuf};

use crate::image_io::{
    Encoding, Image, PendingFile, Tonemap, commit_together, encode_image, refuse_inputs,
};

/// Writes `image` to `output` as `encoding` says (8-bit outputs only;
/// `.pfm` and `.exr` stay linear), unless `output` is one of `inputs`.
pub fn save(
    image: &Image,
    output: &Path,
    encoding: &Encoding,
    inputs: &[PathBuf],
) -> Result<(), String> {
    encoding.check()?;
    let mut file = PendingFile::reserve(output)?;
    let named: Vec<(&str, &Path)> = inputs
        .iter()
        .map(|input| ("a file the scene reads", input.as_path()))
        .collect();
    refuse_inputs(&[&file], &named)?;
    file.write(&encode_image(output, image, encoding)?)?;
    commit_together(vec![file])
}

/// The encoding a save request asks for: `exposure=EV&tonemap=NAME&gamma=G`
/// (each optional; an empty gamma is none).
pub fn encoding_of(query: &str) -> Result<Encoding, String> {
    let mut encoding = Encoding::default();
    for pair in query.split('&').filter(|p| !p.is_empty()) {
        let (name, value) = pair.split_once('=').unwrap_or((pair, ""));
        match name {
            "exposure" => {
                encoding.exposure = value
                    .parse::<f64>()
                    .ok()
                    .filter(|e| e.is_finite() && e.abs() <= 100.0)
                    .ok_or("exposure: a number from -100 to 100")?;
            }
            "tonemap" => {
                encoding.tonemap =
                    Tonemap::from_name(value).ok_or("tonemap: none, reinhard or aces")?;
            }
            "gamma" if value.is_empty() => encoding.gamma = None,
            "gamma" => {
                encoding.gamma = Some(
                    value
                        .parse::<f64>()
                        .ok()
                        .filter(|g| g.is_finite() && *g > 0.0 && *g <= 10.0)
                        .ok_or("gamma: a number above 0, at most 10")?,
                );
            }
            _ => return Err("only exposure, tonemap and gamma".to_string()),
        }
    }
    Ok(encoding)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_query_gives_its_encoding_and_nothing_else_is_taken() {
        let encoding = encoding_of("exposure=-1.5&tonemap=aces&gamma=2.2").expect("valid");
        assert_eq!(encoding.exposure, -1.5);
        assert_eq!(encoding.tonemap, Tonemap::Aces);
        assert_eq!(encoding.gamma, Some(2.2));
        assert_eq!(encoding_of("gamma=").expect("valid"), Encoding::default());
        assert_eq!(encoding_of("").expect("valid"), Encoding::default());
        for bad in [
            "exposure=nan",
            "exposure=1e9",
            "tonemap=film",
            "gamma=0",
            "path=/etc/passwd",
        ] {
            assert!(encoding_of(bad).is_err(), "{bad}");
        }
    }
}
