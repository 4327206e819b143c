//! `contractible conformance --impl 'CMD ARGS'`: runs an implementation of the protocol
//! (`spec/conformance.md`) over the suite as a black box, one process per case, and
//! judges each answer with [`contractible::check`] (and, with `--exact`, against the
//! stored output).

pub mod protocol;
pub mod suite;

use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use contractible::check::{self, DecimateCheck, QuadCheck, SimplifyCheck, Verdict};
use contractible::{Eps, MaxError};
use serde::Serialize;
use wait_timeout::ChildExt;

use self::protocol::{differs, Answer};
use self::suite::{Case, Class, Suite};
use super::args::ConformanceArgs;
use super::{print_json, CliError, Ui};

/// What became of one case.
#[derive(Serialize, Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
#[serde(rename_all = "snake_case")]
pub enum CaseVerdict {
    Passed,
    Failed,
    TimedOut,
    Skipped,
}

/// The outcome of one case in the report.
#[derive(Serialize, Clone, Debug)]
pub struct Outcome {
    pub id: String,
    pub task: String,
    pub class: &'static str,
    pub verdict: CaseVerdict,
    /// Whether the implementation refused the input (exit code not 0).
    pub refused: bool,
    /// Why it failed (or, for a refusal, what the implementation said).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub reasons: Vec<String>,
    pub seconds: f64,
}

/// Counts per task and class.
#[derive(Serialize, Clone, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    pub task: String,
    pub class: &'static str,
    pub passed: usize,
    pub failed: usize,
    /// Cases the implementation refused (passed for invalid cases, failed for valid ones).
    pub refused: usize,
    pub timed_out: usize,
    pub skipped: usize,
}

/// The JSON report.
#[derive(Serialize, Debug)]
pub struct Report {
    pub protocol: u32,
    pub suite_version: u32,
    pub suite: String,
    #[serde(rename = "impl")]
    pub implementation: String,
    pub exact: bool,
    /// Wrong answers the checker rejected with the reason each must give, before the run.
    pub checker_self_test: usize,
    pub passed: bool,
    pub totals: Vec<Tally>,
    pub cases: Vec<Outcome>,
    pub seconds: f64,
}

/// The verdict of the checker on `answer` to the valid `case` (`Err`: the answer is
/// no mesh of the task, or the checker refuses the case's input).
pub fn verdict(case: &Case, answer: &Answer) -> Result<Verdict, String> {
    let input = case.message.mesh()?;
    let n = input.vertex_count;
    let o = &case.message.options;
    match case.task() {
        "reduce" => match &answer.history {
            Some(steps) => check::reduce_history(&input, &answer.mesh::<3>(n)?, steps),
            None => check::reduce(&input, &answer.mesh::<3>(n)?),
        },
        "quad" => check::quad(
            &input,
            &answer.mesh::<4>(n)?,
            &QuadCheck {
                triangles: answer.triangles.as_deref(),
                pairs: answer.pairs.as_deref(),
            },
        ),
        "simplify" => {
            let eps = match (
                o.get("eps").and_then(|v| v.as_f64()),
                o.get("eps_rel").and_then(|v| v.as_f64()),
            ) {
                (Some(e), _) => Eps::Absolute(e),
                (None, Some(r)) => Eps::Relative(r),
                (None, None) => return Err("the case has no eps".into()),
            };
            let position = o
                .get("position")
                .and_then(|v| v.as_str())
                .unwrap_or("midpoint")
                .parse()
                .map_err(|e: contractible::UnknownName| e.to_string())?;
            let guard = o
                .get("guard")
                .and_then(serde_json::Value::as_bool)
                .unwrap_or(true);
            let options = SimplifyCheck {
                eps,
                position,
                allow_foldover: !guard,
            };
            check::simplify(&input, &answer.mesh::<3>(n)?, &options)
        }
        "decimate" => {
            let num = |k: &str| o.get(k).and_then(serde_json::Value::as_f64);
            let max_error = match (num("max_error"), num("max_error_rel")) {
                (Some(e), _) => Some(MaxError::Absolute(e)),
                (None, Some(r)) => Some(MaxError::Relative(r)),
                (None, None) => None,
            };
            let locked: Vec<u32> = o
                .get("locked")
                .and_then(|v| v.as_array())
                .map(|a| {
                    a.iter()
                        .filter_map(|x| x.as_u64().map(|x| x as u32))
                        .collect()
                })
                .unwrap_or_default();
            let placement = o
                .get("placement")
                .and_then(|v| v.as_str())
                .unwrap_or("optimal")
                .parse()
                .map_err(|e: contractible::UnknownName| e.to_string())?;
            let none = contractible::decimate::NO_VERTEX;
            let collapse_map: Option<Vec<u32>> = answer
                .collapse_map
                .as_ref()
                .map(|m| m.iter().map(|x| x.unwrap_or(none)).collect());
            let options = DecimateCheck {
                faces: o
                    .get("faces")
                    .and_then(serde_json::Value::as_u64)
                    .map(|f| f as usize),
                keep: num("keep"),
                max_error,
                placement,
                allow_foldover: !o
                    .get("guard")
                    .and_then(serde_json::Value::as_bool)
                    .unwrap_or(true),
                lock_boundary: o
                    .get("lock_boundary")
                    .and_then(serde_json::Value::as_bool)
                    .unwrap_or(false),
                locked: &locked,
                vertex_map: answer.vertex_map.as_deref(),
                collapse_map: collapse_map.as_deref(),
                face_origin: answer.face_origin.as_deref(),
            };
            check::decimate(&input, &answer.mesh::<3>(n)?, &options)
        }
        other => return Err(format!("no checker for task {other:?}")),
    }
    .map_err(|e| format!("the checker refuses the case's input: {e}"))
}

