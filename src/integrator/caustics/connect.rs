//! The two connections of a caustic vertex `y`: to a diffuse vertex of the
//! camera path, and to the camera itself (light tracing).

use std::f64::consts::PI;

use super::light_path::CausticVertex;
use super::{connection_weight, density_ratio};
use crate::camera::{Camera, Projection};
use crate::color::Color;
use crate::integrator::{CameraSample, Splats};
use crate::math::{Point3, Vec3, offset_origin};
use crate::render_scene::{RenderScene, ShadowTarget};
use crate::shading::Shading;
use crate::subpixel::{covering_pixels, filter_density};

/// The caustic light that `y` sends to the camera path's Lambert vertex
/// `at`, whose BRDF over the probability of its lobe choice is `f` (the
/// caller multiplies by the camera path's throughput), MIS-weighted against
/// the path tracer.
pub fn connect(scene: &RenderScene, at: &Shading, f: Color, y: &CausticVertex) -> Color {
    let offset = y.point - at.point;
    let distance_squared = offset.norm_squared();
    let distance = distance_squared.sqrt();
    if !(distance > 0.0 && distance.is_finite()) {
        return Color::BLACK;
    }
    let w = offset / distance;
    let cosine_pdf = at.normal.dot(&w) / PI;
    let Some(edge) = edge_density(cosine_pdf, -y.geometric.dot(&w), distance_squared) else {
        return Color::BLACK;
    };
    if !scene.unoccluded(
        at.spawn_origin(&w),
        w,
        ShadowTarget::Surface(y.point),
        y.time,
    ) {
        return Color::BLACK;
    }
    let weight = connection_weight(edge, y.shading_ratio, y.emission_density);
    // The BRDFs of x and y, the geometry of the edge, the light's weight.
    f * y.f * y.beta * (edge * PI * weight)
}

/// `(cos_x / pi) (cos_y / d^2)`: the path tracer's density, in area at `y`,
/// of the bounce from `x` that finds `y`, from the cosine-sampling density
/// `cos_x / pi` at `x`; `None` when `y` does not face `x` or `x` faces away
/// (the path tracer cannot make such a path either).
pub fn edge_density(cosine_pdf: f64, cos_y: f64, distance_squared: f64) -> Option<f64> {
    if cosine_pdf <= 0.0 || cos_y <= 0.0 {
        return None;
    }
    let density = cosine_pdf * cos_y / distance_squared;
    (density.is_finite() && density > 0.0).then_some(density)
}

/// The film area per area at `point` (unit geometric `normal` facing the
/// eye) of a projection: `J = film_per_steradian cos / d^2`.
fn film_per_area(projection: &Projection, normal: &Vec3) -> Option<f64> {
    let cosine = -normal.dot(&projection.direction);
    let jacobian =
        projection.film_per_steradian * cosine / (projection.distance * projection.distance);
    (cosine > 0.0 && jacobian.is_finite() && jacobian > 0.0).then_some(jacobian)
}

/// Light tracing's edge for pixel (`x`, `y`): `f_pixel(p) J / (W H)`.
fn camera_edge_for(
    camera: &Camera,
    x: usize,
    y: usize,
    projection: &Projection,
    jacobian: f64,
) -> f64 {
    let pixels = camera.width as f64 * camera.height as f64;
    filter_density(x, y, projection.film_x, projection.film_y) * jacobian / pixels
}

/// The edge (see the module documentation of `caustics`) of the camera ray
/// of `sample` that found the point with unit geometric `normal` (facing the
/// camera): `None` when light tracing could not reach it.
pub fn camera_edge(
    scene: &RenderScene,
    sample: &CameraSample,
    point: &Point3,
    normal: &Vec3,
) -> Option<f64> {
    let camera = scene.camera();
    let projection = camera.project(point, sample.lens)?;
    let jacobian = film_per_area(&projection, normal)?;
    let edge = camera_edge_for(
        camera,
        sample.pixel_x,
        sample.pixel_y,
        &projection,
        jacobian,
    );
    (edge > 0.0).then_some(edge)
}

/// Light tracing: the radiance `y` sends to the camera through the lens
/// point of the unit-square sample `lens`, splatted (MIS-weighted against the
/// path tracer) onto the pixels whose filters cover its film position.
pub fn splat_to_camera(
    scene: &RenderScene,
    camera: &Camera,
    y: &CausticVertex,
    lens: [f64; 2],
    splats: &mut Splats,
) {
    let Some(projection) = camera.project(&y.point, lens) else {
        return;
    };
    if projection.distance <= projection.canvas {
        return; // before the canvas: camera rays start beyond it
    }
    let Some(jacobian) = film_per_area(&projection, &y.geometric) else {
        return;
    };
    let mut pixels = covering_pixels(
        camera.width as usize,
        camera.height as usize,
        projection.film_x,
        projection.film_y,
    )
    .peekable();
    if pixels.peek().is_none() {
        return;
    }
    let to_eye = -projection.direction;
    let origin = offset_origin(&y.point, &y.geometric, &to_eye);
    let free = projection.distance - projection.canvas;
    if !scene.unoccluded(origin, to_eye, ShadowTarget::Distance(free), y.time) {
        return;
    }
    // Radiance towards the eye: the BRDF of y times the subpath's weight;
    // per pixel the filter density and J, over light tracing's share.
    let radiance = y.beta * y.f;
    for (x, pixel_y, density) in pixels {
        let edge = camera_edge_for(camera, x, pixel_y, &projection, jacobian);
        let ratio = density_ratio(edge, y.shading_ratio, y.emission_density);
        let weight = 1.0 / (1.0 + ratio * ratio);
        if weight.is_finite() && weight > 0.0 {
            splats.push(x, pixel_y, radiance * (density * jacobian * weight));
        }
    }
}
