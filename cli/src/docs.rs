//! `contractible completions SHELL` and `contractible man`: shell completions
//! (clap_complete) and the man page (clap_mangen, roff) generated from the same clap
//! grammar as the parser, so they list exactly the commands and options that exist.

use clap::CommandFactory;

use super::args::{Cli, CompletionsArgs};
use super::CliError;

/// Writes the completion script for `a.shell` to stdout.
pub fn completions(a: &CompletionsArgs) -> Result<(), CliError> {
    let mut cmd = Cli::command();
    let mut buf = Vec::new();
    clap_complete::generate(a.shell, &mut cmd, "contractible", &mut buf);
    write_stdout(&buf)
}

/// Writes the man page contractible(1) (roff) to stdout.
pub fn man() -> Result<(), CliError> {
    let mut buf = Vec::new();
    clap_mangen::Man::new(Cli::command())
        .render(&mut buf)
        .map_err(|e| CliError::Failure(format!("cannot render the man page: {e}")))?;
    write_stdout(&buf)
}

fn write_stdout(bytes: &[u8]) -> Result<(), CliError> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(bytes).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
            super::signals::die_of_broken_pipe()
        }
        Err(e) => Err(CliError::Failure(format!("cannot write to stdout: {e}"))),
    }
}
