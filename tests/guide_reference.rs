//! The scene file reference (docs/guide/scene-format.md) names every word
//! the scene builder reads: each identifier-like string literal in the
//! non-test code of src/scene/build/ is a keyword, a block or a value word
//! of the grammar, and must appear in the reference as a whole word.

use std::path::Path;

/// String literals of the builder that are not words of a scene file.
const NOT_SCENE_WORDS: [&str; 2] = [
    // The `.mtl` reader's own structure, not a material field.
    "newmtl", // A word of an error message about Cambrian's mist.
    "survival",
];

/// The identifier-like string literals of `code` (`"abc_1"`, not `"a b"`),
/// comment lines left out (their quotes are prose).
fn identifier_literals(code: &str) -> Vec<String> {
    let code: String = code
        .lines()
        .filter(|line| !line.trim_start().starts_with("//"))
        .flat_map(|line| [line, "\n"])
        .collect();
    code.split('"')
        .skip(1)
        .step_by(2)
        .filter(|s| {
            s.chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        })
        .map(str::to_string)
        .collect()
}

fn contains_word(text: &str, word: &str) -> bool {
    text.match_indices(word).any(|(at, _)| {
        let before = text[..at].chars().next_back();
        let after = text[at + word.len()..].chars().next();
        let part_of_word =
            |c: Option<char>| c.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_');
        !part_of_word(before) && !part_of_word(after)
    })
}

#[test]
fn every_word_the_scene_builder_reads_is_in_the_reference() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let reference = std::fs::read_to_string(root.join("docs/guide/scene-format.md"))
        .expect("the reference exists");
    let mut files: Vec<_> = std::fs::read_dir(root.join("src/scene/build"))
        .expect("the builder's folder")
        .map(|entry| entry.expect("a folder entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "rs"))
        .collect();
    files.sort();
    assert!(files.len() > 10, "{} builder files", files.len());
    let mut missing = Vec::new();
    let mut checked = 0;
    for file in &files {
        let text = std::fs::read_to_string(file).expect("a source file");
        let code = text.split("#[cfg(test)]").next().unwrap_or_default();
        for word in identifier_literals(code) {
            checked += 1;
            if !NOT_SCENE_WORDS.contains(&word.as_str()) && !contains_word(&reference, &word) {
                missing.push(format!("{word} ({})", file.display()));
            }
        }
    }
    assert!(checked > 200, "only {checked} words found in the builder");
    missing.sort();
    missing.dedup();
    assert!(
        missing.is_empty(),
        "words the builder reads that docs/guide/scene-format.md does not name: {}",
        missing.join(", ")
    );
}

#[test]
fn literals_and_whole_words_are_found_as_the_check_needs() {
    assert_eq!(
        identifier_literals(r#"match k { "a_b" => f("x y"), "Z9" => 1 } "#),
        ["a_b", "Z9"]
    );
    assert!(contains_word("the `refr` field", "refr"));
    assert!(!contains_word("refractiveIndex", "refr"));
    assert!(!contains_word("a_refr", "refr"));
    assert_eq!(
        identifier_literals("/// a \"quoted\" comment\nlet k = \"key\";"),
        ["key"]
    );
}
