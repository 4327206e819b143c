//! The `contractible` command-line tool. All logic lives in the binary-only `cli` module;
//! the library (`contractible::*`) does the work.

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
