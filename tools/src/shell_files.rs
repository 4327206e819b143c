//! The shell completions and man pages of the `contractible` command as files a packager
//! ships (`make_shell_files`): generated from the command's own clap grammar
//! (`contractible_cli::command`), the one its parser uses, so they cannot drift from the
//! binary. The same texts are printed by `contractible completions SHELL` and
//! `contractible man` (the main page).

use std::path::{Path, PathBuf};

use clap_complete::Shell;

/// The shells completed, in the order of `contractible completions --help`; each script
/// is written under the name its shell looks for (`contractible.bash`, `_contractible`,
/// `contractible.fish`, `contractible.elv`, `_contractible.ps1`).
pub const SHELLS: [Shell; 5] = [
    Shell::Bash,
    Shell::Elvish,
    Shell::Fish,
    Shell::PowerShell,
    Shell::Zsh,
];

/// Writes `out/completions/` (one script per shell of [`SHELLS`]) and `out/man/`
/// (`contractible.1` and one page per subcommand, `contractible-reduce.1`,
/// `contractible-gen-random.1`, ...), creating the folders; returns the files written,
/// sorted.
pub fn write(out: &Path) -> std::io::Result<Vec<PathBuf>> {
    let completions = out.join("completions");
    let man = out.join("man");
    std::fs::create_dir_all(&completions)?;
    std::fs::create_dir_all(&man)?;
    let mut written = Vec::new();
    for shell in SHELLS {
        let mut cmd = contractible_cli::command();
        written.push(clap_complete::generate_to(
            shell,
            &mut cmd,
            "contractible",
            &completions,
        )?);
    }
    clap_mangen::generate_to(contractible_cli::command(), &man)?;
    for entry in std::fs::read_dir(&man)? {
        written.push(entry?.path());
    }
    written.sort();
    Ok(written)
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeSet;

    use super::*;

    /// The subcommands as docs/cli.md documents them, one `## \`NAME\`` heading each (two
    /// names for `completions`, `man`): a list kept by hand, independent of the grammar.
    fn documented_subcommands() -> BTreeSet<String> {
        let doc =
            std::fs::read_to_string(crate::repo_root().join("docs/cli.md")).expect("docs/cli.md");
        let mut names = BTreeSet::new();
        for line in doc.lines() {
            let Some(title) = line.strip_prefix("## `") else {
                continue;
            };
            for part in title.split(", ") {
                names.insert(part.trim_matches('`').to_string());
            }
        }
        names
    }

    #[test]
    fn shell_files_are_complete_and_well_formed() {
        let out =
            std::env::temp_dir().join(format!("contractible-shell-files-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&out);
        let written = write(&out).expect("write the shell files");

        let completion_names: BTreeSet<String> = std::fs::read_dir(out.join("completions"))
            .expect("completions/")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        let expected: BTreeSet<String> = [
            "contractible.bash",
            "_contractible",
            "contractible.fish",
            "contractible.elv",
            "_contractible.ps1",
        ]
        .map(String::from)
        .into();
        assert_eq!(completion_names, expected);
        for f in &written {
            let len = std::fs::metadata(f).expect("written file").len();
            assert!(len > 0, "{} is empty", f.display());
        }

        // The bash script parses.
        let bash = out.join("completions/contractible.bash");
        let status = std::process::Command::new("bash")
            .arg("-n")
            .arg(&bash)
            .status()
            .expect("run bash");
        assert!(status.success(), "bash -n {}: {status}", bash.display());

        // Every man page is roff with a title line; the main page and the pages name
        // every documented subcommand, and no page names an undocumented one.
        let documented = documented_subcommands();
        assert!(documented.len() >= 10, "{documented:?}");
        let mut page_commands = BTreeSet::new();
        let mut main_page = String::new();
        for entry in std::fs::read_dir(out.join("man")).expect("man/") {
            let path = entry.expect("entry").path();
            let text = std::fs::read_to_string(&path).expect("man page");
            let stem = path
                .file_name()
                .and_then(|n| n.to_str())
                .and_then(|n| n.strip_suffix(".1"))
                .expect("NAME.1")
                .to_string();
            // After the roff preamble clap_mangen puts first (`.ie`/`.el`: how to print
            // an apostrophe), the page is titled with its own name, section 1.
            let title = text
                .lines()
                .find(|l| !l.starts_with(".ie ") && !l.starts_with(".el "))
                .unwrap_or("");
            assert!(
                title.starts_with(&format!(".TH {stem} 1 ")),
                "{}: the page starts with {title:?}, not its .TH title",
                path.display()
            );
            if stem == "contractible" {
                main_page = text.replace('\\', "");
            } else {
                let sub = stem
                    .strip_prefix("contractible-")
                    .expect("contractible-NAME.1");
                // Nested subcommands (`gen random`) have pages `contractible-gen-random.1`.
                let top = sub.split('-').next().unwrap_or(sub);
                page_commands.insert(top.to_string());
            }
        }
        assert_eq!(page_commands, documented);
        for name in &documented {
            assert!(
                main_page.contains(&format!("contractible-{name}(1)")),
                "contractible.1 does not list {name}"
            );
        }
        std::fs::remove_dir_all(&out).expect("remove the scratch folder");
    }
}
