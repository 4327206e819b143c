//! The documents' examples rerun against the binary, so that a document cannot go stale.
//!
//! - `docs/demo.md`: the lines between `<!-- demo-output -->` and `<!-- /demo-output -->`
//!   are the output of `contractible demo`.
//! - `README.md`, `docs/cli.md`: every block between `<!-- shell-example -->` and
//!   `<!-- /shell-example -->` is a shell transcript. A line `$ contractible ARGS` runs the
//!   binary (arguments split at spaces, `'…'` quoting one argument, a trailing `# comment`
//!   dropped); the lines after it, up to the next `$ ` line, are its output, stdout and
//!   stderr merged in the order written. `$ echo $?` prints the exit code of the command
//!   before it; `$ cat > FILE << 'EOF'` writes the lines up to `EOF` into FILE. The
//!   commands of one block run in order in one scratch directory holding a copy of
//!   `tests/data/meshes`, so `tests/data/meshes/...` paths read the repository's meshes
//!   and outputs land in the scratch directory.
//!
//! Timings vary between runs, so both sides are normalised before comparing: a number
//! followed by the unit `s` becomes `N s`, and a number with exactly four decimals (the
//! seconds columns of the tables) becomes `N`; lines are compared word by word, so the
//! width of a column does not matter. An output that starts with `{` is compared as
//! JSON, with the values of keys containing `seconds` ignored.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::cli_common::Scratch;

fn repo() -> PathBuf {
    crate::common::repo_root()
}

