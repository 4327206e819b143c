//! The `contractible` command-line tool: argument parsing, dispatch, exit codes. The
//! binary calls [`main`]; [`command`] is its clap grammar, from which the shell
//! completions and the man pages are generated. Everything else is private: the tool
//! uses only the public API of the `contractible` library.
//!
//! Exit codes: 0 success; 2 invalid input (unreadable or malformed file, mesh that is not
//! a disjoint union of closed surfaces — for `info`, `convert`, `simplify` and
//! `decimate`, of surfaces possibly with boundary — a mesh without usable positions for
//! `simplify` and `decimate`, bad arguments, an output that cannot be written: checked
//! before any work); 1 any other failure. A closed stdout (`| head`) ends the process as SIGPIPE does by default (status 141 in a
//! shell, no message, like `yes | head`); SIGINT and SIGTERM remove the output being
//! written and end it by the signal (130, 143).

/// `println!` for stdout that never panics: a closed stdout (the reader of a pipe went
/// away, as with `| head`) ends the process quietly, as SIGPIPE does, instead of the
/// panic `println!` gives. While a mesh is written to stdout (`-o -`), the report goes to
/// stderr instead.
macro_rules! outln {
    () => {
        $crate::write_stdout_line(format_args!(""))
    };
    ($($arg:tt)*) => {
        $crate::write_stdout_line(format_args!($($arg)*))
    };
}

mod answer;
mod args;
mod batch;
mod check;
mod choice;
mod conformance;
mod convert;
mod decimate;
mod demo;
mod docs;
mod gen;
mod info;
mod jobs;
mod meshio;
mod progress;
mod quad;
mod reduce;
mod signals;
mod simplify;

use std::process::ExitCode;

use clap::Parser;

use args::Cli;

/// A failure of a subcommand, with the exit code it maps to.
#[derive(Debug)]
pub(crate) enum CliError {
    /// Invalid input (exit code 2): one message per problem, each printed as one line.
    Input(String),
    /// Any other failure (exit code 1).
    Failure(String),
}

impl CliError {
    fn exit_code(&self) -> u8 {
        match self {
            CliError::Input(_) => 2,
            CliError::Failure(_) => 1,
        }
    }

    fn message(&self) -> &str {
        match self {
            CliError::Input(m) | CliError::Failure(m) => m,
        }
    }
}

/// Global output settings shared by every subcommand.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ui {
    /// Print the machine-readable result (only it) on stdout.
    pub json: bool,
    /// No progress bars and no human-readable text.
    pub quiet: bool,
}

impl Ui {
    /// Whether human-readable text goes to stdout.
    pub fn human(&self) -> bool {
        !self.json && !self.quiet
    }

    /// Prints a warning on stderr (unless quiet).
    pub fn warn(&self, msg: &str) {
        if !self.quiet {
            eprintln!("warning: {msg}");
        }
    }
}

/// Prints `value` as pretty JSON on stdout.
pub(crate) fn print_json<T: serde::Serialize>(value: &T) -> Result<(), CliError> {
    let s = serde_json::to_string_pretty(value)
        .map_err(|e| CliError::Failure(format!("cannot encode JSON: {e}")))?;
    outln!("{s}");
    JSON_PRINTED.store(true, std::sync::atomic::Ordering::Relaxed);
    Ok(())
}

/// Whether a JSON report was printed (then a failure that follows it, such as `info`'s
/// exit code 2 for a mesh that is not a surface, prints no second JSON value).
static JSON_PRINTED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Whether the report (human or JSON) goes to stderr: stdout carries a mesh (`-o -`).
static REPORT_TO_STDERR: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Sends the report to stderr from now on (stdout carries the output mesh).
pub(crate) fn report_to_stderr() {
    REPORT_TO_STDERR.store(true, std::sync::atomic::Ordering::Relaxed);
}

/// Writes one line of the report to stdout (see `outln!`), or to stderr while stdout
/// carries a mesh. A closed pipe ends the process as SIGPIPE does (no message); any
/// other write error (a full disk: `> /dev/full`) is one line on stderr and exit code 1,
/// since the output the user asked for cannot be delivered.
pub(crate) fn write_stdout_line(args: std::fmt::Arguments<'_>) {
    use std::io::Write;
    if REPORT_TO_STDERR.load(std::sync::atomic::Ordering::Relaxed) {
        eprintln!("{args}");
        return;
    }
    let mut out = std::io::stdout().lock();
    if let Err(e) = writeln!(out, "{args}").and_then(|()| out.flush()) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            signals::die_of_broken_pipe();
        }
        eprintln!("error: cannot write to stdout: {e}");
        std::process::exit(1);
    }
}

/// The command line's clap grammar (subcommands, options, help texts): the one the
/// parser uses, for generating shell completions and man pages that match the binary.
pub fn command() -> clap::Command {
    <Cli as clap::CommandFactory>::command()
}

/// Parses the command line, runs it and maps the result to an exit code.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            let usage = !matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion);
            // A usage error is an error too: with --json it is the JSON object every
            // other error gives (the flag is global, so it may be anywhere).
            if usage && std::env::args_os().any(|a| a == "--json") {
                // The parser's message without its usage and help trailer.
                let text = e.to_string();
                let body = text.split("\n\n").next().unwrap_or("").trim();
                let message = body.strip_prefix("error: ").unwrap_or(body);
                let v = serde_json::json!({
                    "error": { "kind": "usage", "exit_code": 2, "message": message }
                });
                outln!("{v:#}");
                eprint!("{e}");
                return ExitCode::from(2);
            }
            e.exit()
        }
    };
    signals::install();
    let ui = Ui {
        json: cli.json,
        quiet: cli.quiet,
    };
    let result = match cli.command {
        args::Command::Info(a) => info::run(&a, ui),
        args::Command::Gen(a) => gen::run(&a, ui),
        args::Command::Convert(a) => convert::run(&a, ui),
        args::Command::Reduce(a) => reduce::run(&a, ui),
        args::Command::Quad(a) => quad::run(&a, ui),
        args::Command::Simplify(a) => simplify::run(&a, ui),
        args::Command::Decimate(a) => decimate::run(&a, ui),
        args::Command::Check(a) => check::run(&a, ui),
        args::Command::Conformance(a) => conformance::run(&a, ui),
        args::Command::Answer => answer::run(),
        args::Command::Demo(a) => demo::run(&a, ui),
        args::Command::Batch(a) => batch::run(&a, ui),
        args::Command::Completions(a) => docs::completions(&a),
        args::Command::Man => docs::man(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            if ui.json && !JSON_PRINTED.load(std::sync::atomic::Ordering::Relaxed) {
                // With --json, stdout carries one JSON value whatever happens.
                let kind = match e {
                    CliError::Input(_) => "input",
                    CliError::Failure(_) => "failure",
                };
                let v = serde_json::json!({
                    "error": {
                        "kind": kind,
                        "exit_code": e.exit_code(),
                        "message": e.message(),
                    }
                });
                outln!("{v:#}");
            }
            for line in e.message().lines() {
                eprintln!("error: {line}");
            }
            ExitCode::from(e.exit_code())
        }
    }
}
