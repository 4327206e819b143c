//! The output side of the command line: outputs checked before any work (exit code 2),
//! nothing left behind by SIGINT/SIGTERM, a closed or full stdout, `-o -`, the JSON's
//! key types across every command, the verification step and its timing, completions
//! and the man page, and the help texts.

use crate::cli_common;

use std::collections::BTreeMap;
use std::ffi::OsStr;
use std::io::{BufRead, BufReader};
use std::os::unix::process::ExitStatusExt;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use cli_common::{load, mid_surface_file, run, run_json, run_ok, stderr, Scratch};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_contractible"))
}

/// Every file in `dir` (hidden ones included).
fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// A missing output directory is refused before the input is opened: the input is a
/// named pipe with no writer, which any attempt to read would wait on forever (the test
/// kills a command still running after 20 s and fails).
#[test]
fn a_missing_output_directory_fails_at_once_before_reading() {
    // The input lives apart from the directory that must stay empty.
    let inputs = Scratch::new("out-missing-input");
    let fifo = inputs.path("never_written.off");
    let made = Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("run mkfifo");
    assert!(made.success(), "mkfifo {}", fifo.display());
    let big = fifo;
    let dir = Scratch::new("out-missing");
    let missing = dir.path("missing_dir/x.off");
    let cases: Vec<Vec<&OsStr>> = vec![
        vec![
            "reduce".as_ref(),
            big.as_os_str(),
            "-o".as_ref(),
            missing.as_os_str(),
        ],
        vec![
            "quad".as_ref(),
            big.as_os_str(),
            "-o".as_ref(),
            missing.as_os_str(),
        ],
        vec![
            "simplify".as_ref(),
            big.as_os_str(),
            "--eps-rel".as_ref(),
            "0.01".as_ref(),
            "-o".as_ref(),
            missing.as_os_str(),
        ],
        vec!["convert".as_ref(), big.as_os_str(), missing.as_os_str()],
        vec![
            "gen".as_ref(),
            "subdivide".as_ref(),
            "--input".as_ref(),
            big.as_os_str(),
            "-o".as_ref(),
            missing.as_os_str(),
        ],
    ];
    for args in cases {
        let mut child = Command::new(env!("CARGO_BIN_EXE_contractible"))
            .args(&args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("run contractible");
        let t = Instant::now();
        while child.try_wait().expect("wait").is_none() {
            if t.elapsed() > Duration::from_secs(20) {
                let _ = child.kill();
                let _ = child.wait();
                panic!("{args:?} opened the input before refusing the output");
            }
            std::thread::sleep(Duration::from_millis(10));
        }
        let out = child.wait_with_output().expect("output");
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = stderr(&out);
        assert!(
            err.contains("x.off: the directory") && err.contains("missing_dir does not exist"),
            "{args:?}: {err}"
        );
    }
    assert_eq!(files_in(&dir.0), Vec::<String>::new());
}

#[test]
fn bad_outputs_are_refused_with_exit_2_and_leave_nothing() {
    let dir = Scratch::new("out-bad");
    let torus = dir.path("t.off");
    run_ok(&[
        OsStr::new("gen"),
        "torus7".as_ref(),
        "-o".as_ref(),
        torus.as_os_str(),
    ]);
    let t = torus.as_os_str();
    let bad = |args: &[&OsStr], needle: &str| {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = stderr(&out);
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    };
    let o = |name: &str| dir.path(name).into_os_string();
    // Unknown extension, the input itself, a directory, a file as directory.
    bad(
        &["reduce".as_ref(), t, "-o".as_ref(), &o("x.txt")],
        "cannot choose a format",
    );
    bad(
        &["reduce".as_ref(), t, "-o".as_ref(), t],
        "this is the input file",
    );
    bad(&["convert".as_ref(), t, t], "this is the input file");
    bad(
        &["reduce".as_ref(), t, "-o".as_ref(), dir.0.as_os_str()],
        "is a directory",
    );
    bad(
        &["reduce".as_ref(), t, "-o".as_ref(), &o("t.off/x.off")],
        "is not a directory",
    );
    bad(
        &["quad".as_ref(), t, "--pairs".as_ref(), &o("nowhere/p.txt")],
        "does not exist",
    );
    bad(
        &["quad".as_ref(), t, "--pairs".as_ref(), t],
        "this is the input file",
    );
    // A file system where nothing can be created (root ignores permissions).
    bad(
        &["reduce".as_ref(), t, "-o".as_ref(), "/proc/x.off".as_ref()],
        "cannot create a file in /proc",
    );
    // `-` needs a format; a format that contradicts the name is refused.
    bad(
        &["reduce".as_ref(), t, "-o".as_ref(), "-".as_ref()],
        "needs --output-format",
    );
    bad(
        &[
            "reduce".as_ref(),
            t,
            "-o".as_ref(),
            &o("x.ply"),
            "--output-format".as_ref(),
            "off".as_ref(),
        ],
        "--output-format off disagrees with the file name, which says ply",
    );
    bad(
        &[
            "quad".as_ref(),
            t,
            "-o".as_ref(),
            "-".as_ref(),
            "--output-format".as_ref(),
            "off".as_ref(),
            "--pairs".as_ref(),
            "-".as_ref(),
        ],
        "would both write to stdout",
    );
    assert_eq!(files_in(&dir.0), vec!["t.off".to_string()]);
    // `--pairs -`: the pairs on stdout, as many lines as quads; the report on stderr.
    let out = run_ok(&[
        OsStr::new("--json"),
        "quad".as_ref(),
        t,
        "--pairs".as_ref(),
        "-".as_ref(),
    ]);
    let lines = String::from_utf8_lossy(&out.stdout).lines().count();
    let j: serde_json::Value = serde_json::from_slice(&out.stderr).expect("JSON on stderr");
    assert_eq!(lines as i64, cli_common::int(&j, "quads"));
    assert_eq!(files_in(&dir.0), vec!["t.off".to_string()]);
}

/// Starts `args`, waits until a non-empty temporary output appears in `dir`, sends
/// `signal`, and checks that the process died of it leaving `dir` as it was.
fn interrupt_large_write(signal: &str, number: i32) {
    let dir = Scratch::new(&format!("out-{signal}"));
    let out = dir.path("big.off");
    let mut child = bin()
        .args(["gen", "brick", "--paper", "B0", "-o"])
        .arg(&out)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("spawn");
    let started = Instant::now();
    let mut seen = false;
    while started.elapsed() < Duration::from_secs(120) {
        let writing = std::fs::read_dir(&dir.0).expect("dir").any(|e| {
            let e = e.expect("entry");
            e.file_name()
                .to_string_lossy()
                .starts_with(".contractible-")
                && e.metadata().map(|m| m.len() > 1 << 20).unwrap_or(false)
        });
        if writing {
            seen = true;
            break;
        }
        if child.try_wait().expect("try_wait").is_some() {
            break;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    assert!(seen, "no temporary file was seen being written");
    let status = Command::new("kill")
        .arg(format!("-{signal}"))
        .arg(child.id().to_string())
        .status()
        .expect("kill");
    assert!(status.success());
    let st = child.wait().expect("wait");
    assert_eq!(st.signal(), Some(number), "{st:?}");
    assert_eq!(files_in(&dir.0), Vec::<String>::new(), "left behind");
}

#[test]
fn sigterm_during_a_large_write_leaves_no_file() {
    interrupt_large_write("TERM", 15);
}

#[test]
fn sigint_during_a_large_write_leaves_no_file() {
    interrupt_large_write("INT", 2);
}

#[test]
fn demo_piped_into_head_ends_quietly_by_sigpipe() {
    let mut child = bin()
        .arg("demo")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    let mut line = String::new();
    {
        let mut r = BufReader::new(child.stdout.take().expect("stdout"));
        r.read_line(&mut line).expect("read a line");
    } // `head -1` exits: the pipe's read end closes.
    let out = child.wait_with_output().expect("wait");
    assert!(line.starts_with("random genus 3"), "{line}");
    assert_eq!(out.status.signal(), Some(13), "{:?}", out.status);
    assert_eq!(stderr(&out), "", "nothing on stderr");
}

#[test]
fn a_mesh_on_stdout_piped_into_head_ends_quietly_by_sigpipe() {
    let mut child = bin()
        .args([
            "gen",
            "brick",
            "--paper",
            "B4",
            "-o",
            "-",
            "--output-format",
            "off",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    let mut line = String::new();
    {
        let mut r = BufReader::new(child.stdout.take().expect("stdout"));
        r.read_line(&mut line).expect("read a line");
    }
    let out = child.wait_with_output().expect("wait");
    assert_eq!(line, "OFF\n");
    assert_eq!(out.status.signal(), Some(13), "{:?}", out.status);
    let err = stderr(&out);
    assert!(!err.contains("panicked") && !err.contains("error"), "{err}");
}

#[test]
fn a_full_stdout_is_one_error_line_and_exit_1() {
    let full = || {
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full")
    };
    for args in [
        vec!["demo"],
        vec![
            "--json",
            "gen",
            "torus7",
            "-o",
            "-",
            "--output-format",
            "off",
        ],
        vec!["gen", "torus7", "-o", "-", "--output-format", "ply"],
    ] {
        let out = bin()
            .args(&args)
            .stdout(full())
            .stderr(Stdio::piped())
            .output()
            .expect("run");
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = stderr(&out);
        let errors: Vec<&str> = err.lines().filter(|l| l.starts_with("error:")).collect();
        assert_eq!(errors.len(), 1, "{args:?}: {err}");
        assert!(errors[0].contains("No space left on device"), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn dash_writes_the_mesh_to_stdout_and_the_report_to_stderr() {
    let dir = Scratch::new("out-stdout");
    let input = mid_surface_file(&dir);
    let file = dir.path("r.off");
    run_ok(&[
        OsStr::new("reduce"),
        input.as_os_str(),
        "-o".as_ref(),
        file.as_os_str(),
    ]);
    let out = run_ok(&[
        OsStr::new("--json"),
        "reduce".as_ref(),
        input.as_os_str(),
        "-o".as_ref(),
        "-".as_ref(),
        "--output-format".as_ref(),
        "off".as_ref(),
    ]);
    // The same bytes as the file; the JSON report on stderr says where it went.
    assert_eq!(out.stdout, std::fs::read(&file).expect("file"));
    let j: serde_json::Value = serde_json::from_slice(&out.stderr).expect("JSON on stderr");
    assert_eq!(j["output"], "-");
    assert!(j["seconds_write"].as_f64().is_some());
    // Every format, from every command that writes a mesh.
    let torus = dir.path("t.off");
    run_ok(&[
        OsStr::new("gen"),
        "torus7".as_ref(),
        "-o".as_ref(),
        torus.as_os_str(),
    ]);
    for (format, magic) in [
        ("off", &b"OFF"[..]),
        ("obj", b"v "),
        ("ply", b"ply"),
        ("stl", b"contractible"),
    ] {
        for args in [
            vec!["gen", "torus7", "-o", "-"],
            vec!["convert", torus.to_str().expect("utf-8"), "-"],
        ] {
            let mut all: Vec<&str> = vec!["-q"];
            all.extend(&args);
            all.extend(["--output-format", format]);
            let out = run_ok(&all);
            assert!(
                out.stdout
                    .windows(magic.len())
                    .take(200)
                    .any(|w| w == magic),
                "{all:?}"
            );
            let back = dir.path(&format!("back.{format}"));
            std::fs::write(&back, &out.stdout).expect("write");
            let (mesh, _) = load(&back);
            assert_eq!(mesh.faces.len(), 14, "{all:?}");
        }
    }
}

/// The JSON type of a value, `null` apart.
fn kind(v: &serde_json::Value) -> Option<&'static str> {
    use serde_json::Value;
    match v {
        Value::Null => None,
        Value::Bool(_) => Some("bool"),
        Value::Number(n) if n.is_f64() => Some("float"),
        Value::Number(_) => Some("integer"),
        Value::String(_) => Some("string"),
        Value::Array(_) => Some("array"),
        Value::Object(_) => Some("object"),
    }
}

/// Records the type of every key of every object in `v`, recursively. A float key may
/// hold a whole number (serde writes 2.0 as 2.0, but a sum of integers may be integral),
/// so "integer" and "float" are told apart only by the key's other occurrences.
fn collect(
    v: &serde_json::Value,
    source: &str,
    seen: &mut BTreeMap<String, BTreeMap<&'static str, String>>,
) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                if let Some(t) = kind(x) {
                    seen.entry(k.clone())
                        .or_default()
                        .entry(t)
                        .or_insert_with(|| source.to_string());
                }
                collect(x, source, seen);
            }
        }
        serde_json::Value::Array(a) => {
            for x in a {
                collect(x, source, seen);
            }
        }
        _ => {}
    }
}

#[test]
fn every_json_key_has_one_type_in_every_command() {
    let dir = Scratch::new("out-json");
    let p = |name: &str| dir.path(name).to_string_lossy().into_owned();
    // A mid-sized closed surface (a sphere of radius 1).
    let sphere = mid_surface_file(&dir).to_string_lossy().into_owned();
    let hyper = p("hyper.off");
    let runs: Vec<Vec<String>> = vec![
        vec!["gen".into(), "torus7".into(), "-o".into(), p("t.off")],
        vec![
            "gen".into(),
            "random".into(),
            "--genus".into(),
            "2".into(),
            "-o".into(),
            p("r.off"),
        ],
        vec![
            "gen".into(),
            "isosurface".into(),
            "--surface".into(),
            "hyperboloid".into(),
            "--resolution".into(),
            "12".into(),
            "-o".into(),
            hyper.clone(),
        ],
        vec!["info".into(), p("t.off")],
        vec!["info".into(), hyper.clone()],
        vec!["convert".into(), p("t.off"), p("t.ply")],
        vec![
            "convert".into(),
            "--no-validate".into(),
            p("t.off"),
            p("t2.obj"),
        ],
        vec!["reduce".into(), sphere.clone(), "-o".into(), p("red.off")],
        vec!["reduce".into(), "--no-verify".into(), p("r.off")],
        vec!["reduce".into(), "--algo".into(), "brute".into(), p("r.off")],
        vec![
            "quad".into(),
            p("r.off"),
            "-o".into(),
            p("q.off"),
            "--pairs".into(),
            p("q.txt"),
        ],
        vec!["quad".into(), sphere.clone()],
        vec![
            "simplify".into(),
            hyper.clone(),
            "--eps-rel".into(),
            "0.05".into(),
            "-o".into(),
            p("s.off"),
        ],
        vec![
            "simplify".into(),
            sphere,
            "--eps".into(),
            "0.01".into(),
            "-o".into(),
            p("s2.off"),
        ],
        vec!["demo".into(), "--algos".into(), "rs".into()],
    ];
    let mut seen = BTreeMap::new();
    for args in &runs {
        let j = run_json(args);
        collect(&j, &args[..2].join(" "), &mut seen);
    }
    let mut clashes = Vec::new();
    for (key, types) in &seen {
        let mut t: Vec<&&str> = types.keys().collect();
        // An integer-valued float (a total that happens to be whole) is still a number.
        if t.len() == 2 && types.contains_key("float") && types.contains_key("integer") {
            let floats_only = key.starts_with("seconds")
                || key.ends_with("_seconds")
                || key.ends_with("_percent")
                || key.starts_with("degree_mean")
                || ["eps", "eps_rel", "bbox_diagonal", "shortest_remaining_edge"]
                    .contains(&key.as_str());
            if floats_only {
                t.retain(|k| **k == "float");
            }
        }
        if t.len() > 1 {
            clashes.push(format!("{key}: {types:?}"));
        }
    }
    assert!(
        clashes.is_empty(),
        "keys with several types:\n{}",
        clashes.join("\n")
    );
    assert!(seen.contains_key("seconds_verify"));
    assert!(seen.contains_key("seconds_write"));
}

/// Every `seconds*` value in `v`, recursively, with its key.
fn timings(v: &serde_json::Value, out: &mut Vec<(String, f64)>) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                if k.starts_with("seconds") {
                    out.push((k.clone(), x.as_f64().unwrap_or(f64::NAN)));
                }
                timings(x, out);
            }
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| timings(x, out)),
        _ => {}
    }
}

