//! Command line: parses arguments, calls the library, prints errors, sets the
//! exit code. Each subcommand lives in `commands/`.

// A failed `eprintln!` panics: messages go through `stderr_line!` (console.rs).
#![deny(clippy::print_stderr)]

mod commands;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(
    name = "pathtracer",
    version,
    about = "A path tracer for PA scene files"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Parse and build scene files and print a summary of each.
    Check(commands::check::CheckArgs),
    /// Render a scene file to an image (or, with --film, one part of a render).
    Render(commands::render::RenderArgs),
    /// Add the films of render jobs (render --film) into one image.
    Merge(commands::merge::MergeArgs),
    /// Compare an image with a reference: RMSE, relative MSE, PSNR, SSIM, FLIP, look-alike.
    Compare(commands::compare::CompareArgs),
    /// Render every pair of a pairs file and measure how alike ours and theirs look.
    Lookalike(commands::lookalike::LookalikeArgs),
    /// Convert an image to another format (8-bit output: optional exposure, tone curve, gamma).
    Convert(commands::compare::ConvertArgs),
    /// Render at doubling sample counts and record error against time.
    Converge(commands::converge::ConvergeArgs),
    /// Draw error-against-time CSV files as one log-log SVG plot.
    Plot(commands::converge::PlotArgs),
    /// Render a scene progressively and watch it converge in a browser (127.0.0.1 only).
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
        Command::View(args) => commands::view::run(&args),
    };
    let failed = match result {
        Ok(()) => false,
        Err(message) => {
            let message = pathtracer::scene::error::printable(&message, true);
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
