//! The help and the guide say what the program does: docs/guide/options.md
//! names every long option of every command's `--help` and no option the
//! help lacks; in `newcomer`, the help, README, Makefile and guide agree
//! where they describe the same thing, what a render tells a newcomer (a
//! linear image, a PA1 scene's single sample), shell completions, and that
//! `make render` resumes.

use std::collections::{BTreeMap, BTreeSet};
use std::process::Command;

mod newcomer;

fn help(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(args)
        .arg("--help")
        .output()
        .expect("the binary runs");
    assert!(out.status.success(), "{args:?} --help failed");
    String::from_utf8(out.stdout).expect("help is UTF-8")
}

/// The subcommands listed by `pathtracer --help` (clap's own `help` left out).
fn commands() -> Vec<String> {
    help(&[])
        .lines()
        .skip_while(|line| !line.starts_with("Commands:"))
        .skip(1)
        .take_while(|line| line.starts_with("  "))
        .filter_map(|line| line.split_whitespace().next())
        .filter(|name| *name != "help")
        .map(str::to_string)
        .collect()
}

/// The `--long` options a help text lists (the option column of its lines).
fn help_options(text: &str) -> BTreeSet<String> {
    text.lines()
        .map(str::trim_start)
        .filter(|line| line.starts_with('-'))
        .flat_map(|line| {
            line.split_whitespace()
                .take_while(|word| word.starts_with('-') || word.starts_with('<'))
                .filter(|word| word.starts_with("--"))
                .map(|word| word.trim_end_matches(',').to_string())
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Every `--word` of a piece of text (`--spp=64` gives `--spp`).
fn long_options(text: &str) -> BTreeSet<String> {
    text.match_indices("--")
        .filter_map(|(at, _)| {
            let name: String = text[at + 2..]
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '-')
                .collect();
            let starts_word =
                !text[..at].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '-');
            (starts_word && name.starts_with(|c: char| c.is_ascii_lowercase()))
                .then(|| format!("--{name}"))
        })
        .collect()
}

/// A `## ` section of the reference: its title and its lines.
struct Section {
    title: String,
    body: Vec<String>,
}

fn sections(doc: &str) -> Vec<Section> {
    let mut sections: Vec<Section> = Vec::new();
    for line in doc.lines() {
        match line.strip_prefix("## ") {
            Some(title) => sections.push(Section {
                title: title.to_string(),
                body: Vec::new(),
            }),
            None => {
                if let Some(section) = sections.last_mut() {
                    section.body.push(line.to_string());
                }
            }
        }
    }
    sections
}

/// The options of a section's table: the long options of each row's first cell.
fn table_options(section: &Section) -> BTreeSet<String> {
    section
        .body
        .iter()
        .filter(|line| line.starts_with("| `"))
        .flat_map(|line| {
            let line = line.replace("\\|", "/");
            long_options(line.split('|').nth(1).unwrap_or_default())
        })
        .collect()
}

/// The anchor GitHub gives a heading: lower case, spaces to dashes.
fn anchor(title: &str) -> String {
    title
        .to_lowercase()
        .chars()
        .filter(|c| c.is_ascii_alphanumeric() || *c == ' ' || *c == '-')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// Each command's options by the reference: its own table and the tables
/// of the option groups its section links to (`[...](#sampling-options)`).
fn documented_options(doc: &str) -> BTreeMap<String, BTreeSet<String>> {
    let sections = sections(doc);
    let groups: BTreeMap<String, BTreeSet<String>> = sections
        .iter()
        .map(|section| (anchor(&section.title), table_options(section)))
        .collect();
    sections
        .iter()
        .filter_map(|section| {
            let command = section.title.strip_prefix("`pathtracer ")?;
            let command = command.split([' ', '`']).next()?.to_string();
            let text = section.body.join("\n");
            let mut options = table_options(section);
            for (anchor, group) in &groups {
                if text.contains(&format!("(#{anchor})")) {
                    options.extend(group.iter().cloned());
                }
            }
            Some((command, options))
        })
        .collect()
}

fn reference() -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/guide/options.md");
    std::fs::read_to_string(path).expect("docs/guide/options.md exists")
}

#[test]
fn the_option_reference_and_the_help_name_the_same_options() {
    let documented = documented_options(&reference());
    let commands = commands();
    assert!(commands.len() >= 8, "commands: {commands:?}");
    let mut wrong = Vec::new();
    for command in &commands {
        let in_help: BTreeSet<String> = help_options(&help(&[command]))
            .into_iter()
            .filter(|option| option != "--help")
            .collect();
        let Some(in_doc) = documented.get(command) else {
            wrong.push(format!("{command}: no section `pathtracer {command} ...`"));
            continue;
        };
        for option in in_help.difference(in_doc) {
            wrong.push(format!("{command} {option}: in --help, not in options.md"));
        }
        for option in in_doc.difference(&in_help) {
            wrong.push(format!("{command} {option}: in options.md, not in --help"));
        }
    }
    for command in documented.keys() {
        if !commands.contains(command) {
            wrong.push(format!(
                "options.md documents `{command}`, which is no command"
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn every_option_the_reference_mentions_is_an_option_of_some_command() {
    let mut known = help_options(&help(&[]));
    for command in commands() {
        known.extend(help_options(&help(&[&command])));
    }
    assert!(
        known.contains("--spp") && known.contains("--version"),
        "{known:?}"
    );
    let unknown: Vec<String> = long_options(&reference())
        .difference(&known)
        .cloned()
        .collect();
    assert!(
        unknown.is_empty(),
        "options.md mentions {unknown:?}, no command has them"
    );
}

#[test]
fn the_reference_reader_finds_what_it_is_given() {
    let doc = "## `pathtracer render SCENE`\nTakes the [s](#sampling-options).\n\n\
        | option | what |\n|---|---|\n| `-o`, `--output FILE` | x `--not-this` |\n\
        | `--only ok\\|all` | y |\n## Sampling options\n| `--seed S` | z |\n";
    let documented = documented_options(doc);
    let expected: BTreeSet<String> = ["--output", "--only", "--seed"].map(String::from).into();
    assert_eq!(documented["render"], expected);
    let help =
        "Options:\n  -o, --output <OUTPUT>  Output --image\n      --quiet\n          Do --not\n";
    assert_eq!(
        help_options(help),
        ["--output", "--quiet"].map(String::from).into()
    );
}
