//! `pathtracer compare`: image error metrics against a reference.

use std::path::PathBuf;

use clap::Args;

use pathtracer::image_io::read_image;
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
        println!("{}", comparison.to_json());
    } else {
        println!("{comparison}");
    }
    Ok(())
}
