//! The glossy lobes: Phong, rough conductors and coats, rough glass, and
//! point lights on glossy surfaces, by both integrators.

use super::*;

/// (g) Phong lobes (PA1 specularColor / shininess) on their own, over a
/// diffuse base and next to a mirror, lit by a small sphere light (light
/// sampling and the light subpaths through the mirror see the glossy vertices).
fn phong() -> Scene {
    let mut materials = box_materials();
    materials.push(emitter(20.0)); // 3
    let phong = |exponent: f64| Phong {
        color: Color::gray(0.5),
        exponent,
    };
    materials.push(Material {
        color: Color::new(0.4, 0.1, 0.1),
        phong: Some(phong(40.0)),
        ..Material::default()
    }); // 4
    materials.push(Material {
        color: Color::gray(0.3),
        diffuse: 0.5,
        specular: 0.5,
        phong: Some(phong(4.0)),
        ..Material::default()
    }); // 5
    materials.push(Material {
        color: Color::BLACK,
        phong: Some(phong(200.0)),
        ..Material::default()
    }); // 6
    let mut objects = box_walls();
    objects.push(sphere(Vec3::new(0.0, 1.3, -6.0), 0.35, 3));
    objects.push(sphere(Vec3::new(-0.9, -1.4, -5.5), 0.6, 4));
    objects.push(sphere(Vec3::new(0.9, -1.4, -4.5), 0.6, 5));
    objects.push(sphere(Vec3::new(0.0, -0.2, -6.5), 0.4, 6));
    common::scene_with(materials, Object::Group(objects))
}

/// (h) Rough conductors (GGX, constant and Schlick Fresnel), a glossy coat
/// over a diffuse base, and a mirror, under a small light.
fn rough_conductors() -> Scene {
    let mut materials = box_materials();
    materials.push(emitter(20.0)); // 3
    materials.push(Material {
        color: Color::new(0.9, 0.7, 0.4),
        diffuse: 0.0,
        specular: 1.0,
        roughness: 0.15,
        ..Material::default()
    }); // 4
    materials.push(Material {
        color: Color::gray(0.9),
        diffuse: 0.0,
        specular: 1.0,
        roughness: 0.5,
        conductor_fresnel: ConductorFresnel::Schlick,
        ..Material::default()
    }); // 5
    materials.push(Material {
        color: Color::new(0.1, 0.3, 0.6),
        coat: Some(Coat {
            alpha: 0.08,
            color: Color::gray(0.2),
            fresnel: ConductorFresnel::Schlick,
        }),
        ..Material::default()
    }); // 6
    materials.push(Material {
        color: Color::gray(0.95),
        diffuse: 0.0,
        specular: 1.0,
        ..Material::default()
    }); // 7
    let mut objects = box_walls();
    objects.push(sphere(Vec3::new(0.0, 1.3, -6.0), 0.35, 3));
    objects.push(sphere(Vec3::new(-0.9, -1.4, -5.5), 0.6, 4));
    objects.push(sphere(Vec3::new(0.9, -1.4, -4.5), 0.6, 5));
    objects.push(sphere(Vec3::new(0.2, -0.3, -6.8), 0.5, 6));
    objects.push(sphere(Vec3::new(-1.3, 0.6, -6.5), 0.4, 7));
    common::scene_with(materials, Object::Group(objects))
}

/// (i) Rough glass (GGX dielectric, alpha 0.25 and 0.6) and smooth glass
/// side by side under a small light, over a diffuse floor (rough caustics).
fn rough_glass() -> Scene {
    let mut materials = box_materials();
    materials.push(emitter(20.0)); // 3
    let glass = |roughness: f64| Material {
        color: Color::gray(0.95),
        diffuse: 0.0,
        refract: 1.0,
        roughness,
        ..Material::default()
    };
    materials.push(glass(0.25)); // 4
    materials.push(glass(0.6)); // 5
    materials.push(glass(0.0)); // 6
    let mut objects = box_walls();
    objects.push(sphere(Vec3::new(0.0, 1.3, -6.0), 0.35, 3));
    objects.push(sphere(Vec3::new(-0.9, -1.4, -5.5), 0.6, 4));
    objects.push(sphere(Vec3::new(0.9, -1.4, -4.5), 0.6, 5));
    objects.push(sphere(Vec3::new(0.1, -0.9, -6.5), 0.5, 6));
    common::scene_with(materials, Object::Group(objects))
}

/// (j) PA1 lights only, on Phong and rough conductor surfaces: the
/// shadow-ray term evaluates the glossy lobes.
fn point_lights_on_glossy() -> Scene {
    let mut scene = point_lights();
    scene.materials[3] = Material {
        color: Color::gray(0.6),
        phong: Some(Phong {
            color: Color::gray(0.4),
            exponent: 16.0,
        }),
        ..Material::default()
    };
    scene.materials[0] = Material {
        color: Color::gray(0.7),
        diffuse: 0.5,
        specular: 0.5,
        roughness: 0.3,
        ..Material::default()
    };
    scene
}

#[test]
fn phong_lobes_agree() {
    assert_agree("(g) phong", &phong(), 64);
}

#[test]
fn rough_conductors_and_coats_agree() {
    assert_agree("(h) rough conductors", &rough_conductors(), 64);
}

#[test]
fn rough_glass_agrees() {
    assert_agree("(i) rough glass", &rough_glass(), 64);
}

#[test]
fn point_lights_on_glossy_surfaces_agree() {
    assert_agree("(j) point lights, glossy", &point_lights_on_glossy(), 256);
}