/// The verdict of the checker on `answer` to the valid `case`, as failure lines: the
/// first three reasons and the count of all (empty: a correct output).
pub fn judge(case: &Case, answer: &Answer) -> Result<Vec<String>, String> {
    let verdict = verdict(case, answer)?;
    let mut lines: Vec<String> = verdict
        .failures
        .iter()
        .take(3)
        .map(|f| format!("{}: {}", f.kind.name(), f.message))
        .collect();
    let total: usize = verdict.counts.iter().map(|&(_, n)| n).sum();
    if total > lines.len() {
        lines.push(format!("... {} reasons in all", total));
    }
    Ok(lines)
}

/// Runs the checker on every wrong answer of the suite: each must fail, naming its
/// kind. Returns how many did, or the first that did not.
pub fn self_test(suite: &Suite) -> Result<usize, String> {
    for w in &suite.wrong {
        let v = verdict(&w.case, &w.answer).map_err(|e| format!("{}: {e}", w.case.id()))?;
        if !v.counts.iter().any(|&(k, _)| k.name() == w.kind) {
            return Err(format!(
                "the checker does not reject the wrong answer {} with {} (it found {:?})",
                w.case.id(),
                w.kind,
                v.counts.iter().map(|&(k, _)| k.name()).collect::<Vec<_>>()
            ));
        }
    }
    Ok(suite.wrong.len())
}

