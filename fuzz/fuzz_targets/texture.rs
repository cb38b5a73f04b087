//! Fuzz target `texture`: any bytes as a scene's image file (BMP, PNG or
//! whatever the decoder recognises), read as the scene build reads textures:
//! as a sphere's colour texture, and for inputs of odd length also as a
//! plane's bump map (height or normal map, decided from the image); then
//! rendered at 4x4 with 1 spp by every integrator.

#![no_main]

use std::sync::OnceLock;

use libfuzzer_sys::{Corpus, fuzz_target};
use pathtracer::scene::LoadOptions;
use pathtracer_fuzz::sandbox::Sandbox;
use pathtracer_fuzz::{panics, tiny_render};

static SANDBOX: OnceLock<Sandbox> = OnceLock::new();

fn sandbox() -> &'static Sandbox {
    SANDBOX.get_or_init(|| Sandbox::enter("texture"))
}

const SCENE: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 width 4 height 4 }
Lights { numLights 1 PointLight { position 3 3 3 color 1 1 1 } }
Background { color 0.2 0.2 0.2 }
Materials { numMaterials 2
    Material { color 1 1 1 texture t.img }
    Material { color 0.8 0.8 0.8 BUMP }
}
Group { numObjects 2
    MaterialIndex 0 Sphere { center 0 0 0 radius 1 }
    MaterialIndex 1 Plane { normal 0 1 0 offset -1 }
}
";

fuzz_target!(
    init: {
        panics::install();
        sandbox();
    },
    |data: &[u8]| -> Corpus {
        let sandbox = sandbox();
        if !sandbox.write("t.img", data) {
            return Corpus::Reject;
        }
        let text = SCENE.replace(" BUMP", if data.len() % 2 == 1 { " bump t.img" } else { "" });
        let file = sandbox.path("scene.txt");
        let options = LoadOptions {
            base: Some(sandbox.folder.clone()),
            ..LoadOptions::default()
        };
        panics::crash_on_panic(|| {
            let Some(scene) = tiny_render::build_text(&text, &file, &options) else {
                return;
            };
            tiny_render::render_every_integrator(scene);
        });
        Corpus::Keep
    }
);
