//! Properties of the medium: transmittance, free-flight sampling's
//! expectations per channel, and the Henyey-Greenstein phase function.

use super::*;
use crate::math::Vec3;
use crate::rng::Rng;

fn chromatic() -> Medium {
    Medium {
        sigma_a: Color::new(0.1, 0.0, 0.4),
        sigma_s: Color::new(0.4, 1.0, 1.6),
        phase: HenyeyGreenstein { g: 0.0 },
        cambrian_mist: None,
    }
}

#[test]
fn transmittance_is_exp_of_minus_sigma_t_d() {
    let medium = chromatic();
    for d in [0.0, 0.3, 1.0, 7.5] {
        let t = medium.transmittance(d);
        assert!((t.r - (-0.5 * d).exp()).abs() < 1e-15);
        assert!((t.g - (-d).exp()).abs() < 1e-15);
        assert!((t.b - (-2.0 * d).exp()).abs() < 1e-15);
    }
    // Multiplicative along a ray, and an infinite distance leaves nothing
    // of a channel with extinction and everything of one without.
    let (a, b) = (0.7, 1.9);
    let split = medium.transmittance(a) * medium.transmittance(b);
    assert!((split.b - medium.transmittance(a + b).b).abs() < 1e-15);
    let clear_green = Medium {
        sigma_a: Color::new(1.0, 0.0, 1.0),
        sigma_s: Color::BLACK,
        ..chromatic()
    };
    assert_eq!(
        clear_green.transmittance(f64::INFINITY),
        Color::new(0.0, 1.0, 0.0)
    );
}

/// Means over `n` stratified flights of the pass weight and the scatter weight.
fn flight_means(medium: &Medium, t_max: f64, n: usize) -> (Color, Color, usize) {
    let (mut pass, mut scatter, mut scattered) = (Color::BLACK, Color::BLACK, 0);
    for i in 0..n {
        match medium.sample_flight(t_max, (i as f64 + 0.5) / n as f64) {
            Flight::Pass { weight } => pass += weight,
            Flight::Scatter { distance, weight } => {
                assert!(distance >= 0.0 && distance < t_max);
                scatter += weight;
                scattered += 1;
            }
        }
    }
    (pass / n as f64, scatter / n as f64, scattered)
}

#[test]
fn free_flights_estimate_transmittance_and_collisions_per_channel() {
    // E[pass weight] = T(t_max) and E[scatter weight] = sigma_s / sigma_t
    // (1 - T(t_max)) in every channel, although one channel's distance is
    // sampled at a time: the one-sample MIS over channels makes both exact
    // in expectation (here: stratified quadrature, so within 1e-3).
    let medium = chromatic();
    for t_max in [0.5, 2.0] {
        let (pass, scatter, _) = flight_means(&medium, t_max, 300_000);
        let t = medium.transmittance(t_max);
        let sigma_t = medium.sigma_t();
        for (got, want) in [(pass.r, t.r), (pass.g, t.g), (pass.b, t.b)] {
            assert!((got - want).abs() < 1e-3, "pass {got} vs {want} at {t_max}");
        }
        let collided = [
            (scatter.r, medium.sigma_s.r / sigma_t.r * (1.0 - t.r)),
            (scatter.g, medium.sigma_s.g / sigma_t.g * (1.0 - t.g)),
            (scatter.b, medium.sigma_s.b / sigma_t.b * (1.0 - t.b)),
        ];
        for (got, want) in collided {
            assert!((got - want).abs() < 1e-3, "scatter {got} vs {want}");
        }
    }
}

#[test]
fn grey_free_flights_collide_with_probability_one_minus_transmittance() {
    let medium = Medium {
        sigma_a: Color::gray(0.25),
        sigma_s: Color::gray(0.75),
        phase: HenyeyGreenstein { g: 0.5 },
        cambrian_mist: None,
    };
    let n = 100_000;
    let (_, scatter, scattered) = flight_means(&medium, 1.5, n);
    let want = 1.0 - (-1.5f64).exp();
    assert!((scattered as f64 / n as f64 - want).abs() < 1e-3);
    // The weight of a grey collision is the albedo.
    assert!((scatter.r / (scattered as f64 / n as f64) - 0.75).abs() < 1e-9);
    // With no surface ahead every flight collides.
    let (pass, _, scattered) = flight_means(&medium, f64::INFINITY, 1000);
    assert_eq!((pass, scattered), (Color::BLACK, 1000));
}

