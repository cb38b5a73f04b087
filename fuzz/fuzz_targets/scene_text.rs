//! Fuzz target `scene_text`: any bytes as a scene file, parsed, built,
//! checked and rendered at 4x4 with 1 spp by every integrator.
//!
//! The scene lives in the sandbox, which holds the project's torus mesh and
//! checker texture under their usual names (`mesh/torus.obj`,
//! `texture/checker.bmp`); any other file it names does not exist and is
//! refused (or, for inputs of odd length, replaced by the placeholder).

#![no_main]

use std::sync::OnceLock;

use libfuzzer_sys::{Corpus, fuzz_target};
use pathtracer::scene::{LoadOptions, MissingAssets};
use pathtracer_fuzz::sandbox::{Sandbox, names_stay_inside};
use pathtracer_fuzz::{panics, tiny_render};

static SANDBOX: OnceLock<Sandbox> = OnceLock::new();

fn sandbox() -> &'static Sandbox {
    SANDBOX.get_or_init(|| {
        let sandbox = Sandbox::enter("scene_text");
        sandbox.copy_asset("mesh/torus.obj", "mesh/torus.obj");
        sandbox.copy_asset("texture/checker.bmp", "texture/checker.bmp");
        sandbox
    })
}

fuzz_target!(
    init: {
        panics::install();
        sandbox();
    },
    |data: &[u8]| -> Corpus {
        if !names_stay_inside(data) {
            return Corpus::Reject;
        }
        let sandbox = sandbox();
        let file = sandbox.path("scene.txt");
        let options = LoadOptions {
            base: Some(sandbox.folder.clone()),
            missing_assets: if data.len() % 2 == 1 {
                MissingAssets::Placeholder
            } else {
                MissingAssets::Error
            },
            ..LoadOptions::default()
        };
        panics::crash_on_panic(|| {
            let text = String::from_utf8_lossy(data);
            let Some(scene) = tiny_render::build_text(&text, &file, &options) else {
                return;
            };
            tiny_render::render_every_integrator(scene);
        });
        Corpus::Keep
    }
);
