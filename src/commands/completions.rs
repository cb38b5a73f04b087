//! `pathtracer completions SHELL`: clap's own completion script for bash,
//! zsh or fish, written to standard output.

use clap::Args;
use clap_complete::Shell;

#[derive(Args)]
pub struct CompletionsArgs {
    /// The shell to complete in: bash, zsh or fish (elvish and powershell too).
    shell: Shell,
}

/// Writes the script of `args.shell` for `command` (the whole command line).
pub fn run(args: &CompletionsArgs, mut command: clap::Command) -> Result<(), String> {
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut command, "pathtracer", &mut script);
    // Like every report, the script ignores a closed standard output.
    use std::io::Write as _;
    let _ = std::io::stdout().write_all(&script);
    Ok(())
}
