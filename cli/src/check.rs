//! `contractible check TASK INPUT OUTPUT [options]`: the verdict of [`contractible::check`] on an
//! output of any implementation.

use std::collections::BTreeMap;

use std::path::{Path, PathBuf};

use contractible::check::{self, DecimateCheck, QuadCheck, SimplifyCheck, Verdict};
use contractible::{Eps, MaxError, QuadMesh};
use serde::Serialize;

use super::args::{CheckArgs, CheckTask, InputOpts};
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

/// The task's options, checked against the task.
enum Judged {
    Reduce {
        history: Option<PathBuf>,
    },
    Quad {
        triangles: Option<PathBuf>,
        pairs: Option<PathBuf>,
    },
    Simplify(SimplifyCheck),
    Decimate,
}

/// The options `args` gives, refused where they belong to another task.
fn judged(args: &CheckArgs) -> Result<Judged, CliError> {
    let simplify_flags = [
        ("--eps", args.eps.is_some()),
        ("--eps-rel", args.eps_rel.is_some()),
        ("--position", args.position.is_some()),
        ("--allow-foldover", args.allow_foldover),
    ];
    let quad_flags = [
        ("--triangles", args.triangles.is_some()),
        ("--pairs", args.pairs.is_some()),
    ];
    let decimate_flags = [
        ("--faces", args.faces.is_some()),
        ("--keep", args.keep.is_some()),
        ("--max-error", args.max_error.is_some()),
        ("--max-error-rel", args.max_error_rel.is_some()),
        ("--placement", args.placement.is_some()),
        ("--lock-boundary", args.lock_boundary),
        ("--lock", !args.lock.is_empty()),
        ("--maps", args.maps.is_some()),
    ];
    let foreign = |flags: &[(&'static str, bool)], owner: &str| -> Result<(), CliError> {
        match flags.iter().find(|&&(_, on)| on) {
            Some((flag, _)) => Err(CliError::Input(format!(
                "{flag} is an option of `check {owner}`, not of `check {}`",
                task_name(args.task)
            ))),
            None => Ok(()),
        }
    };
    if args.task != CheckTask::Simplify {
        // --allow-foldover is also decimate's.
        let flags = if args.task == CheckTask::Decimate {
            &simplify_flags[..3]
        } else {
            &simplify_flags[..]
        };
        foreign(flags, "simplify")?;
    }
    if args.task != CheckTask::Decimate {
        foreign(&decimate_flags, "decimate")?;
    }
    if args.task != CheckTask::Quad {
        foreign(&quad_flags, "quad")?;
    }
    if args.task != CheckTask::Reduce {
        foreign(&[("--history", args.history.is_some())], "reduce")?;
    }
    match args.task {
        CheckTask::Reduce => Ok(Judged::Reduce {
            history: args.history.clone(),
        }),
        CheckTask::Decimate => Ok(Judged::Decimate),
        CheckTask::Quad => Ok(Judged::Quad {
            triangles: args.triangles.clone(),
            pairs: args.pairs.clone(),
        }),
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
            Ok(Judged::Simplify(SimplifyCheck {
                eps,
                position: args.position.unwrap_or_default(),
                allow_foldover: args.allow_foldover,
            }))
        }
    }
}

fn task_name(t: CheckTask) -> &'static str {
    match t {
        CheckTask::Reduce => "reduce",
        CheckTask::Quad => "quad",
        CheckTask::Simplify => "simplify",
        CheckTask::Decimate => "decimate",
    }
}

/// The three maps of a `decimate --maps` document (a `null` collapse_map entry, a
/// vertex no face uses, read as `NO_VERTEX`).
struct Maps {
    vertex_map: Vec<u32>,
    collapse_map: Vec<u32>,
    face_origin: Vec<u32>,
}

fn read_maps(path: &Path) -> Result<Maps, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    let doc: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| CliError::Input(format!("{}: not JSON: {e}", path.display())))?;
    let list = |key: &str, nulls: bool| -> Result<Vec<u32>, CliError> {
        let bad = |what: String| CliError::Input(format!("{}: {key}: {what}", path.display()));
        let items = doc[key]
            .as_array()
            .ok_or_else(|| bad("missing, or not an array".into()))?;
        items
            .iter()
            .enumerate()
            .map(|(i, x)| match x {
                serde_json::Value::Null if nulls => Ok(contractible::decimate::NO_VERTEX),
                _ => x
                    .as_u64()
                    .and_then(|v| u32::try_from(v).ok())
                    .filter(|&v| v != contractible::decimate::NO_VERTEX)
                    .ok_or_else(|| bad(format!("entry {i} is {x}, not an id"))),
            })
            .collect()
    };
    Ok(Maps {
        vertex_map: list("vertex_map", false)?,
        collapse_map: list("collapse_map", true)?,
        face_origin: list("face_origin", false)?,
    })
}