#[test]
fn timings_are_measured_never_placeholders() {
    // A step that did not run has no timing (see the test above); one that ran took
    // some nanoseconds at least: a 0 would be a placeholder.
    let dir = Scratch::new("out-timings");
    let t = dir.path("t.off");
    let o = dir.path("o.off");
    let mut all = Vec::new();
    for args in [
        vec![
            OsStr::new("gen"),
            "torus7".as_ref(),
            "-o".as_ref(),
            t.as_os_str(),
        ],
        vec![OsStr::new("info"), t.as_os_str()],
        vec![OsStr::new("convert"), t.as_os_str(), o.as_os_str()],
        vec![
            OsStr::new("reduce"),
            t.as_os_str(),
            "-o".as_ref(),
            o.as_os_str(),
        ],
        vec![
            OsStr::new("quad"),
            t.as_os_str(),
            "-o".as_ref(),
            o.as_os_str(),
        ],
        vec![OsStr::new("demo"), "--algos".as_ref(), "rs".as_ref()],
    ] {
        timings(&run_json(&args), &mut all);
    }
    assert!(all.len() > 20, "{all:?}");
    let bad: Vec<_> = all
        .iter()
        .filter(|(_, x)| x.is_nan() || *x <= 0.0)
        .collect();
    assert!(bad.is_empty(), "{bad:?}");
}

