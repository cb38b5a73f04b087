//! The facts of the look of CaveSpiderLZJ's path tracer (`cav`), one test
//! per fact that changes pixels (../shared/docs/looks.md has the facts).

mod common;

use common::{mean, render_text};
use pathtracer::geometry::{Sphere, SphereTest};
use pathtracer::integrator::Integrator;
use pathtracer::look::Look;
use pathtracer::math::{Point3, Ray, Vec3};
use pathtracer::rng::Rng;

/// The camera under a glass plane (z = 0, its outside above), looking up
/// with a 150 degree field: every camera ray meets the plane from inside,
/// beyond the critical angle of index 1.5. Above, a plane that emits 1.
const UNDER_GLASS: &str = "PerspectiveCamera { center 0 0 -1 direction 0 0 1 up 0 1 0 \
     angle 150 width 4 height 4 focus 0 field 0 }\nBackground { color 0 0 0 }\n\
     Materials { numMaterials 2\n\
     Material { diffuseColor 1 1 1 refractiveIndex 1.5 Fresnel { fbase 0 fscale 1 power 100 } }\n\
     Material { diffuseColor 0 0 0 luminance 1 1 1 } }\n\
     Group { numObjects 2 MaterialIndex 0 Plane { normal 0 0 1 offset 0 }\n\
     MaterialIndex 1 Plane { normal 0 0 -1 offset -10 } }";

#[test]
fn cav_glass_lets_a_leaving_ray_out_as_if_it_entered() {
    // Entering glass no ray is totally reflected, and with fscale 1 and
    // power 100 almost every ray refracts: the sky shows through (about 1).
    // Leaving it beyond the critical angle, the rays are reflected down
    // into the dark (but for a few rays of the tent filter near the
    // critical angle).
    let cav = mean(&render_text("under-glass", UNDER_GLASS, Look::CAV, 16));
    assert!(cav > 0.8, "cav: {cav}");
    let sided = Look {
        every_hit_enters: false,
        ..Look::CAV
    };
    let physical = mean(&render_text("under-glass", UNDER_GLASS, sided, 16));
    assert!(physical < 0.2, "by the side of the normal: {physical}");
}

/// `UNDER_GLASS` with the glass plane made of two triangles, their winding
/// normal up (the plane's normal).
const UNDER_GLASS_TRIANGLES: &str = "PerspectiveCamera { center 0 0 -1 direction 0 0 1 up 0 1 0 \
     angle 150 width 4 height 4 focus 0 field 0 }\nBackground { color 0 0 0 }\n\
     Materials { numMaterials 2\n\
     Material { diffuseColor 1 1 1 refractiveIndex 1.5 Fresnel { fbase 0 fscale 1 power 100 } }\n\
     Material { diffuseColor 0 0 0 luminance 1 1 1 } }\n\
     Group { numObjects 3 MaterialIndex 0\n\
     Triangle { vertex0 -100 -100 0 vertex1 100 -100 0 vertex2 100 100 0 }\n\
     Triangle { vertex0 -100 -100 0 vertex1 100 100 0 vertex2 -100 100 0 }\n\
     MaterialIndex 1 Plane { normal 0 0 -1 offset -10 } }";

#[test]
fn cav_triangles_keep_their_winding_normal() {
    // cav's triangles do not turn their normal towards the ray (its
    // planes do): under the same glass made of triangles the camera is
    // inside it, and the rays beyond the critical angle are reflected
    // down into the dark.
    let plane = mean(&render_text("under-glass", UNDER_GLASS, Look::CAV, 16));
    let triangles = mean(&render_text(
        "under-glass-triangles",
        UNDER_GLASS_TRIANGLES,
        Look::CAV,
        16,
    ));
    assert!(
        plane > 0.8 && triangles < 0.2,
        "plane {plane}, triangles {triangles}"
    );
}

/// The camera above a mirror of two triangles at z = 0 in a transform of
/// uniform scale `scale` (vertices divided by it), and under the mirror
/// an emitting floor.
fn scaled_mirror(scale: f64) -> String {
    let v = 20.0 / scale;
    format!(
        "PerspectiveCamera {{ center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 \
         width 4 height 4 focus 0 field 0 }}\nBackground {{ color 0 0 0 }}\n\
         Materials {{ numMaterials 2\n\
         Material {{ diffuseColor 1 1 1 Fresnel {{ fbase 1 fscale 0 power 1 }} }}\n\
         Material {{ diffuseColor 0 0 0 luminance 1 1 1 }} }}\n\
         Group {{ numObjects 2 MaterialIndex 0\n\
         Transform {{ UniformScale {scale} Group {{ numObjects 2\n\
         Triangle {{ vertex0 -{v} -{v} 0 vertex1 {v} -{v} 0 vertex2 {v} {v} 0 }}\n\
         Triangle {{ vertex0 -{v} -{v} 0 vertex1 {v} {v} 0 vertex2 -{v} {v} 0 }} }} }}\n\
         MaterialIndex 1 Plane {{ normal 0 0 1 offset -5 }} }}"
    )
}

