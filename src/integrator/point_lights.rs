//! The point, spot and directional lights of PA1 (and cyy) scenes, added at
//! every vertex.
//!
//! The course framework shades a diffuse surface with `albedo * color *
//! max(0, n . l)` and no distance falloff; the port adds exactly that, with
//! a shadow ray: a light delivers the irradiance `pi * color` (falling off
//! with the cosine), which the BSDF turns into radiance, `pi * color *
//! f(wo, l) cos`. For a Lambert surface that is the framework's term; a
//! Phong lobe adds its highlight, a glossy conductor its reflection. A spot
//! light is a point light times `max(0, cos)^exponent` of the angle between
//! its direction and the way to the lit point (cyy's law, no cut-off).

use crate::spectral::PathSpectrum;
use std::f64::consts::PI;

use crate::bsdf::Bsdf;
use crate::color::Color;
use crate::math::{Point3, Vec3};
use crate::render_scene::{RenderScene, ShadowTarget};
use crate::scene::model::Light;
use crate::shading::Shading;

/// Radiance reflected towards `wo` from the point and directional lights
/// of `scene` (its direct lights), the light's colour and the BSDF each as
/// the path's `spectrum` sees them (the caller multiplies by the path
/// throughput).
pub fn direct(
    scene: &RenderScene,
    at: &Shading,
    bsdf: &Bsdf,
    wo: &Vec3,
    spectrum: &PathSpectrum,
) -> Color {
    let mut sum = Color::BLACK;
    for light in scene.direct_lights() {
        let Some(LightRay {
            to_light,
            distance,
            color,
        }) = toward(light, &at.point)
        else {
            continue;
        };
        if at.geometric.dot(&to_light) <= 0.0 {
            continue;
        }
        let reflected = bsdf.eval(wo, &to_light);
        if reflected.is_black() {
            continue;
        }
        // At shutter time 0, whatever the path's (as the original).
        if !scene.unoccluded(
            at.spawn_origin(&to_light),
            to_light,
            ShadowTarget::Distance(distance),
            0.0,
        ) {
            continue;
        }
        sum += spectrum.factor(reflected) * spectrum.factor(color) * PI;
    }
    sum
}

/// The way from a lit point to a point, spot or directional light.
pub struct LightRay {
    /// Unit direction from the point to the light.
    pub to_light: Vec3,
    /// Distance to the light (infinite for a directional one).
    pub distance: f64,
    /// The light's colour, times a spot light's cone factor.
    pub color: Color,
}

