//! `contractible conformance` and `contractible answer`: the harness over the
//! repository's suite (`spec/vectors`, `spec/suite`) with this library's adapter (every
//! case passes, with `--exact` too), with the deliberately wrong adapter of
//! `cli/examples/wrong_adapter.rs` (it fails where it must, and `--script` lists those
//! failures as known ones), the selection flags, timeouts, and the checker's self-test.

use std::path::PathBuf;

use serde_json::Value;

use crate::cli_common::{run, stderr, Scratch};

fn suite() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../spec")
}

/// The suite's lines of `spec/suite/NAME`.
fn case_lines(name: &str) -> Vec<Value> {
    std::fs::read_to_string(suite().join("suite").join(name))
        .expect("the case file")
        .lines()
        .map(|l| serde_json::from_str(l).expect("a JSON line"))
        .collect()
}

/// `contractible answer` as a command line for `--impl`.
fn ours() -> String {
    format!("{} answer", env!("CARGO_BIN_EXE_contractible"))
}

/// The wrong adapter, which `cargo test` builds with the package's examples.
fn wrong() -> String {
    let exe = std::env::current_exe().expect("the test binary");
    // target/PROFILE/deps/cli-HASH -> target/PROFILE/examples/wrong_adapter
    let path = exe
        .parent()
        .and_then(|deps| deps.parent())
        .map(|p| p.join("examples").join("wrong_adapter"))
        .expect("the target folder");
    assert!(
        path.is_file(),
        "{} is missing: `cargo test` builds the examples of contractible-cli",
        path.display()
    );
    path.display().to_string()
}

fn harness(args: &[&str]) -> (Option<i32>, Value, String) {
    let s = suite();
    let mut all = vec!["--json", "conformance", "--suite", s.to_str().unwrap()];
    all.extend_from_slice(args);
    let out = run(&all);
    let report = serde_json::from_slice(&out.stdout).unwrap_or(Value::Null);
    (out.status.code(), report, stderr(&out))
}

fn total(report: &Value, key: &str) -> u64 {
    report["totals"]
        .as_array()
        .map_or(0, |t| t.iter().map(|x| x[key].as_u64().unwrap_or(0)).sum())
}

#[test]
fn our_adapter_passes_every_case_with_and_without_exact() {
    let invalid = case_lines("invalid.jsonl").len() as u64;
    for exact in [false, true] {
        let o = ours();
        let mut args = vec!["--impl", o.as_str(), "-j", "2"];
        if exact {
            args.push("--exact");
        }
        let (code, r, err) = harness(&args);
        assert_eq!(code, Some(0), "{err}");
        assert_eq!(r["passed"], true);
        assert_eq!(r["exact"], exact);
        assert_eq!(total(&r, "failed") + total(&r, "timed_out"), 0);
        // Every vector run is a valid case: 3 reductions per input of the four
        // irreducible groups, one case per run of the others.
        assert!(total(&r, "passed") > 1400, "{}", total(&r, "passed"));
        // The invalid inputs are refused, each with the kind the suite states.
        assert_eq!(total(&r, "refused"), invalid);
        let kinds: std::collections::HashMap<String, String> = case_lines("invalid.jsonl")
            .iter()
            .map(|c| {
                (
                    c["id"].as_str().unwrap().to_owned(),
                    c["kind"].as_str().unwrap().to_owned(),
                )
            })
            .collect();
        for c in r["cases"].as_array().expect("cases") {
            if c["class"] == "invalid" {
                let said = c["reasons"][0].as_str().unwrap_or("");
                let want = &kinds[c["id"].as_str().unwrap()];
                assert!(said.starts_with(&format!("{want}:")), "{c}");
            }
        }
        assert_eq!(
            r["checker_self_test"],
            case_lines("wrong-answers.jsonl").len()
        );
    }
}