#[test]
fn cav_mirrors_with_a_transformed_normal_shorter_than_a_unit() {
    // cav's transforms give a shape the inverse transpose times its unit
    // normal, not normalised: scaled by 3 its length is 1/3, and cav's
    // mirror direction d - 2 n (d.n) keeps 1 - 2/9 of the ray's normal
    // part: the ray goes on through the mirror to the emitting floor.
    // Unscaled, the mirror sends it up into the dark.
    let scaled = mean(&render_text(
        "scaled-mirror",
        &scaled_mirror(3.0),
        Look::CAV,
        4,
    ));
    let unscaled = mean(&render_text("mirror", &scaled_mirror(1.0), Look::CAV, 4));
    assert!(
        scaled > 0.99 && unscaled < 0.01,
        "scaled {scaled}, unscaled {unscaled}"
    );
}

/// Rays from the floor that meet the cap of cav's light (a radius-600
/// sphere whose cap hangs 5e-3 under the ceiling at z = 5), each followed
/// by one diffuse ray leaving its hit point downwards: how many of those
/// meet the sphere again.
fn cap_rehits(test: SphereTest) -> usize {
    let mut sphere = Sphere::new(Point3::new(0.0, 0.0, 604.995), 600.0, Vec3::zeros());
    sphere.test = test;
    let mut rng = Rng::new(31, 7);
    let mut again = 0;
    for _ in 0..20_000 {
        let floor = Point3::new(4.0 * rng.next_f64() - 2.0, 4.0 * rng.next_f64() - 2.0, -5.0);
        let up = Vec3::new(0.2 * rng.next_f64() - 0.1, 0.2 * rng.next_f64() - 0.1, 1.0);
        let ray = Ray::new(floor, up.normalize(), 0.0);
        let Some(hit) = sphere.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        let down = Vec3::new(rng.next_f64() - 0.5, rng.next_f64() - 0.5, -1.0).normalize();
        let point = ray.at(hit.t);
        let leaving = match test {
            SphereTest::Robust => point - Vec3::z() * 1e-9 * point.norm(),
            _ => point,
        };
        let bounce = Ray::new(leaving, down, 0.0);
        again += usize::from(sphere.intersect(&bounce, 0.0, f64::INFINITY).is_some());
    }
    again
}

#[test]
fn cav_light_caps_are_met_again_by_rays_leaving_them() {
    // cav's single-precision test rounds the hit on the cap ~1e-4 inside
    // the big sphere, and a ray leaving it downwards meets the cap again
    // from inside about one time in twenty.
    let cav = cap_rehits(SphereTest::Cav);
    assert!((200..=3000).contains(&cav), "cav: {cav} of 20000");
    assert_eq!(cap_rehits(SphereTest::Robust), 0);
}

/// A white floor lit by a small, bright ball above it.
const SMALL_LIGHT: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 \
     angle 30 width 8 height 8 focus 0 field 0 }\nBackground { color 0 0 0 }\n\
     Materials { numMaterials 2 Material { diffuseColor 0.5 0.5 0.5 }\n\
     Material { diffuseColor 0 0 0 luminance 25 25 25 } }\n\
     Group { numObjects 2 MaterialIndex 0 Plane { normal 0 0 1 offset 0 }\n\
     MaterialIndex 1 Sphere { center 0 3 2 radius 0.2 } }";

/// The spread of the pixels of a uniformly lit patch over their mean.
fn relative_spread(look: Look) -> f64 {
    // About one bounce in 500 meets the ball: the 4096 paths find it a
    // few times, whatever the sample points (at 16 spp it may be none).
    let image = render_text("small-light", SMALL_LIGHT, look, 64);
    let values: Vec<f64> = image.pixels.iter().map(|p| p.g).collect();
    let m = values.iter().sum::<f64>() / values.len() as f64;
    let variance = values.iter().map(|v| (v - m).powi(2)).sum::<f64>() / values.len() as f64;
    variance.sqrt() / m
}

#[test]
fn cav_finds_its_lights_by_the_bounce_alone() {
    // Without light samples only the bounces that happen to meet the small
    // ball bring light: the floor is far noisier than with them.
    let cav = relative_spread(Look::CAV);
    let sampled = relative_spread(Look {
        integrator: Integrator::Path,
        ..Look::CAV
    });
    assert!(
        cav > 3.0 * sampled,
        "cav {cav}, with light samples {sampled}"
    );
}

