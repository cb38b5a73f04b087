//! Fuzz target `pfm`: any bytes as an image file read by `compare` and
//! `convert` (PFM by its header, EXR and the 8-bit formats by the `image`
//! crate): an error, or an image with as many finite-or-not pixels as its
//! width times height.

#![no_main]

use std::sync::OnceLock;

use libfuzzer_sys::{Corpus, fuzz_target};
use pathtracer::image_io::read_image_encoded;
use pathtracer_fuzz::panics;
use pathtracer_fuzz::sandbox::Sandbox;

static SANDBOX: OnceLock<Sandbox> = OnceLock::new();

fn sandbox() -> &'static Sandbox {
    SANDBOX.get_or_init(|| Sandbox::enter("pfm"))
}

fuzz_target!(
    init: {
        panics::install();
        sandbox();
    },
    |data: &[u8]| -> Corpus {
        let sandbox = sandbox();
        if !sandbox.write("i.pfm", data) {
            return Corpus::Reject;
        }
        let path = sandbox.path("i.pfm");
        panics::crash_on_panic(|| {
            if let Ok((image, _)) = read_image_encoded(&path) {
                assert_eq!(image.pixels.len(), image.width * image.height);
            }
        });
        Corpus::Keep
    }
);
