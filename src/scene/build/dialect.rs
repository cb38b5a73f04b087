//! Which coursework dialect a file is written in, by the fingerprints of scene-format.md §6.6.

use std::collections::{BTreeSet, HashSet};

use crate::limits::MAX_KEPT_WORDS;

use crate::scene::ast::{Document, ItemKind};
use crate::scene::model::Dialect;

/// Fingerprints in priority order: the first rule whose words appear wins.
const RULES: [(&[&str], Dialect); 12] = [
    (
        &["attenuation", "DiffuseMaterial", "LightMaterial"],
        Dialect::Rtiow,
    ),
    (&["prop"], Dialect::Prop),
    (
        &[
            "perDiffuse",
            "cookTorrence",
            "lightColor",
            "defocusAngle",
            "Quad",
        ],
        Dialect::Rub,
    ),
    (&["Energy", "ns", "Func"], Dialect::SmallptInt),
    (&["Global", "lookFrom"], Dialect::Dst),
    (&["luminance", "Fresnel", "field"], Dialect::Cav),
    (&["reflective", "transmissive"], Dialect::Jef),
    (&["emissionColor", "brightness", "refl"], Dialect::Yao),
    (&["BRDF", "LensCamera"], Dialect::Cyy),
    (&["emissiveColor", "diffuseMap"], Dialect::Piu),
    (
        &["GlossyMaterial", "RefractiveMaterial", "transmittance"],
        Dialect::Bow,
    ),
    (&["refractive_rate", "texture_file"], Dialect::Cambrian),
];

const CANONICAL: [&str; 6] = [
    "diffusionRate",
    "specularRate",
    "refractRate",
    "canvasDistance",
    "interfereRatio",
    "focusDistance",
];

/// cyf words besides its documented fingerprint (files without a Textures block).
const CYF: [&str; 6] = [
    "Textures",
    "Lambert",
    "Emissive",
    "Metal",
    "Dielectric",
    "aperture",
];

/// The distinct identifier-like words of a file (field and block names),
/// sorted, at most [`MAX_KEPT_WORDS`] of them: what look detection reads
/// (`look::detect`). Numbers, paths and longer words are not kept.
pub fn distinct_words(document: &Document) -> Vec<String> {
    let mut found: BTreeSet<String> = BTreeSet::new();
    document.for_each_word(&mut |word, _, _| {
        let identifier = word.len() <= 32
            && word.starts_with(|c: char| c.is_ascii_alphabetic())
            && word.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if identifier && found.len() < MAX_KEPT_WORDS && !found.contains(word) {
            found.insert(word.to_string());
        }
    });
    found.into_iter().collect()
}

/// Detects the dialect of a parsed file.
pub fn detect_dialect(document: &Document) -> Dialect {
    let mut words: HashSet<&str> = HashSet::new();
    let mut type_vector = false;
    let mut color_material = false;
    document.for_each_word(&mut |word, items, index| {
        // A material written with `color` is not the PA1 framework's, which
        // knows only `diffuseColor`, but the canonical grammar's (and the
        // D3 family's, which `type d s r` or `refr` tell apart).
        if matches!(word, "Material" | "PhongMaterial")
            && let Some(ItemKind::Block(block)) = items.get(index).map(|i| &i.kind)
        {
            color_material |= block.items.iter().any(|i| i.word() == Some("color"));
        }
        if word == "type" {
            let numbers = items
                .iter()
                .skip(index + 1)
                .take_while(|i| matches!(i.kind, ItemKind::Number(_)))
                .count();
            type_vector |= numbers == 3;
        }
        if word == "refr" {
            type_vector = true;
        }
        if let Some(known) = RULES
            .iter()
            .flat_map(|(names, _)| names.iter())
            .chain(CANONICAL.iter())
            .chain(CYF.iter())
            .find(|name| **name == word)
        {
            words.insert(known);
        }
    });
    let has = |name: &str| words.contains(name);
    for (index, (names, dialect)) in RULES.iter().enumerate() {
        // cyf sits between afb and dst in the documented order.
        if index == 4 && has("Textures") && (has("Lambert") || has("Emissive")) {
            return Dialect::Cyf;
        }
        if names.iter().any(|n| has(n)) {
            return *dialect;
        }
    }
    // cyf files without textures: its material kinds, or `aperture` with `focusDistance`
    // (the canonical dialect has `interfereRatio` instead).
    let canonical_only = CANONICAL.iter().take(5).any(|n| has(n));
    if ["Lambert", "Emissive", "Metal", "Dielectric"]
        .iter()
        .any(|n| has(n))
        || (has("aperture") && has("focusDistance") && !canonical_only)
    {
        return Dialect::Cyf;
    }
    if CANONICAL.iter().any(|n| has(n)) {
        return Dialect::Canonical;
    }
    if type_vector {
        return Dialect::TypeVector;
    }
    if color_material {
        return Dialect::Canonical;
    }
    Dialect::Pa1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse::parse;
    use std::path::Path;

    fn detect(text: &str) -> Dialect {
        detect_dialect(&parse(text, Path::new("t")).expect("parses"))
    }

    #[test]
    fn fingerprints() {
        assert_eq!(
            detect("Materials { Material { diffuseColor 1 1 1 } }"),
            Dialect::Pa1
        );
        assert_eq!(detect("Material { type 1 0 0 }"), Dialect::TypeVector);
        assert_eq!(
            detect("Materials { Material { color 1 1 1 specularColor 1 1 1 } }"),
            Dialect::Canonical
        );
        assert_eq!(
            detect("Materials { Material { color 1 1 1 type 0 1 0 } }"),
            Dialect::TypeVector
        );
        assert_eq!(detect("Material { refr 1.5 }"), Dialect::TypeVector);
        assert_eq!(detect("Material { specularRate 1 }"), Dialect::Canonical);
        assert_eq!(
            detect("M { type DIFF refractive_rate 1 }"),
            Dialect::Cambrian
        );
        assert_eq!(
            detect("M { refractRate 1.5 fuzz 0 perDiffuse 1 }"),
            Dialect::Rub
        );
        assert_eq!(
            detect("Textures { } Materials { Lambert { } }"),
            Dialect::Cyf
        );
        assert_eq!(detect("M { attenuation 1 1 1 } Global { }"), Dialect::Rtiow);
        assert_eq!(detect("M { emissionColor 1 1 1 }"), Dialect::Yao);
        assert_eq!(detect("C { aperture 1 focusDistance 2 }"), Dialect::Cyf);
        assert_eq!(
            detect("C { interfereRatio 1 focusDistance 2 }"),
            Dialect::Canonical
        );
    }
}