/// Runs `argv` on `case` and judges what it does.
fn run_case(argv: &[String], case: &Case, timeout: Duration, exact: bool) -> Outcome {
    let start = Instant::now();
    let mut outcome = Outcome {
        id: case.id().to_string(),
        task: case.task().to_string(),
        class: case.class.name(),
        verdict: CaseVerdict::Failed,
        refused: false,
        reasons: Vec::new(),
        seconds: 0.0,
    };
    let finish = |mut o: Outcome, verdict: CaseVerdict, reasons: Vec<String>| {
        o.verdict = verdict;
        o.reasons = reasons;
        o.seconds = start.elapsed().as_secs_f64();
        o
    };
    let input = match serde_json::to_vec(&case.message) {
        Ok(b) => b,
        Err(e) => {
            return finish(
                outcome,
                CaseVerdict::Failed,
                vec![format!("cannot encode the case: {e}")],
            )
        }
    };
    let child = Command::new(&argv[0])
        .args(&argv[1..])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let mut child = match child {
        Ok(c) => c,
        Err(e) => {
            return finish(
                outcome,
                CaseVerdict::Failed,
                vec![format!("cannot start {}: {e}", argv[0])],
            )
        }
    };
    // Written and read on threads: a large case or answer must not fill a pipe while
    // the other side waits.
    let stdin = child.stdin.take();
    let writer = std::thread::spawn(move || {
        if let Some(mut s) = stdin {
            // An implementation that exits without reading is judged by its answer.
            let _ = s.write_all(&input);
        }
    });
    let reader = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            if let Some(mut p) = pipe {
                let _ = p.read_to_end(&mut buf);
            }
            buf
        })
    };
    let out = reader(
        child
            .stdout
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let err = reader(
        child
            .stderr
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let status = match child.wait_timeout(timeout) {
        Ok(Some(s)) => Some(s),
        Ok(None) => {
            let _ = child.kill();
            let _ = child.wait();
            None
        }
        Err(e) => {
            let _ = child.kill();
            let _ = child.wait();
            let _ = writer.join();
            return finish(
                outcome,
                CaseVerdict::Failed,
                vec![format!("cannot wait for it: {e}")],
            );
        }
    };
    let _ = writer.join();
    let stdout = out.join().unwrap_or_default();
    let stderr = err.join().unwrap_or_default();
    let Some(status) = status else {
        return finish(
            outcome,
            CaseVerdict::TimedOut,
            vec![format!("no answer within {} s", timeout.as_secs_f64())],
        );
    };
    let said = || {
        let text = String::from_utf8_lossy(&stderr);
        text.lines().last().unwrap_or("").trim().to_string()
    };
    let parsed: Result<Answer, String> = serde_json::from_slice(&stdout)
        .map_err(|e| format!("its standard output is no answer: {e}"));
    match (status.code(), case.class) {
        (None, _) => finish(
            outcome,
            CaseVerdict::Failed,
            vec![format!(
                "it was killed by a signal ({status}); stderr: {}",
                said()
            )],
        ),
        (Some(0), Class::Invalid) => finish(
            outcome,
            CaseVerdict::Failed,
            vec![format!(
                "it answered an input it must refuse: {}",
                case.why.as_deref().unwrap_or("")
            )],
        ),
        (Some(_), Class::Invalid) => {
            outcome.refused = true;
            let note = match parsed.ok().and_then(|a| a.error) {
                Some(r) => format!("{}: {}", r.kind, r.message),
                None => format!("no error object; stderr: {}", said()),
            };
            finish(outcome, CaseVerdict::Passed, vec![note])
        }
        (Some(code), Class::Valid) if code != 0 => {
            outcome.refused = true;
            let note = match parsed.ok().and_then(|a| a.error) {
                Some(r) => format!("refused a valid input ({}): {}", r.kind, r.message),
                None => format!("exit code {code}; stderr: {}", said()),
            };
            finish(outcome, CaseVerdict::Failed, vec![note])
        }
        (Some(_), Class::Valid) => {
            let answer = match parsed {
                Ok(a) if a.error.is_none() => a,
                Ok(_) => {
                    return finish(
                        outcome,
                        CaseVerdict::Failed,
                        vec!["exit code 0 with an error object".into()],
                    )
                }
                Err(e) => return finish(outcome, CaseVerdict::Failed, vec![e]),
            };
            let mut reasons = match judge(case, &answer) {
                Ok(r) => r,
                Err(e) => vec![e],
            };
            if exact {
                if let Some(d) = case.expected.as_ref().and_then(|x| differs(&answer, x)) {
                    reasons.push(format!("--exact: {d}"));
                }
            }
            let v = if reasons.is_empty() {
                CaseVerdict::Passed
            } else {
                CaseVerdict::Failed
            };
            finish(outcome, v, reasons)
        }
    }
}

/// Whether `id` matches any of `patterns` (glob syntax: `*` any run of characters,
/// `?` one, `[...]` a class).
fn matches_any(id: &str, patterns: &[glob::Pattern]) -> bool {
    patterns.iter().any(|p| p.matches(id))
}

fn patterns(list: &[String], flag: &str) -> Result<Vec<glob::Pattern>, CliError> {
    list.iter()
        .map(|s| {
            glob::Pattern::new(s)
                .map_err(|e| CliError::Input(format!("{flag} {s:?}: not a pattern: {e}")))
        })
        .collect()
}

/// Quotes `s` for a POSIX shell when it needs it.
fn shell_quoted(s: &str) -> String {
    shlex::try_quote(s).map_or_else(|_| s.to_string(), |q| q.into_owned())
}

pub fn run(args: &ConformanceArgs, ui: Ui) -> Result<(), CliError> {
    let start = Instant::now();
    let argv = shlex::split(&args.implementation)
        .filter(|v| !v.is_empty())
        .ok_or_else(|| {
            CliError::Input(format!(
                "--impl {:?}: not a command (a program and its arguments, quoted as a shell would)",
                args.implementation
            ))
        })?;
    if !(args.timeout.is_finite() && args.timeout > 0.0) {
        return Err(CliError::Input(format!(
            "--timeout {}: expected a number of seconds > 0",
            args.timeout
        )));
    }
    let run_patterns = patterns(&args.run, "--run")?;
    let skip_patterns = patterns(&args.skip, "--skip")?;
    let suite = suite::load(&args.suite).map_err(CliError::Input)?;
    let checked = self_test(&suite).map_err(CliError::Failure)?;
    let selected: Vec<(&Case, bool)> = suite
        .cases
        .iter()
        .filter(|c| args.task.is_empty() || args.task.iter().any(|t| t.name() == c.task()))
        .filter(|c| args.class.is_none_or(|k| k.class() == c.class))
        .filter(|c| run_patterns.is_empty() || matches_any(c.id(), &run_patterns))
        .map(|c| {
            let skip = matches_any(c.id(), &skip_patterns)
                || (args.skip_must_fail && c.class == Class::Invalid);
            (c, skip)
        })
        .collect();
    let jobs = args
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    let timeout = Duration::from_secs_f64(args.timeout);
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Outcome>>> = Mutex::new(vec![None; selected.len()]);
    let bar = super::progress::bar(ui, selected.len() as u64, "cases");
    std::thread::scope(|s| {
        for _ in 0..jobs.min(selected.len().max(1)) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(&(case, skip)) = selected.get(i) else {
                    break;
                };
                let o = if skip {
                    Outcome {
                        id: case.id().to_string(),
                        task: case.task().to_string(),
                        class: case.class.name(),
                        verdict: CaseVerdict::Skipped,
                        refused: false,
                        reasons: Vec::new(),
                        seconds: 0.0,
                    }
                } else {
                    run_case(&argv, case, timeout, args.exact)
                };
                if let Ok(mut r) = results.lock() {
                    r[i] = Some(o);
                }
                bar.inc(1);
            });
        }
    });
    bar.finish_and_clear();
    let cases: Vec<Outcome> = results
        .into_inner()
        .map_err(|_| CliError::Failure("a case's thread failed".into()))?
        .into_iter()
        .flatten()
        .collect();
    let mut tallies: BTreeMap<(String, &'static str), Tally> = BTreeMap::new();
    for o in &cases {
        let t = tallies
            .entry((o.task.clone(), o.class))
            .or_insert_with(|| Tally {
                task: o.task.clone(),
                class: o.class,
                ..Tally::default()
            });
        match o.verdict {
            CaseVerdict::Passed => t.passed += 1,
            CaseVerdict::Failed => t.failed += 1,
            CaseVerdict::TimedOut => t.timed_out += 1,
            CaseVerdict::Skipped => t.skipped += 1,
        }
        t.refused += usize::from(o.refused);
    }
    let failures: Vec<&Outcome> = cases
        .iter()
        .filter(|o| matches!(o.verdict, CaseVerdict::Failed | CaseVerdict::TimedOut))
        .collect();
    let report = Report {
        protocol: protocol::PROTOCOL,
        suite_version: suite::SUITE,
        suite: args.suite.display().to_string(),
        implementation: args.implementation.clone(),
        exact: args.exact,
        checker_self_test: checked,
        passed: failures.is_empty(),
        totals: tallies.into_values().collect(),
        cases: cases.clone(),
        seconds: start.elapsed().as_secs_f64(),
    };
    if args.script {
        for o in &failures {
            outln!("--skip {}", shell_quoted(&o.id));
        }
    } else if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        print_human(&report, &failures);
    }
    if failures.is_empty() {
        Ok(())
    } else {
        Err(CliError::Failure(format!(
            "{} of {} cases failed or timed out",
            failures.len(),
            cases
                .iter()
                .filter(|o| o.verdict != CaseVerdict::Skipped)
                .count()
        )))
    }
}

fn print_human(report: &Report, failures: &[&Outcome]) {
    for o in failures {
        let what = if o.verdict == CaseVerdict::TimedOut {
            "TIMEOUT"
        } else {
            "FAIL"
        };
        outln!("{what} {}", o.id);
        for r in &o.reasons {
            outln!("    {r}");
        }
    }
    outln!(
        "{:<9} {:<8} {:>7} {:>7} {:>8} {:>10} {:>8}",
        "task",
        "class",
        "passed",
        "failed",
        "refused",
        "timed out",
        "skipped"
    );
    for t in &report.totals {
        outln!(
            "{:<9} {:<8} {:>7} {:>7} {:>8} {:>10} {:>8}",
            t.task,
            t.class,
            t.passed,
            t.failed,
            t.refused,
            t.timed_out,
            t.skipped
        );
    }
    let run = report
        .cases
        .iter()
        .filter(|o| o.verdict != CaseVerdict::Skipped)
        .count();
    outln!(
        "{} of {run} cases passed{} ({} skipped) in {:.1} s; the checker rejected all {} wrong answers of its self-test",
        run - failures.len(),
        if report.exact { " with --exact" } else { "" },
        report.cases.len() - run,
        report.seconds,
        report.checker_self_test
    );
}