/// The output of `check quad`: its faces must all be quads.
fn read_quads(path: &Path, opts: &InputOpts, ui: Ui) -> Result<QuadMesh, CliError> {
    let loaded = meshio::load(path, opts, ui)?;
    let poly = &loaded.poly;
    let mut faces = Vec::with_capacity(poly.face_count());
    for i in 0..poly.face_count() {
        match <[u32; 4]>::try_from(poly.face(i)) {
            Ok(q) => faces.push(q),
            Err(_) => {
                return Err(CliError::Input(format!(
                    "{}: {} has {} corners: a quad output has quads only",
                    loaded.names.shown,
                    loaded.names.face(i),
                    poly.face(i).len()
                )))
            }
        }
    }
    Ok(QuadMesh {
        vertex_count: poly.vertex_count,
        positions: poly.positions.clone(),
        faces,
    })
}

/// A file of index pairs (`quad --pairs`: per quad, two 0-based face indices; `reduce
/// --history`: per contraction, two 0-based vertex ids), one pair per line, blank lines
/// skipped. `what` names the indices in errors.
fn read_pairs(path: &Path, what: &str) -> Result<Vec<[u32; 2]>, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    let mut pairs = Vec::new();
    for (n, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let mut words = line.split_whitespace().map(str::parse::<u32>);
        match (words.next(), words.next(), words.next()) {
            (Some(Ok(f)), Some(Ok(g)), None) => pairs.push([f, g]),
            _ => {
                return Err(CliError::Input(format!(
                    "{}:{}: expected two {what} (0-based integers), found {:?}",
                    path.display(),
                    n + 1,
                    line.trim()
                )))
            }
        }
    }
    Ok(pairs)
}

pub fn run(args: &CheckArgs, ui: Ui) -> Result<(), CliError> {
    let judged = judged(args)?;
    let (input, _, _, names) = meshio::read_input(&args.input, &args.input_opts, ui)?;
    let (verdict, faces) = match &judged {
        Judged::Reduce { history } => {
            let (output, _, _, _) = meshio::read_input(&args.output, &args.input_opts, ui)?;
            let v = match history {
                Some(path) => {
                    let steps = read_pairs(path, "vertex ids")?;
                    check::reduce_history(&input, &output, &steps)
                }
                None => check::reduce(&input, &output),
            }
            .map_err(|e| meshio::task_error(&input, &names, "check reduce", e))?;
            (v, output.faces.len())
        }
        Judged::Simplify(o) => {
            let (output, _, _, _) = meshio::read_input(&args.output, &args.input_opts, ui)?;
            let v = check::simplify(&input, &output, o)
                .map_err(|e| meshio::task_error(&input, &names, "check simplify", e))?;
            (v, output.faces.len())
        }
        Judged::Decimate => {
            let (output, _, _, _) = meshio::read_input(&args.output, &args.input_opts, ui)?;
            let maps = match &args.maps {
                Some(p) => Some(read_maps(p)?),
                None => None,
            };
            let options = DecimateCheck {
                faces: args.faces,
                keep: args.keep,
                max_error: match (args.max_error, args.max_error_rel) {
                    (Some(e), _) => Some(MaxError::Absolute(e)),
                    (None, Some(r)) => Some(MaxError::Relative(r)),
                    (None, None) => None,
                },
                placement: args.placement.unwrap_or_default(),
                allow_foldover: args.allow_foldover,
                lock_boundary: args.lock_boundary,
                locked: &args.lock,
                vertex_map: maps.as_ref().map(|m| m.vertex_map.as_slice()),
                collapse_map: maps.as_ref().map(|m| m.collapse_map.as_slice()),
                face_origin: maps.as_ref().map(|m| m.face_origin.as_slice()),
            };
            let v = check::decimate(&input, &output, &options)
                .map_err(|e| meshio::task_error(&input, &names, "check decimate", e))?;
            (v, output.faces.len())
        }
        Judged::Quad { triangles, pairs } => {
            let output = read_quads(&args.output, &args.input_opts, ui)?;
            let k = match triangles {
                Some(path) => Some(meshio::read_input(path, &args.input_opts, ui)?.0.faces),
                None => None,
            };
            let pairs = match pairs {
                Some(path) => Some(read_pairs(path, "face indices")?),
                None => None,
            };
            let stated = QuadCheck {
                triangles: k.as_deref(),
                pairs: pairs.as_deref(),
            };
            let v = check::quad(&input, &output, &stated)
                .map_err(|e| meshio::task_error(&input, &names, "check quad", e))?;
            (v, output.faces.len())
        }
    };
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
                faces
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