#[test]
fn a_pure_absorber_is_crossed_with_its_transmittance() {
    let medium = Medium {
        sigma_a: Color::new(1.0, 2.0, 3.0),
        sigma_s: Color::BLACK,
        phase: HenyeyGreenstein { g: 0.0 },
        cambrian_mist: None,
    };
    for u in [0.0, 0.5, 0.999] {
        assert_eq!(
            medium.sample_flight(0.4, u),
            Flight::Pass {
                weight: medium.transmittance(0.4)
            }
        );
    }
}

#[test]
fn henyey_greenstein_integrates_to_one_and_has_mean_cosine_g() {
    for g in [-0.7, -0.2, 0.0, 0.3, 0.9] {
        let phase = HenyeyGreenstein { g };
        // Integral over the sphere: 2 pi times the integral over cos.
        let n = 200_000;
        let (mut total, mut mean_cos) = (0.0, 0.0);
        for i in 0..n {
            let c = -1.0 + 2.0 * (i as f64 + 0.5) / n as f64;
            let p = phase.density(c) * 2.0 * std::f64::consts::PI * 2.0 / n as f64;
            total += p;
            mean_cos += c * p;
        }
        assert!((total - 1.0).abs() < 1e-4, "g {g}: integral {total}");
        assert!((mean_cos - g).abs() < 1e-3, "g {g}: mean cosine {mean_cos}");
    }
}

#[test]
fn henyey_greenstein_samples_follow_its_density() {
    // Histogram of sampled cosines against the density integrated over each
    // bin, for a forward and a backward lobe; and eval is the density of
    // the cosine between the travel direction and the sample.
    let travel = Vec3::new(0.3, -0.5, 0.8).normalize();
    for g in [0.6, -0.4, 0.0] {
        let phase = HenyeyGreenstein { g };
        let bins = 20;
        let mut counts = vec![0usize; bins];
        let mut rng = Rng::for_sample(1, 2, 3);
        let n = 200_000;
        for _ in 0..n {
            let wi = phase.sample(&travel, [rng.next_f64(), rng.next_f64()]);
            assert!((wi.norm() - 1.0).abs() < 1e-9);
            let c = travel.dot(&wi);
            assert!((phase.eval(&travel, &wi) - phase.density(c)).abs() < 1e-12);
            let bin = (((c + 1.0) / 2.0 * bins as f64) as usize).min(bins - 1);
            counts[bin] += 1;
        }
        for (bin, &count) in counts.iter().enumerate() {
            let steps = 1000;
            let width = 2.0 / bins as f64;
            let expected: f64 = (0..steps)
                .map(|k| {
                    let c = -1.0 + width * (bin as f64 + (k as f64 + 0.5) / steps as f64);
                    phase.density(c) * 2.0 * std::f64::consts::PI * width / steps as f64
                })
                .sum::<f64>()
                * n as f64;
            let sigma = expected.sqrt().max(1.0);
            assert!(
                (count as f64 - expected).abs() < 5.0 * sigma,
                "g {g} bin {bin}: {count} vs {expected}"
            );
        }
    }
}

#[test]
fn cambrian_mist_absorbs_over_the_whole_segment_before_scattering() {
    // Cambrian: a path scatters before a surface at 10 with the chance
    // e^(-sigma_a 10) (1 - e^(-sigma_s 10)), and never without a surface.
    let medium = Medium {
        sigma_a: Color::gray(0.05),
        sigma_s: Color::gray(0.1),
        phase: HenyeyGreenstein { g: 0.0 },
        cambrian_mist: Some(crate::medium::CambrianLobe { bias: 0.2 }),
    };
    let n = 20_000;
    let scattered = |t_max: f64| {
        (0..n)
            .map(
                |i| match medium.sample_flight(t_max, (i as f64 + 0.5) / n as f64) {
                    // Their expected weight is the chance Cambrian scatters.
                    Flight::Scatter { weight, .. } => weight.g,
                    Flight::Pass { .. } => 0.0,
                },
            )
            .sum::<f64>()
            / n as f64
    };
    let want = (-0.5f64).exp() * (1.0 - (-1.0f64).exp());
    let got = scattered(10.0);
    assert!((got - want).abs() < 0.01 * want, "{got} {want}");
    assert_eq!(scattered(f64::INFINITY), 0.0);
}
