//! `pathtracer compare` (image error metrics against a reference) and
//! `pathtracer convert` (an image to another format, e.g. PFM to BMP).

use std::path::PathBuf;

use clap::Args;

use pathtracer::image_io::{Encoding, is_hdr, read_image, write_encoded};

use super::EncodingOptions;
use pathtracer::metrics::compare;

#[derive(Args)]
pub struct CompareArgs {
    /// The image under test (BMP, PNG or PFM).
    image: PathBuf,
    /// The reference image.
    reference: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &CompareArgs) -> Result<(), String> {
    let test = read_image(&args.image)?;
    let reference = read_image(&args.reference)?;
    let comparison = compare(&test, &reference)?;
    if args.json {
        say!("{}", comparison.to_json());
    } else {
        say!("{comparison}");
    }
    Ok(())
}

#[derive(Args)]
pub struct ConvertArgs {
    /// The image to read (BMP, PNG or PFM).
    input: PathBuf,
    /// The image to write (.bmp, .png, .pfm or .exr).
    output: PathBuf,
    /// Gamma, exposure and tone curve for 8-bit output, as `render`'s.
    #[command(flatten)]
    encoding: EncodingOptions,
}

pub fn convert(args: &ConvertArgs) -> Result<(), String> {
    let encoding = args.encoding.encoding();
    encoding.check()?;
    if is_hdr(&args.output) && encoding != Encoding::default() {
        eprintln!(
            "warning: --gamma, --exposure and --tonemap apply to 8-bit outputs; {} stays linear",
            args.output.display()
        );
    }
    write_encoded(&args.output, &read_image(&args.input)?, &encoding)
}