/// The way from `point` to `light`, or `None` for lights that are
/// emitting geometry (disk and area lights) and degenerate ones.
pub fn toward(light: &Light, point: &Point3) -> Option<LightRay> {
    let (to_light, distance, color) = match light {
        Light::Point { position, color } => {
            let offset = position - point;
            let distance = offset.norm();
            if distance <= 0.0 {
                return None;
            }
            (offset / distance, distance, *color)
        }
        Light::Spot {
            position,
            direction,
            color,
            exponent,
        } => {
            let offset = position - point;
            let distance = offset.norm();
            if distance <= 0.0 {
                return None;
            }
            let to_light = offset / distance;
            let cone = direction.dot(&-to_light).max(0.0).powf(*exponent);
            (to_light, distance, *color * cone)
        }
        Light::Directional { direction, color } => {
            let d = (-direction).try_normalize(1e-12)?;
            (d, f64::INFINITY, *color)
        }
        // Disk and area lights are emitting geometry in the world (the
        // scene builder adds it): found by rays, not here.
        Light::Disk { .. } | Light::Area { .. } => return None,
    };
    Some(LightRay {
        to_light,
        distance,
        color,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsdf::lambert::Lambert;
    use crate::bsdf::phong::Phong;
    use crate::bsdf::{Bsdf, Lobe, LobeSet, Rules};
    use crate::look::Look;
    use crate::math::Point3;
    use crate::render_scene::SceneSettings;
    use crate::scene::model::{Object, Scene};

    /// An empty scene lit by `lights` (added by shadow rays: it has no
    /// emitter).
    fn lit_by(lights: Vec<Light>) -> RenderScene {
        let mut scene = Scene::new(Vec::new(), Object::Group(Vec::new()));
        scene.lights = lights;
        let settings = SceneSettings::defaults(&scene, Look::ORIGINAL);
        RenderScene::build(scene, &settings)
    }

    /// The origin of an empty scene, facing +z.
    fn origin_of(scene: &RenderScene) -> Shading<'_> {
        let normal = Vec3::z();
        Shading {
            point: Point3::zeros(),
            material: scene.material(0),
            color: Color::WHITE,
            geometric: normal,
            normal,
            entering: true,
            leaves_from_point: false,
        }
    }

    /// The PA1 framework's term for a Lambert surface, and the energy-
    /// normalised Phong highlight on top, from a directional light.
    #[test]
    fn point_and_directional_lights_reflect_by_the_bsdf() {
        let to_light = Vec3::new(0.6, 0.0, 0.8);
        let scene = lit_by(vec![Light::Directional {
            direction: -to_light,
            color: Color::gray(2.0),
        }]);
        let at = origin_of(&scene);
        let wo = Vec3::new(-0.6, 0.0, 0.8);
        let (kd, ks, n) = (0.5, 0.3, 20.0);
        let mut set = LobeSet::default();
        let lambert = Lambert {
            albedo: Color::gray(kd),
        };
        set.push(Lobe::Lambert(lambert), 1.0, false);
        let rules = Rules::default();
        let bsdf = Bsdf::new(&set, Color::WHITE, &at.normal, true, wo.z, rules);
        let diffuse_only = direct(&scene, &at, &bsdf, &wo, &PathSpectrum::Rgb);
        // albedo * color * cos, the framework's term.
        assert!((diffuse_only.r - kd * 2.0 * 0.8).abs() < 1e-12);
        let phong = Phong {
            color: Color::gray(ks),
            exponent: n,
        };
        set.push(Lobe::Phong(phong), 1.0, false);
        let bsdf = Bsdf::new(&set, Color::WHITE, &at.normal, true, wo.z, rules);
        let with_highlight = direct(&scene, &at, &bsdf, &wo, &PathSpectrum::Rgb);
        // wo is the mirror of the light direction: cos(alpha) = 1.
        let highlight = ks * (n + 2.0) / 2.0 * 0.8 * 2.0;
        assert!((with_highlight.r - diffuse_only.r - highlight).abs() < 1e-9);
    }

    /// A spot light is the point light times max(0, cos)^exponent about its
    /// axis, with no other cut-off.
    #[test]
    fn spot_lights_fall_off_as_a_power_of_the_cosine_about_their_axis() {
        let mut set = LobeSet::default();
        let lambert = Lambert {
            albedo: Color::WHITE,
        };
        set.push(Lobe::Lambert(lambert), 1.0, false);
        let wo = Vec3::z();
        let position = Point3::new(0.0, 0.0, 2.0);
        let radiance = |light: Light| {
            let scene = lit_by(vec![light]);
            let at = origin_of(&scene);
            let bsdf = Bsdf::new(&set, Color::WHITE, &at.normal, true, wo.z, Rules::default());
            direct(&scene, &at, &bsdf, &wo, &PathSpectrum::Rgb).r
        };
        let lit = |direction: Vec3, exponent: f64| {
            radiance(Light::Spot {
                position,
                direction: direction.normalize(),
                color: Color::gray(3.0),
                exponent,
            })
        };
        let point = radiance(Light::Point {
            position,
            color: Color::gray(3.0),
        });
        assert!(
            (point - 3.0).abs() < 1e-12,
            "albedo * colour * cos: {point}"
        );
        // On the axis: the point light.
        assert!((lit(-Vec3::z(), 20.0) - point).abs() < 1e-12);
        // 60 degrees off the axis: cos^2 = 1/4.
        let tilted = Vec3::new(3f64.sqrt(), 0.0, -1.0);
        assert!((lit(tilted, 2.0) - point / 4.0).abs() < 1e-12);
        // Exponent 0: a point light over the whole sphere (as cyy's pow(0, 0)).
        assert!((lit(Vec3::z(), 0.0) - point).abs() < 1e-12);
        // Pointing away: dark.
        assert_eq!(lit(Vec3::z(), 1.0), 0.0);
        assert_eq!(lit(Vec3::x(), 1.0), 0.0);
    }
}
