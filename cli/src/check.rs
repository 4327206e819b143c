//! `contractible check TASK INPUT OUTPUT [--eps E | --eps-rel R]`: the verdict of [`contractible::check`] on an
//! output of any implementation.

use std::collections::BTreeMap;

use contractible::check::{self, SimplifyCheck, Verdict};
use contractible::Eps;
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

/// The options of `check simplify` (`None` for `check reduce`, which takes none).
fn simplify_options(args: &CheckArgs) -> Result<Option<SimplifyCheck>, CliError> {
    let given: Vec<&str> = [
        ("--eps", args.eps.is_some()),
        ("--eps-rel", args.eps_rel.is_some()),
        ("--position", args.position.is_some()),
        ("--allow-foldover", args.allow_foldover),
    ]
    .iter()
    .filter(|&&(_, on)| on)
    .map(|&(flag, _)| flag)
    .collect();
    match args.task {
        CheckTask::Reduce => match given.first() {
            Some(flag) => Err(CliError::Input(format!(
                "{flag} is an option of `check simplify`, not of `check reduce`"
            ))),
            None => Ok(None),
        },
        CheckTask::Simplify => {
            let eps = match (args.eps, args.eps_rel) {
                (Some(e), _) => Eps::Absolute(e),
                (None, Some(r)) => Eps::Relative(r),
                (None, None) => {
                    return Err(CliError::Input(
                        "`check simplify` needs the run's ε: --eps or --eps-rel".into(),
                    ))
                }
            };
            Ok(Some(SimplifyCheck {
                eps,
                position: args.position.unwrap_or_default(),
                allow_foldover: args.allow_foldover,
            }))
        }
    }
}

pub fn run(args: &CheckArgs, ui: Ui) -> Result<(), CliError> {
    let simplify = simplify_options(args)?;
    let (input, _, _, names) = meshio::read_input(&args.input, &args.input_opts, ui)?;
    let (output, _, _, _) = meshio::read_input(&args.output, &args.input_opts, ui)?;
    let verdict = match simplify {
        None => check::reduce(&input, &output)
            .map_err(|e| meshio::task_error(&input, &names, "check reduce", e)),
        Some(o) => check::simplify(&input, &output, &o)
            .map_err(|e| meshio::task_error(&input, &names, "check simplify", e)),
    }?;
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
