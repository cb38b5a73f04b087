//! How 8-bit outputs encode radiance (`--gamma`, `--exposure`, `--tonemap`),
//! and the hint after an image written linear.

use std::path::Path;

use clap::Args;
use pathtracer::image_io::{Encoding, Tonemap, is_hdr};

/// How 8-bit outputs (BMP, PNG) encode radiance, shared by `render` and
/// `convert`; PFM and EXR outputs stay linear.
#[derive(Args, Clone)]
pub struct EncodingOptions {
    /// Gamma for 8-bit output (2.2 for smallpt-style images; default: none,
    /// as the PA framework writer).
    #[arg(long)]
    pub gamma: Option<f64>,
    /// Exposure for 8-bit output in stops: values are multiplied by
    /// 2^EXPOSURE before the tone curve (default 0).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub exposure: f64,
    /// Tone curve for 8-bit output, per channel: `none` (the default:
    /// clipped at 1), `reinhard` (c / (1 + c)) or `aces` (Narkowicz's fit).
    #[arg(long, default_value = "none", value_parser = parse_tonemap)]
    pub tonemap: Tonemap,
}

impl EncodingOptions {
    pub fn encoding(&self) -> Encoding {
        Encoding {
            exposure: self.exposure,
            tonemap: self.tonemap,
            gamma: self.gamma,
        }
    }
}

fn parse_tonemap(name: &str) -> Result<Tonemap, String> {
    Tonemap::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Tonemap::ALL.iter().map(|t| t.name()).collect();
        format!("unknown tone curve '{name}' (one of: {})", names.join(", "))
    })
}

/// The line after an image written as linear 8-bit (no gamma, no tone
/// curve): how to get one to look at.
pub fn linear_output_hint(output: &Path, encoding: &Encoding) -> Option<String> {
    let linear = encoding.gamma.is_none() && encoding.tonemap == Tonemap::None;
    (linear && !is_hdr(output)).then(|| {
        format!(
            "{}: linear 8-bit, as the course framework wrote it (dark on a screen); \
             --gamma 2.2 writes a display-encoded image",
            output.display()
        )
    })
}