#[test]
fn the_wrong_adapter_fails_where_it_must_and_script_lists_its_failures() {
    let w = wrong();
    let (code, r, _) = harness(&["--impl", &w, "-j", "2"]);
    assert_eq!(code, Some(1));
    assert_eq!(r["passed"], false);
    let cases = r["cases"].as_array().expect("cases");
    let verdict = |id: &str| {
        cases
            .iter()
            .find(|c| c["id"] == id)
            .map(|c| c["verdict"].as_str().unwrap_or("").to_owned())
            .unwrap_or_else(|| panic!("no case {id}"))
    };
    // It never refuses: every invalid case fails.
    for c in cases.iter().filter(|c| c["class"] == "invalid") {
        assert_eq!(c["verdict"], "failed", "{c}");
        assert!(c["reasons"][0]
            .as_str()
            .unwrap_or("")
            .contains("must refuse"));
    }
    // Its "reduction" of a reducible input is the input: contractible edges.
    assert_eq!(
        verdict("reduce/generated/random_S0_f100_p30_s1/rs"),
        "failed"
    );
    let c = cases
        .iter()
        .find(|c| c["id"] == "reduce/generated/random_S0_f100_p30_s1/rs")
        .expect("the case");
    assert!(c["reasons"][0]
        .as_str()
        .unwrap_or("")
        .starts_with("contractible_edge:"));
    // ... and of an irreducible input is right.
    assert_eq!(verdict("reduce/torus/torus_T1_n7/rs"), "passed");
    // Its simplification leaves short edges; its greedy pairing leaves triangles.
    assert!(cases
        .iter()
        .any(|c| c["task"] == "simplify" && c["verdict"] == "failed"));
    assert!(cases.iter().any(|c| c["task"] == "quad"
        && c["reasons"].as_array().is_some_and(|r| r
            .iter()
            .any(|x| x.as_str().unwrap_or("").starts_with("triangle_unused:")))));
    // --script prints the failures as --skip arguments; skipping them, the run passes.
    let s = suite();
    let out = run(&[
        "conformance",
        "--suite",
        s.to_str().unwrap(),
        "--impl",
        &w,
        "--script",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let script = String::from_utf8_lossy(&out.stdout).into_owned();
    let skips: Vec<String> = script
        .lines()
        .map(|l| {
            l.strip_prefix("--skip ")
                .expect("a --skip line")
                .trim_matches('\'')
                .to_owned()
        })
        .collect();
    assert_eq!(skips.len() as u64, total(&r, "failed"));
    let mut args: Vec<&str> = vec!["--impl", &w];
    for id in &skips {
        args.extend(["--skip", id.as_str()]);
    }
    let (code, again, err) = harness(&args);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(total(&again, "skipped"), skips.len() as u64);
    assert_eq!(total(&again, "passed"), total(&r, "passed"));
}

#[test]
fn cases_are_selected_by_task_class_and_glob() {
    let o = ours();
    let (code, r, _) = harness(&["--impl", &o, "--task", "quad", "--class", "invalid"]);
    assert_eq!(code, Some(0));
    let cases = r["cases"].as_array().expect("cases");
    assert!(!cases.is_empty());
    assert!(cases
        .iter()
        .all(|c| c["task"] == "quad" && c["class"] == "invalid"));
    let (_, r, _) = harness(&[
        "--impl",
        &o,
        "--run",
        "reduce/torus/*",
        "--run",
        "simplify/*/run0",
        "--skip",
        "*/schipper",
    ]);
    let cases = r["cases"].as_array().expect("cases");
    let ids: Vec<&str> = cases.iter().filter_map(|c| c["id"].as_str()).collect();
    assert!(ids
        .iter()
        .all(|id| id.starts_with("reduce/torus/") || id.ends_with("/run0")));
    assert_eq!(
        ids.iter()
            .filter(|id| id.starts_with("reduce/torus/"))
            .count(),
        63
    );
    assert_eq!(total(&r, "skipped"), 21);
    // --skip-must-fail skips every invalid case.
    let w = wrong();
    let (code, r, _) = harness(&["--impl", &w, "--class", "invalid", "--skip-must-fail"]);
    assert_eq!(code, Some(0));
    assert_eq!(
        total(&r, "skipped"),
        case_lines("invalid.jsonl").len() as u64
    );
}

#[test]
fn a_slow_or_missing_implementation_is_reported_not_waited_for() {
    let (code, r, _) = harness(&[
        "--impl",
        "sleep 5",
        "--timeout",
        "0.2",
        "--run",
        "reduce/projective-plane/*/rs",
    ]);
    assert_eq!(code, Some(1));
    assert_eq!(total(&r, "timed_out"), 2);
    assert!(
        r["seconds"].as_f64().unwrap_or(9.0) < 4.0,
        "{}",
        r["seconds"]
    );
    let (code, r, _) = harness(&[
        "--impl",
        "/nonexistent/implementation",
        "--run",
        "reduce/projective-plane/*/rs",
    ]);
    assert_eq!(code, Some(1));
    assert!(r["cases"][0]["reasons"][0]
        .as_str()
        .unwrap_or("")
        .contains("cannot start"));
    // An implementation that prints nothing useful: no answer.
    let (code, r, _) = harness(&["--impl", "true", "--run", "quad/quad-generated/*/lrs-s0"]);
    assert_eq!(code, Some(1));
    assert!(r["cases"][0]["reasons"][0]
        .as_str()
        .unwrap_or("")
        .contains("no answer"));
}

#[test]
fn usage_errors_exit_2() {
    let o = ours();
    for args in [
        vec!["--impl", "'unbalanced"],
        vec!["--impl", ""],
        vec!["--impl", o.as_str(), "--timeout", "0"],
        vec!["--impl", o.as_str(), "--run", "[unclosed"],
    ] {
        let (code, _, err) = harness(&args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
    }
    let d = Scratch::new("conformance-empty");
    let out = run(&[
        "conformance",
        "--suite",
        d.path("").to_str().unwrap(),
        "--impl",
        "true",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("no suite here"), "{}", stderr(&out));
}

#[test]
fn the_checker_must_reject_every_wrong_answer_before_a_run() {
    // A "wrong answer" that is right: the harness refuses to judge anything.
    let d = Scratch::new("conformance-selftest");
    let dir = d.path("suite");
    std::fs::create_dir_all(&dir).expect("mkdir");
    let mut line = case_lines("wrong-answers.jsonl")
        .into_iter()
        .find(|c| c["id"] == "wrong/quad/not-two-triangles")
        .expect("the case");
    // Our own answer to the same input.
    let case = serde_json::json!({
        "protocol": 1, "id": "x", "task": "quad", "options": line["options"],
        "vertex_count": line["vertex_count"], "faces": line["faces"], "positions": line["positions"],
    });
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_contractible"))
        .arg("answer")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("runs");
    {
        use std::io::Write;
        let mut stdin = child.stdin.take().expect("stdin");
        stdin
            .write_all(case.to_string().as_bytes())
            .expect("writes");
    }
    let out = child.wait_with_output().expect("answers");
    assert!(out.status.success());
    let answer: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    line["answer"] = answer;
    std::fs::write(dir.join("wrong.jsonl"), format!("{line}\n")).expect("writes");
    let out = run(&[
        "conformance",
        "--suite",
        d.path("").to_str().unwrap(),
        "--impl",
        &ours(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("does not reject the wrong answer wrong/quad/not-two-triangles"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn answer_refuses_what_is_no_case_with_an_error_object() {
    for (input, kind) in [
        ("not json", "protocol"),
        (
            r#"{"protocol": 2, "id": "x", "task": "reduce", "options": {}, "vertex_count": 3, "faces": [[0,1,2]], "positions": null}"#,
            "protocol",
        ),
        (
            r#"{"protocol": 1, "id": "x", "task": "reduce", "options": {}, "vertex_count": 4000000000, "faces": [[0,1,2]], "positions": null}"#,
            "protocol",
        ),
        (
            r#"{"protocol": 1, "id": "x", "task": "dilate", "options": {}, "vertex_count": 3, "faces": [[0,1,2]], "positions": null}"#,
            "unsupported",
        ),
        (
            r#"{"protocol": 1, "id": "x", "task": "reduce", "options": {"colour": 1}, "vertex_count": 3, "faces": [[0,1,2]], "positions": null}"#,
            "bad_option",
        ),
        (
            r#"{"protocol": 1, "id": "x", "task": "quad", "options": {"algorithm": "best"}, "vertex_count": 3, "faces": [[0,1,2]], "positions": null}"#,
            "unknown_name",
        ),
    ] {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_contractible"))
            .arg("answer")
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("runs");
        {
            use std::io::Write;
            let mut stdin = child.stdin.take().expect("stdin");
            stdin.write_all(input.as_bytes()).expect("writes");
        }
        let out = child.wait_with_output().expect("answers");
        assert_eq!(out.status.code(), Some(2), "{input}");
        let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
        assert_eq!(v["error"]["kind"], kind, "{input}: {v}");
        assert!(v["error"]["message"]
            .as_str()
            .is_some_and(|m| !m.is_empty()));
    }
}