/// A 2x1 image, black then white, written to a fresh folder.
fn black_then_white(name: &str) -> std::path::PathBuf {
    use pathtracer::color::Color;
    use pathtracer::image_io::{Image, write_image};
    let dir = common::fresh_dir(&format!("cav-texture-{name}"));
    let path = dir.join("black-white.png");
    let image = Image {
        width: 2,
        height: 1,
        pixels: vec![Color::BLACK, Color::WHITE],
    };
    write_image(&path, &image, None).expect("writes");
    path
}

/// The camera 5 above a textured plane z = 0 under a white sky, seeing
/// x and y in [-1, 1]: a pixel is its texel (one bounce to the sky).
fn textured_floor(texture: &std::path::Path, scale: &str) -> String {
    format!(
        "PerspectiveCamera {{ center 0 0 5 direction 0 0 -1 up 0 1 0 angle 22.619865 \
         width 8 height 8 focus 0 field 0 }}\nBackground {{ color 1 1 1 }}\n\
         Materials {{ numMaterials 1 Material {{ diffuseColor 1 1 1 luminance 0 0 0 \
         texture {} {scale} }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 Plane {{ normal 0 0 1 offset 0 }} }}",
        texture.display()
    )
}

/// The mean of the columns `columns` of `image`.
fn columns_mean(image: &pathtracer::image_io::Image, columns: std::ops::Range<usize>) -> f64 {
    let mut sum = 0.0;
    let mut n = 0;
    for (i, p) in image.pixels.iter().enumerate() {
        if columns.contains(&(i % image.width)) {
            sum += p.g;
            n += 1;
        }
    }
    sum / n as f64
}

#[test]
fn cav_scales_texture_coordinates_by_texture_scale_and_wraps_them() {
    // cav's frame on the plane z = 0 has u = x: times 0.1 and wrapped, x
    // in [-1, 0) reads 0.9 to 1 (the white texel) and [0, 1) reads 0 to 0.1
    // (the black one). Without the scale the image would repeat every
    // world unit, and our own tiling (10 texels a unit) makes stripes 0.1
    // wide: grey pixels.
    let texture = black_then_white("scale");
    let image = render_text(
        "texture-scale",
        &textured_floor(&texture, "textureScale 0.1"),
        Look::CAV,
        4,
    );
    let (left, right) = (columns_mean(&image, 0..3), columns_mean(&image, 5..8));
    assert!(left > 0.95 && right < 0.05, "left {left}, right {right}");
    let ours = Look {
        texture_frames: pathtracer::look::TextureFrames::Shapes,
        ..Look::CAV
    };
    let image = render_text(
        "texture-scale",
        &textured_floor(&texture, "textureScale 0.1"),
        ours,
        4,
    );
    let (left, right) = (columns_mean(&image, 0..3), columns_mean(&image, 5..8));
    assert!(
        left < 0.8 && right > 0.2,
        "ours: left {left}, right {right}"
    );
    std::fs::remove_dir_all(texture.parent().expect("a folder")).ok();
}

#[test]
fn cav_divides_a_texel_byte_by_256() {
    // The white texel, 255, reads 255/256 (not 1); under the white sky one
    // bounce returns it exactly.
    let texture = black_then_white("bytes");
    let image = render_text(
        "texel-bytes",
        &textured_floor(&texture, "textureScale 0.1"),
        Look::CAV,
        2,
    );
    let white = image.pixels[0].g;
    assert!((white - 255.0 / 256.0).abs() < 1e-6, "{white}");
    std::fs::remove_dir_all(texture.parent().expect("a folder")).ok();
}

#[test]
fn cav_samples_a_pixel_within_half_a_pixel_of_its_corner() {
    // The texture's edge (x = 0) runs down the middle of the 8 pixels,
    // film x = 4: cav's pixel 4 draws its points from [3.5, 4.5), half on
    // the white side; a filter about the pixel's centre (4.5) sees the
    // black side but for the tent's tail.
    let texture = black_then_white("corner");
    let scene = textured_floor(&texture, "textureScale 0.1");
    let image = render_text("pixel-corner", &scene, Look::CAV, 64);
    let edge = columns_mean(&image, 4..5);
    assert!((edge - 0.5).abs() < 0.1, "cav: {edge}");
    assert!(columns_mean(&image, 3..4) > 0.95);
    let centred = Look {
        pixels: pathtracer::look::PixelSampling::Tent,
        ..Look::CAV
    };
    let image = render_text("pixel-corner", &scene, centred, 64);
    let edge = columns_mean(&image, 4..5);
    assert!(edge < 0.2, "about the centre: {edge}");
    std::fs::remove_dir_all(texture.parent().expect("a folder")).ok();
}
