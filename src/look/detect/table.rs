//! The fingerprints that say which renderer wrote a scene file, one row per
//! renderer, in the order they are tried (the first row that matches wins).
//! A row names the dialect the file must be read in and what else the file
//! must contain; a file that matches no row renders in `original`. Adding a
//! renderer is adding a row here (and its look in `look::rows` or the
//! look's module).
//!
//! No row is of the canonical dialect, and no canonical field moves a file
//! out of it (docs/guide/scene-format.md, "The canonical grammar"): a
//! user's own file in that grammar is never taken for a coursework
//! renderer's. `tests/look_detection.rs` holds this for every field.

use super::{Evidence, Fingerprint};
use crate::look::Look;
use crate::scene::model::Dialect;

/// Every fingerprint, tried in this order.
pub const FINGERPRINTS: &[Fingerprint] = &[
    Fingerprint {
        // Its files are the framework's, yuzc19's word for word, and one
        // in the rtiow words its parser cannot read.
        dialects: &[Dialect::Pa1, Dialect::TypeVector, Dialect::Rtiow],
        evidence: Evidence::Folder {
            owner: "yangjunx21",
            repository: "jt_lighting",
            repository_alone: true,
        },
        look: Look::YJX,
        says: "yangjunx21's path tracer (its files are others' word for word; --look pa1 or yzc for theirs)",
    },
    Fingerprint {
        dialects: &[Dialect::Pa1, Dialect::TypeVector],
        evidence: Evidence::Folder {
            owner: "hanna0911",
            repository: "image-renderer",
            repository_alone: true,
        },
        look: Look::HAN,
        says: "hanna0911's ray caster (its files are the framework's; --look pa1 for pixel centres)",
    },
    Fingerprint {
        dialects: &[Dialect::Pa1],
        evidence: Evidence::Folder {
            owner: "emily-jia",
            repository: "graphic_homework",
            repository_alone: true,
        },
        look: Look::EMJ,
        says: "emily-jia's Whitted ray tracer (its files are the framework's; --look pa1 for its ray caster)",
    },
    Fingerprint {
        dialects: &[Dialect::Jef],
        evidence: Evidence::Dialect,
        look: Look::JEF,
        says: "jefflyy's Whitted ray tracer",
    },
    Fingerprint {
        dialects: &[Dialect::Pa1],
        evidence: Evidence::Folder {
            owner: "jefflyy",
            repository: "CG_2022spring",
            repository_alone: true,
        },
        look: Look::JEF,
        says: "jefflyy's Whitted ray tracer (its files are the framework's; --look pa1 for its ray caster)",
    },
    Fingerprint {
        // Its `largeaxis` and `storeaxis` are the framework's files; its
        // PPM renders them (black: their only light is directional).
        dialects: &[Dialect::Pa1],
        evidence: Evidence::Folder {
            owner: "yao-jz",
            repository: "Computer-Graphics-THU",
            repository_alone: false,
        },
        look: Look::YAO,
        says: "yao-jz's photon mapper (its files are the framework's; --look pa1 for its ray caster)",
    },
    Fingerprint {
        // Its scene01, 03, 07 and 08 are the framework's files (its own
        // parser refuses three of them and divides by zero on the fourth).
        dialects: &[Dialect::Pa1],
        evidence: Evidence::Folder {
            owner: "Tschal-rsa",
            repository: "rang-kardan",
            repository_alone: true,
        },
        look: Look::TSC,
        says: "Tschal-rsa's photon mapper (its files are the framework's; --look pa1 for its ray caster)",
    },
    Fingerprint {
        dialects: &[Dialect::Pa1],
        evidence: Evidence::Dialect,
        look: Look::PA1,
        says: "the course framework's ray caster (its materials' own words only: diffuseColor, specularColor, shininess)",
    },
    Fingerprint {
        dialects: &[Dialect::Cambrian],
        evidence: Evidence::Dialect,
        look: Look::CAMBRIAN,
        says: "Cambrian-yzt's path tracer",
    },
    Fingerprint {
        dialects: &[Dialect::TypeVector],
        evidence: Evidence::AnyWord(&["DepthCamera", "glossy", "speed"]),
        look: Look::OSB,
        says: "one-step-beh1nd's path tracer",
    },
    Fingerprint {
        dialects: &[Dialect::TypeVector],
        evidence: Evidence::AnyWord(&["DiskLights", "focal"]),
        look: Look::YLC,
        says: "ylc2001's path tracer",
    },
    Fingerprint {
        dialects: &[Dialect::TypeVector],
        // yuzc19's renderer has no bump maps; W-Solaris's has.
        evidence: Evidence::AnyWord(&["bump"]),
        look: Look::WSO,
        says: "W-Solaris's path tracer (yuzc19's reads no bump maps)",
    },
    Fingerprint {
        // Its scene05 has only the framework's words and `color`: the
        // canonical dialect, rendered by W-Solaris's path tracer all the same.
        dialects: &[Dialect::TypeVector, Dialect::Canonical],
        // "computer-graphics" alone is anybody's folder.
        evidence: Evidence::Folder {
            owner: "W-Solaris",
            repository: "computer-graphics",
            repository_alone: false,
        },
        look: Look::WSO,
        says: "W-Solaris's path tracer (its files are yuzc19's word for word; --look yzc for yuzc19's)",
    },
    Fingerprint {
        dialects: &[Dialect::TypeVector],
        evidence: Evidence::Folder {
            owner: "one-step-beh1nd",
            repository: "THU2024Spring-CG-Final",
            repository_alone: true,
        },
        look: Look::OSB,
        says: "one-step-beh1nd's path tracer (this file is yuzc19's word for word; --look yzc for yuzc19's)",
    },
    Fingerprint {
        dialects: &[Dialect::TypeVector],
        // W-Solaris's and yuzc19's files are otherwise word for word the
        // same (vase.txt is scene09_norm.txt at another size).
        evidence: Evidence::Dialect,
        look: Look::YZC,
        says: "yuzc19's path tracer; W-Solaris's files are word for word the same, \
               --look wso renders them as W-Solaris's path tracer did",
    },
    Fingerprint {
        dialects: &[Dialect::Prop],
        evidence: Evidence::Dialect,
        look: Look::TSC,
        says: "Tschal-rsa's photon mapper (its materials' `prop` words)",
    },
    Fingerprint {
        dialects: &[Dialect::Yao],
        evidence: Evidence::Dialect,
        look: Look::YAO,
        says: "yao-jz's photon mapper (its materials' diff/refl/refr, its lights' brightness)",
    },
    Fingerprint {
        dialects: &[Dialect::Cav],
        evidence: Evidence::Dialect,
        look: Look::CAV,
        says: "CaveSpiderLZJ's path tracer",
    },
    Fingerprint {
        dialects: &[Dialect::SmallptInt],
        evidence: Evidence::Dialect,
        look: Look::AFB,
        says: "AfireBao's path tracer",
    },
    Fingerprint {
        dialects: &[Dialect::Bow],
        evidence: Evidence::Dialect,
        look: Look::BOW,
        says: "Bowen-Xu04's path tracer",
    },
    Fingerprint {
        // The rtiow dialect is also cuibst's: only ShuoAndy's camera has
        // these words.
        dialects: &[Dialect::Rtiow],
        evidence: Evidence::AnyWord(&["focus_distance", "lens_radius"]),
        look: Look::SHU,
        says: "ShuoAndy's path tracer",
    },
    Fingerprint {
        dialects: &[Dialect::Rtiow],
        evidence: Evidence::AnyWord(&["len_radius", "MovingObj"]),
        look: Look::RE2,
        says: "re2ikotr's path tracer",
    },
    Fingerprint {
        dialects: &[Dialect::Cyf],
        evidence: Evidence::Dialect,
        look: Look::CYF,
        says: "chen-yingfa's path tracer",
    },
    Fingerprint {
        // Its words (`perDiffuse`, `cookTorrence`, `lightColor`,
        // `defocusAngle`, `Quad`) are its own.
        dialects: &[Dialect::Rub],
        evidence: Evidence::Dialect,
        look: Look::RUB,
        says: "1rubbishyuan's recursive estimator",
    },
    Fingerprint {
        dialects: &[Dialect::Cyy],
        evidence: Evidence::Dialect,
        look: Look::CYY,
        says: "Chenyu-Yang-2000's path tracer",
    },
];