fn read_doc(rel: &str) -> String {
    std::fs::read_to_string(repo().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

/// A line of a document with its (1-based) number.
type Line = (usize, String);

/// The blocks between `<!-- NAME -->` and `<!-- /NAME -->`: (line number of the opening
/// marker, the lines inside without the code fences).
fn blocks(text: &str, name: &str, doc: &str) -> Vec<(usize, Vec<Line>)> {
    let open = format!("<!-- {name} -->");
    let close = format!("<!-- /{name} -->");
    let mut out = Vec::new();
    let mut current: Option<(usize, Vec<Line>)> = None;
    for (i, line) in text.lines().enumerate() {
        let trimmed = line.trim();
        if trimmed == open {
            assert!(
                current.is_none(),
                "{doc}:{}: {open} inside another block",
                i + 1
            );
            current = Some((i + 1, Vec::new()));
        } else if trimmed == close {
            let block = current
                .take()
                .unwrap_or_else(|| panic!("{doc}:{}: {close} without {open}", i + 1));
            out.push(block);
        } else if let Some((_, lines)) = current.as_mut() {
            if !trimmed.starts_with("```") {
                lines.push((i + 1, line.to_string()));
            }
        }
    }
    assert!(current.is_none(), "{doc}: {open} is never closed");
    out
}

fn is_number(s: &str) -> bool {
    let mut parts = s.splitn(2, '.');
    let int = parts.next().unwrap_or("");
    let frac = parts.next().unwrap_or("");
    !int.is_empty()
        && int.bytes().all(|b| b.is_ascii_digit())
        && !frac.is_empty()
        && frac.bytes().all(|b| b.is_ascii_digit())
}

/// A line as words, timings replaced (see the module documentation).
fn normalise(line: &str) -> Vec<String> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let mut out = Vec::with_capacity(words.len());
    for (i, w) in words.iter().enumerate() {
        let unit_follows = words
            .get(i + 1)
            .is_some_and(|next| matches!(*next, "s" | "s," | "s;" | "s)"));
        let four_decimals = is_number(w) && w.split('.').nth(1).is_some_and(|f| f.len() == 4);
        if (is_number(w) && unit_follows) || four_decimals {
            out.push("N".to_string());
        } else {
            out.push(w.to_string());
        }
    }
    out
}

/// The lines without trailing empty ones.
fn trim_end(lines: &[String]) -> &[String] {
    let mut n = lines.len();
    while n > 0 && lines[n - 1].trim().is_empty() {
        n -= 1;
    }
    &lines[..n]
}

/// The number of leading lines that form one JSON value (the report), if the lines
/// start with `{`; the value with its timings blanked.
fn json_prefix(lines: &[String]) -> Option<(usize, serde_json::Value)> {
    if !lines.first()?.trim_start().starts_with('{') {
        return None;
    }
    (1..=lines.len()).find_map(|k| {
        let mut v: serde_json::Value = serde_json::from_str(&lines[..k].join("\n")).ok()?;
        blank_seconds(&mut v);
        Some((k, v))
    })
}

/// Compares shown and actual output. The error names the first difference and the
/// index of the shown line where it is (`shown.len()` when the actual output is
/// longer). A JSON report at the start is compared as a value, the lines after it as
/// text.
fn compare(shown: &[String], actual: &str) -> Result<(), (usize, String)> {
    let shown = trim_end(shown);
    let actual: Vec<String> = actual.lines().map(str::to_string).collect();
    let actual = trim_end(&actual);
    let stale = |at: usize, what: String| {
        Err((at, format!("{what}\nactual output:\n{}", actual.join("\n"))))
    };
    let (mut shown_rest, mut actual_rest, mut skipped) = (shown, actual, 0);
    if shown
        .first()
        .is_some_and(|l| l.trim_start().starts_with('{'))
    {
        let Some((ks, s)) = json_prefix(shown) else {
            return stale(0, "the JSON shown does not parse".into());
        };
        let Some((ka, a)) = json_prefix(actual) else {
            return stale(0, "the actual output is not JSON".into());
        };
        if s != a {
            return stale(0, "the JSON differs (timings aside)".into());
        }
        (shown_rest, actual_rest, skipped) = (&shown[ks..], &actual[ka..], ks);
    }
    for i in 0..shown_rest.len().max(actual_rest.len()) {
        let s = shown_rest.get(i).map(|l| normalise(l));
        let a = actual_rest.get(i).map(|l| normalise(l));
        if s != a {
            return stale(
                skipped + i,
                format!(
                    "a line differs\n  shown:  {}\n  actual: {}",
                    shown_rest.get(i).map_or("(nothing)", |l| l.as_str()),
                    actual_rest.get(i).map_or("(nothing)", |l| l.as_str()),
                ),
            );
        }
    }
    Ok(())
}

fn blank_seconds(v: &mut serde_json::Value) {
    match v {
        serde_json::Value::Object(map) => {
            for (k, x) in map.iter_mut() {
                if k.contains("seconds") {
                    *x = serde_json::Value::Null;
                } else {
                    blank_seconds(x);
                }
            }
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(blank_seconds),
        _ => {}
    }
}

/// Runs the binary in `dir` with stdout and stderr into one file, so that their lines
/// keep the order in which they were written. Returns the text and the exit code.
fn run_merged(args: &[String], dir: &Path) -> (String, Option<i32>) {
    let log = dir.join(".transcript-output");
    let file = File::create(&log).expect("create the output file");
    let status = Command::new(env!("CARGO_BIN_EXE_contractible"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(file.try_clone().expect("clone the output file"))
        .stderr(file)
        .status()
        .expect("run contractible");
    let text = std::fs::read_to_string(&log).expect("read the output");
    let _ = std::fs::remove_file(&log);
    (text, status.code())
}

/// Splits a command line into arguments: spaces separate, `'…'` quotes.
fn split_args(line: &str) -> Vec<String> {
    let mut args = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    let mut any = false;
    for ch in line.chars() {
        match ch {
            '\'' => {
                quoted = !quoted;
                any = true;
            }
            c if c.is_whitespace() && !quoted => {
                if any {
                    args.push(std::mem::take(&mut cur));
                    any = false;
                }
            }
            c => {
                cur.push(c);
                any = true;
            }
        }
    }
    assert!(!quoted, "unbalanced quote in `{line}`");
    if any {
        args.push(cur);
    }
    args
}

/// The command without a trailing `# comment` (a `#` after a space, outside quotes).
fn strip_comment(line: &str) -> &str {
    let mut quoted = false;
    let bytes = line.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        match b {
            b'\'' => quoted = !quoted,
            b'#' if !quoted && i > 0 && bytes[i - 1] == b' ' => return line[..i].trim_end(),
            _ => {}
        }
    }
    line.trim_end()
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("create dir");
    for entry in std::fs::read_dir(from).expect("read dir") {
        let entry = entry.expect("dir entry");
        let target = to.join(entry.file_name());
        if entry.file_type().expect("file type").is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), &target).expect("copy file");
        }
    }
}