#[test]
fn verification_is_its_own_timed_step_and_timings_are_absent_when_not_done() {
    let dir = Scratch::new("out-verify");
    let t = dir.path("t.off");
    run_ok(&[
        OsStr::new("gen"),
        "random".as_ref(),
        "--genus".as_ref(),
        "3".as_ref(),
        "-o".as_ref(),
        t.as_os_str(),
    ]);
    let o = dir.path("o.off");
    let j = run_json(&[
        OsStr::new("reduce"),
        t.as_os_str(),
        "-o".as_ref(),
        o.as_os_str(),
    ]);
    assert!(j["seconds_verify"].as_f64().is_some_and(|x| x > 0.0), "{j}");
    assert!(j["seconds_write"].as_f64().is_some_and(|x| x > 0.0), "{j}");
    assert_eq!(j["verified_by"], "naive");
    assert_eq!(j["component_list"][0]["verified_by"], "naive");
    let j = run_json(&[OsStr::new("reduce"), "--no-verify".as_ref(), t.as_os_str()]);
    for k in ["seconds_verify", "seconds_write", "verified_by"] {
        assert!(j.get(k).is_none(), "{k} present: {j}");
    }
    assert!(j["irreducible"].is_null());
    let j = run_json(&[OsStr::new("quad"), t.as_os_str()]);
    assert!(j["seconds_verify"].as_f64().is_some_and(|x| x > 0.0), "{j}");
    assert!(j.get("seconds_write").is_none());
    // `gen` and `demo` describe meshes they did not read: no read or build time.
    let j = run_json(&[
        OsStr::new("gen"),
        "torus7".as_ref(),
        "-o".as_ref(),
        o.as_os_str(),
    ]);
    assert!(
        j.get("seconds_read").is_none() && j.get("seconds_build").is_none(),
        "{j}"
    );
    let human = String::from_utf8_lossy(
        &run_ok(&[
            OsStr::new("reduce"),
            t.as_os_str(),
            "-o".as_ref(),
            o.as_os_str(),
        ])
        .stdout,
    )
    .into_owned();
    assert!(
        human.contains("verify ")
            && human.contains("naive link test on every edge")
            && human.contains("write "),
        "{human}"
    );
}

