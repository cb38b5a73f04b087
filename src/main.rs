//! Command line: parses arguments, calls the library, prints errors, sets the
//! exit code. Each subcommand lives in `commands/`.

// A failed `eprintln!` panics: messages go through `stderr_line!` (console.rs).
#![deny(clippy::print_stderr)]
// Bad input is an error message and an exit code, never a panic; tests may unwrap.
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::unreachable,
        clippy::todo,
        clippy::unimplemented
    )
)]

mod commands;

use std::process::ExitCode;

use clap::{CommandFactory, Parser, Subcommand};

use commands::examples;

#[derive(Parser)]
#[command(
    name = "pathtracer",
    version,
    about = "A path tracer for PA scene files",
    after_help = examples::PATHTRACER
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Parse and build scene files and print a summary of each.
    #[command(after_help = examples::CHECK)]
    Check(commands::check::CheckArgs),
    /// Render a scene file to an image (or, with --film, one part of a render).
    #[command(after_help = examples::RENDER)]
    Render(commands::render::RenderArgs),
    /// Add the films of render jobs (render --film) into one image.
    #[command(after_help = examples::MERGE)]
    Merge(commands::merge::MergeArgs),
    /// Compare an image with a reference: RMSE, relative MSE, PSNR, SSIM, FLIP, look-alike.
    #[command(after_help = examples::COMPARE)]
    Compare(commands::compare::CompareArgs),
    /// Render every pair of a pairs file and measure how alike ours and theirs look.
    #[command(after_help = examples::LOOKALIKE)]
    Lookalike(commands::lookalike::LookalikeArgs),
    /// Convert an image to another format (8-bit output: optional exposure, tone curve, gamma).
    #[command(after_help = examples::CONVERT)]
    Convert(commands::compare::ConvertArgs),
    /// Render at doubling sample counts and record error against time.
    #[command(after_help = examples::CONVERGE)]
    Converge(commands::converge::ConvergeArgs),
    /// Draw error-against-time CSV files as one log-log SVG plot.
    #[command(after_help = examples::PLOT)]
    Plot(commands::converge::PlotArgs),
    /// Print a shell completion script (bash, zsh or fish) to standard output.
    #[command(after_help = examples::COMPLETIONS)]
    Completions(commands::completions::CompletionsArgs),
    /// Render a scene progressively and watch it converge in a browser (127.0.0.1 only).
    #[command(after_help = examples::VIEW)]
    View(commands::view::ViewArgs),
}

fn main() -> ExitCode {
    let command = Cli::parse().command;
    if let Err(message) = pathtracer::interrupt::install() {
        pathtracer::stderr_line!("warning: {message}");
    }
    let result = match command {
        Command::Check(args) => commands::check::run(&args),
        Command::Render(args) => commands::render::run(&args),
        Command::Merge(args) => commands::merge::run(&args),
        Command::Compare(args) => commands::compare::run(&args),
        Command::Lookalike(args) => commands::lookalike::run(&args),
        Command::Convert(args) => commands::compare::convert(&args),
        Command::Converge(args) => commands::converge::run(&args),
        Command::Plot(args) => commands::converge::plot(&args),
        Command::Completions(args) => commands::completions::run(&args, Cli::command()),
        Command::View(args) => commands::view::run(&args),
    };
    let failed = match result {
        Ok(()) => false,
        Err(message) => {
            let message = pathtracer::limits::printable(&message, true);
            pathtracer::stderr_line!("error: {message}");
            true
        }
    };
    // A command that finished gracefully after SIGINT or SIGTERM (a render
    // that wrote what it had) ends as an interrupted process does.
    match pathtracer::interrupt::interrupted() {
        Some(signal) => ExitCode::from((128 + signal).clamp(0, 255) as u8),
        None if failed => ExitCode::FAILURE,
        None => ExitCode::SUCCESS,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The words of a shell command line: double quotes group, `>` ends it.
    fn shell_words(line: &str) -> Vec<String> {
        let mut words = Vec::new();
        let mut word = String::new();
        let mut quoted = false;
        for c in line.chars() {
            match c {
                '"' => quoted = !quoted,
                '>' if !quoted => break,
                ' ' if !quoted => {
                    if !word.is_empty() {
                        words.push(std::mem::take(&mut word));
                    }
                }
                c => word.push(c),
            }
        }
        if !word.is_empty() {
            words.push(word);
        }
        words
    }

    #[test]
    fn every_command_has_examples_and_every_example_parses() {
        let cli = Cli::command();
        let mut helps = vec![("pathtracer".to_string(), cli.get_after_help().cloned())];
        for command in cli.get_subcommands() {
            helps.push((
                command.get_name().to_string(),
                command.get_after_help().cloned(),
            ));
        }
        assert!(helps.len() >= 10, "{} commands", helps.len());
        for (name, help) in helps {
            let help = help
                .unwrap_or_else(|| panic!("{name} --help has no examples"))
                .to_string();
            assert!(help.starts_with("Examples:"), "{name}: {help}");
            let lines: Vec<&str> = help
                .lines()
                .filter_map(|line| line.strip_prefix("  pathtracer "))
                .collect();
            assert!(
                name == "pathtracer" || lines.iter().any(|line| line.starts_with(&name)),
                "{name}: no example of the command itself"
            );
            for line in lines {
                let words = shell_words(&format!("pathtracer {line}"));
                match Cli::try_parse_from(&words) {
                    Ok(_) => {}
                    // `pathtracer help render` shows a help, as it should.
                    Err(error) if error.kind() == clap::error::ErrorKind::DisplayHelp => {}
                    Err(error) => panic!("{name}'s example `{line}` does not parse: {error}"),
                }
            }
        }
    }

    #[test]
    fn every_argument_is_described() {
        let cli = Cli::command();
        for command in cli.get_subcommands() {
            for argument in command.get_arguments() {
                assert!(
                    argument.get_help().is_some(),
                    "{} {}: no description in --help",
                    command.get_name(),
                    argument.get_id()
                );
            }
        }
    }

    #[test]
    fn the_example_reader_splits_like_a_shell() {
        assert_eq!(
            shell_words(r#"plot a.csv --title "SSIM of a"  -o x.svg > out"#),
            ["plot", "a.csv", "--title", "SSIM of a", "-o", "x.svg"]
        );
    }
}
