//! `contractible check TASK INPUT OUTPUT`: the verdict of [`contractible::check`] on an
//! output of any implementation.

use std::collections::BTreeMap;

use contractible::check::{self, Verdict};
use serde::Serialize;

use super::args::{CheckArgs, CheckTask};
use super::{meshio, print_json, CliError, Ui};

/// One reason in the JSON report.
#[derive(Serialize, Debug)]
pub struct FailureReport {
    pub kind: &'static str,
    pub message: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub face: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub edge: Option<[u32; 2]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vertex: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub component: Option<usize>,
}

/// The JSON report of `check`.
#[derive(Serialize, Debug)]
pub struct CheckReport {
    pub task: &'static str,
    pub input: String,
    pub output: String,
    pub passed: bool,
    /// Per kind: how many reasons there were (listed or not).
    pub counts: BTreeMap<&'static str, usize>,
    /// The reasons, at most 20 of a kind, in the order found.
    pub failures: Vec<FailureReport>,
}

fn report(args: &CheckArgs, v: &Verdict) -> CheckReport {
    CheckReport {
        task: v.task,
        input: meshio::shown(&args.input),
        output: meshio::shown(&args.output),
        passed: v.passed(),
        counts: v.counts.iter().map(|&(k, n)| (k.name(), n)).collect(),
        failures: v
            .failures
            .iter()
            .map(|f| FailureReport {
                kind: f.kind.name(),
                message: f.message.clone(),
                face: f.face,
                edge: f.edge,
                vertex: f.vertex,
                component: f.component,
            })
            .collect(),
    }
}

pub fn run(args: &CheckArgs, ui: Ui) -> Result<(), CliError> {
    let (input, _, _, names) = meshio::read_input(&args.input, &args.input_opts, ui)?;
    let (output, _, _, _) = meshio::read_input(&args.output, &args.input_opts, ui)?;
    let verdict = match args.task {
        CheckTask::Reduce => check::reduce(&input, &output),
    }
    .map_err(|e| meshio::task_error(&input, &names, "check reduce", e))?;
    let r = report(args, &verdict);
    if ui.json {
        print_json(&r)?;
    } else if !ui.quiet {
        if r.passed {
            outln!(
                "{}: a correct {} output for {} ({} faces)",
                r.output,
                r.task,
                r.input,
                output.faces.len()
            );
        } else {
            outln!(
                "{}: not a correct {} output for {}",
                r.output,
                r.task,
                r.input
            );
            for f in &r.failures {
                outln!("  {}: {}", f.kind, f.message);
            }
            for &(kind, n) in &verdict.counts {
                let listed = verdict.failures.iter().filter(|f| f.kind == kind).count();
                if n > listed {
                    outln!("  ... and {} more {}", n - listed, kind.name());
                }
            }
        }
    }
    if r.passed {
        Ok(())
    } else {
        let total: usize = verdict.counts.iter().map(|&(_, n)| n).sum();
        Err(CliError::Failure(format!(
            "{} fails the {} check: {total} reason{}",
            r.output,
            r.task,
            if total == 1 { "" } else { "s" }
        )))
    }
}