/// Runs every transcript of `doc` (see the module documentation); returns how many
/// commands ran. Panics naming the document's line at the first difference.
fn check_transcripts(doc: &str) -> usize {
    let text = read_doc(doc);
    let found = blocks(&text, "shell-example", doc);
    assert!(
        !found.is_empty(),
        "{doc}: no <!-- shell-example --> block (were the markers removed?)"
    );
    let mut commands = 0;
    for (b, (_, lines)) in found.iter().enumerate() {
        let scratch = Scratch::new(&format!("docs-{}-{b}", doc.replace(['/', '.'], "_")));
        copy_dir(
            &repo().join("tests/data/meshes"),
            &scratch.path("tests/data/meshes"),
        );
        let mut i = 0;
        let mut last_code: Option<i32> = None;
        while i < lines.len() {
            let (at, line) = (lines[i].0, lines[i].1.trim_end());
            i += 1;
            if line.trim().is_empty() {
                continue;
            }
            let command = line
                .strip_prefix("$ ")
                .unwrap_or_else(|| panic!("{doc}:{at}: output before any command: `{line}`"));
            let command = strip_comment(command);
            let mut shown: Vec<Line> = Vec::new();
            if let Some(rest) = command.strip_prefix("cat > ") {
                let (file, marker) = rest
                    .split_once(" << ")
                    .unwrap_or_else(|| panic!("{doc}:{at}: expected `cat > FILE << 'EOF'`"));
                let marker = marker.trim_matches('\'');
                let mut content = String::new();
                while i < lines.len() && lines[i].1.trim_end() != marker {
                    content.push_str(&lines[i].1);
                    content.push('\n');
                    i += 1;
                }
                assert!(i < lines.len(), "{doc}:{at}: `{marker}` never comes");
                i += 1;
                std::fs::write(scratch.path(file.trim()), content).expect("write the file");
                continue;
            }
            while i < lines.len() && !lines[i].1.starts_with("$ ") {
                shown.push(lines[i].clone());
                i += 1;
            }
            let actual = if command == "echo $?" {
                format!("{}\n", last_code.map_or("?".to_string(), |c| c.to_string()))
            } else {
                let args = split_args(command);
                assert_eq!(
                    args.first().map(String::as_str),
                    Some("contractible"),
                    "{doc}:{at}: only `contractible`, `echo $?` and `cat > FILE << 'EOF'` \
                     run in a transcript: `{command}`"
                );
                let (text, code) = run_merged(&args[1..], &scratch.0);
                last_code = code;
                commands += 1;
                text
            };
            let text: Vec<String> = shown.iter().map(|(_, l)| l.clone()).collect();
            if let Err((k, e)) = compare(&text, &actual) {
                let line = shown.get(k).map_or(at, |(n, _)| *n);
                panic!("{doc}:{line}: `{command}`: the document is stale: {e}");
            }
        }
    }
    commands
}

#[test]
fn normalising_keeps_everything_but_timings() {
    assert_eq!(
        normalise("  rs   6119  0  9981  15     0.0054"),
        ["rs", "6119", "0", "9981", "15", "N"]
    );
    assert_eq!(
        normalise("time: read 0.004 s, check input 0.000 s, rs 12.5 s"),
        ["time:", "read", "N", "s,", "check", "input", "N", "s,", "rs", "N", "s"]
    );
    // Counts, percentages, ε and means are not timings.
    assert_eq!(
        normalise("lrs 10000 99.810 38 ε = 0.0458258 mean 6.00"),
        [
            "lrs",
            "10000",
            "99.810",
            "38",
            "ε",
            "=",
            "0.0458258",
            "mean",
            "6.00"
        ]
    );
    assert!(compare(&["a 1.0000".into()], "a 2.5000\n").is_ok());
    assert!(compare(&["a 1".into()], "a 2\n").is_err());
    assert!(compare(&["a".into()], "a\nb\n").is_err());
    assert!(compare(
        &[r#"{"n": 1, "seconds_read": 0.5}"#.into()],
        r#"{"n": 1, "seconds_read": 9}"#
    )
    .is_ok());
    assert!(compare(&[r#"{"n": 1}"#.into()], r#"{"n": 2}"#).is_err());
    assert_eq!(
        split_args("contractible batch 'a b/*.off' -j 2"),
        ["contractible", "batch", "a b/*.off", "-j", "2"]
    );
    assert_eq!(
        strip_comment("contractible info x.off   # note"),
        "contractible info x.off"
    );
}

#[test]
fn demo_output_shown_in_docs_demo_md_is_the_binary_s() {
    let doc = "docs/demo.md";
    let text = read_doc(doc);
    let found = blocks(&text, "demo-output", doc);
    assert_eq!(
        found.len(),
        1,
        "{doc}: expected one <!-- demo-output --> block"
    );
    let (start, lines) = &found[0];
    let shown: Vec<String> = lines.iter().map(|(_, l)| l.clone()).collect();
    assert!(
        trim_end(&shown).len() > 10,
        "{doc}:{start}: the block is (almost) empty"
    );
    let scratch = Scratch::new("docs-demo");
    let (actual, code) = run_merged(&["demo".to_string()], &scratch.0);
    assert_eq!(code, Some(0), "demo failed:\n{actual}");
    if let Err((k, e)) = compare(&shown, &actual) {
        let line = lines.get(k).map_or(*start, |(n, _)| *n);
        panic!("{doc}:{line}: the demo output shown is stale: {e}");
    }
}

#[test]
fn shell_examples_in_the_readme_are_the_binary_s() {
    assert!(check_transcripts("README.md") > 0);
}

#[test]
fn shell_examples_in_docs_cli_md_are_the_binary_s() {
    assert!(check_transcripts("docs/cli.md") > 0);
}
