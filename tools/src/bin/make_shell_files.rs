//! Writes the shell completions and man pages of the `contractible` command for a
//! package to ship, generated from the command's clap grammar:
//!
//! ```sh
//! cargo run -p contractible-tools --bin make_shell_files -- OUTDIR
//! ```
//!
//! `OUTDIR/completions/` holds `contractible.bash`, `_contractible` (zsh),
//! `contractible.fish`, `contractible.elv` and `_contractible.ps1` (PowerShell);
//! `OUTDIR/man/` holds `contractible.1` and one page per subcommand
//! (`contractible-reduce.1`, `contractible-gen-random.1`, ...). Prints the files written.

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<std::ffi::OsString> = std::env::args_os().skip(1).collect();
    let [out] = args.as_slice() else {
        eprintln!("usage: make_shell_files OUTDIR");
        return ExitCode::from(2);
    };
    match contractible_tools::shell_files::write(std::path::Path::new(out)) {
        Ok(files) => {
            for f in files {
                println!("{}", f.display());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!(
                "error: cannot write the shell files under {}: {e}",
                out.to_string_lossy()
            );
            ExitCode::FAILURE
        }
    }
}
