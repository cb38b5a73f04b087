//! What kind of scattering a lobe, a BSDF or one of its samples does, in
//! pbrt's words (`BxDFFlags`): reflection or transmission, and diffuse,
//! glossy or specular (a delta direction); and which way a path carries
//! light (`TransportMode`): integrators ask these instead of naming lobes.

use std::ops::BitOr;

/// A set of scattering kinds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BsdfFlags(u8);

impl BsdfFlags {
    pub const NONE: BsdfFlags = BsdfFlags(0);
    /// Light leaves on the side it arrived from.
    pub const REFLECTION: BsdfFlags = BsdfFlags(1);
    /// Light crosses the surface.
    pub const TRANSMISSION: BsdfFlags = BsdfFlags(2);
    /// Lambert: the same in every direction.
    pub const DIFFUSE: BsdfFlags = BsdfFlags(4);
    /// A continuous lobe about a direction (Phong, microfacets).
    pub const GLOSSY: BsdfFlags = BsdfFlags(8);
    /// A delta direction (a mirror, smooth glass).
    pub const SPECULAR: BsdfFlags = BsdfFlags(16);
    /// A sample that crossed a surface whose transport is not the same
    /// both ways (a sphere under Cambrian's test, whose exit is taken for
    /// an entry): light subpaths do not go there, and camera paths count
    /// such paths alone.
    pub const NONRECIPROCAL: BsdfFlags = BsdfFlags(32);
    /// The lobes a direction is drawn from (not delta).
    pub const CONTINUOUS: BsdfFlags = BsdfFlags(4 | 8);
    pub const DIFFUSE_REFLECTION: BsdfFlags = BsdfFlags(1 | 4);

    /// Whether every kind of `other` is in the set.
    #[inline]
    pub const fn contains(self, other: BsdfFlags) -> bool {
        self.0 & other.0 == other.0
    }

    /// Whether any kind of `other` is in the set.
    #[inline]
    pub const fn intersects(self, other: BsdfFlags) -> bool {
        self.0 & other.0 != 0
    }

    #[inline]
    pub const fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// A delta direction.
    #[inline]
    pub const fn is_specular(self) -> bool {
        self.contains(BsdfFlags::SPECULAR)
    }

    /// Diffuse reflection and nothing else (empty included): what light
    /// subpaths connect to.
    #[inline]
    pub const fn is_diffuse_reflection_only(self) -> bool {
        self.0 & !BsdfFlags::DIFFUSE_REFLECTION.0 == 0
    }

    /// The set without the kinds of `other`.
    #[inline]
    pub const fn without(self, other: BsdfFlags) -> BsdfFlags {
        BsdfFlags(self.0 & !other.0)
    }
}

impl BitOr for BsdfFlags {
    type Output = BsdfFlags;

    #[inline]
    fn bitor(self, other: BsdfFlags) -> BsdfFlags {
        BsdfFlags(self.0 | other.0)
    }
}

/// Which way a path carries light: camera paths carry radiance, light
/// subpaths importance. A BSDF sampled for importance gives no direction
/// that crosses a non-reciprocal surface ([`BsdfFlags::NONRECIPROCAL`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TransportMode {
    #[default]
    Radiance,
    Importance,
}