#[test]
fn completions_and_the_man_page_cover_every_subcommand() {
    let subcommands = [
        "info",
        "gen",
        "convert",
        "reduce",
        "quad",
        "simplify",
        "demo",
        "completions",
        "man",
    ];
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let out = run_ok(&["completions", shell]);
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.len() > 1000, "{shell}: {} bytes", text.len());
        for s in subcommands {
            assert!(text.contains(s), "{shell}: no {s}");
        }
        assert!(text.contains("output-format"), "{shell}");
    }
    let out = run_ok(&["man"]);
    let man = String::from_utf8_lossy(&out.stdout);
    assert!(
        man.starts_with(".ie") || man.contains(".TH contractible"),
        "{man}"
    );
    assert!(man.contains(".SH NAME") && man.contains(".SH SYNOPSIS"));
    for s in subcommands {
        assert!(man.contains(s), "man: no {s}");
    }
    let bad = run(&["completions", "tcsh"]);
    assert_eq!(bad.status.code(), Some(2));
}

#[test]
fn help_explains_the_counters_and_lists_what_exists() {
    // Words joined by single spaces: clap wraps the text to the terminal's width.
    let help = |args: &[&str]| {
        String::from_utf8_lossy(&run_ok(args).stdout)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
    };
    let top = help(&["--help"]);
    for s in [
        "info",
        "gen",
        "convert",
        "reduce",
        "quad",
        "simplify",
        "demo",
        "completions",
        "man",
    ] {
        assert!(top.contains(&format!(" {s} ")), "--help lacks {s}:\n{top}");
        // Every subcommand's help works.
        help(&[s, "--help"]);
    }
    for g in [
        "random",
        "brick",
        "subdivide",
        "isosurface",
        "tetrahedron",
        "octahedron",
        "icosahedron",
        "torus7",
        "rp2",
        "klein",
    ] {
        help(&["gen", g, "--help"]);
    }
    for cmd in ["reduce", "demo"] {
        let h = help(&[cmd, "--help"]);
        assert!(
            h.contains("ℓ is the number of link-condition tests"),
            "{cmd}: {h}"
        );
        assert!(
            h.contains("ε is the number of edges tested more than once"),
            "{cmd}: {h}"
        );
    }
    let h = help(&["simplify", "--help"]);
    assert!(h.contains("ε (--eps, or --eps-rel"), "{h}");
    assert!(h.contains("unrelated to the ε column of `reduce`"), "{h}");
    // The formats listed are the ones that exist.
    let h = help(&["convert", "--help"]);
    assert!(h.contains(".off/.obj/.ply/.stl"), "{h}");
    assert!(h.contains("--output-format"), "{h}");
}
