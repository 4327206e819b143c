//! The `contractible` command-line tool. All logic lives in this package's library
//! (`contractible_cli`); the `contractible` library does the work.

fn main() -> std::process::ExitCode {
    contractible_cli::main()
}
