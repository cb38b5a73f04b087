//! cav's angle-dependent weights of a material's diffuse, conductor and
//! dielectric lobes, set per hit from the outgoing direction's cosine.

/// cav's angle-dependent weights: reflection `base + scale (1 - cos)^power`
/// from outside (inside a dielectric the term is scaled up so that it reaches
/// `base + scale` at the critical angle; beyond it everything reflects),
/// refraction `base + scale` minus that, diffuse the rest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AngularWeights {
    pub base: f64,
    pub scale: f64,
    pub power: f64,
}

impl AngularWeights {
    /// (diffuse, specular, refract) for light leaving at `cos_o` on the
    /// outside (`entering`) or the inside of a dielectric of index `ior`.
    pub fn weights(&self, cos_o: f64, entering: bool, ior: f64) -> (f64, f64, f64) {
        let total = self.base + self.scale;
        let c = cos_o.clamp(0.0, 1.0);
        let falloff = (1.0 - c).powf(self.power);
        let reflection = if entering || ior <= 1.0 {
            self.base + self.scale * falloff
        } else if (1.0 - c * c) * ior * ior >= 1.0 {
            // Beyond the critical angle.
            total
        } else {
            let critical = 1.0 - (1.0 - 1.0 / (ior * ior)).sqrt();
            self.base + self.scale * falloff / critical.powf(self.power)
        };
        let reflection = reflection.clamp(0.0, total.max(0.0));
        (
            (1.0 - total).max(0.0),
            reflection,
            (total - reflection).max(0.0),
        )
    }
}
