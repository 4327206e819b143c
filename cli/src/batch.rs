//! `contractible batch INPUT... --task TASK [-o OUTDIR] [--jobs N] [--jsonl FILE
//! [--resume]] [-- TASK OPTIONS]`: one task over many files, in parallel.
//!
//! Guarantees:
//! - Inputs are directories (every file below them with a mesh extension, recursively),
//!   glob patterns (quoted, expanded here) or files; the list is sorted and deduplicated,
//!   so the run is the same whatever the file system's order.
//! - Each file runs exactly as `contractible TASK FILE [-o OUTDIR/…] TASK OPTIONS` would
//!   (the task options are parsed by the task's own parser, once up front, so a bad option
//!   fails before any work), single-threaded and quiet, on a pool of `--jobs` threads.
//! - One JSON line per file, **in input order** whatever the completion order:
//!   `{"file", "task", "ok": true, "result": <the task's --json report>}` or
//!   `{"file", "task", "ok": false, "error": {"kind": "input" | "failure" | "panic",
//!   "exit_code", "message"}}` (the message is the command's own, with its location: file
//!   line, face, vertex). A failing file — even a panic — never stops the batch.
//! - `--jsonl FILE` writes the lines to FILE (replacing it) as they are ready, in order;
//!   with `--resume` it first reads FILE, skips every file that already has a complete
//!   line there and appends the others, so an interrupted batch continues where it
//!   stopped.
//! - Files start largest first (by size on disk), one per free thread, so that a long
//!   file does not end the run alone; the lines still come out in input order.
//! - An overall progress bar (files done / total) on stderr; a summary line at the end.
//!   Exit code 0 when every file succeeded, 1 when any failed (2 for bad arguments).

use std::collections::{BTreeMap, HashSet};
use std::io::{BufRead, Write};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::mpsc;

use clap::Parser;
use rayon::prelude::*;
use serde_json::{json, Value};

use super::args::{BatchArgs, BatchTask, Cli, Command};
use super::progress::bar;
use super::{decimate, info, quad, reduce, simplify, CliError, Ui};

/// Extensions of the files a directory contributes (after an optional `.gz`).
const MESH_EXTENSIONS: [&str; 4] = ["off", "obj", "ply", "stl"];

fn task_name(t: BatchTask) -> &'static str {
    match t {
        BatchTask::Info => "info",
        BatchTask::Reduce => "reduce",
        BatchTask::Quad => "quad",
        BatchTask::Simplify => "simplify",
        BatchTask::Decimate => "decimate",
    }
}

/// Whether `path` names a mesh file by its extension (`x.off`, `x.off.gz`...).
fn is_mesh_file(path: &Path) -> bool {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    let name = name.strip_suffix(".gz").unwrap_or(&name);
    MESH_EXTENSIONS
        .iter()
        .any(|e| name.len() > e.len() + 1 && name.ends_with(&format!(".{e}")))
}

/// Every mesh file below `dir`, recursively (links are not followed).
fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> Result<(), CliError> {
    let entries = std::fs::read_dir(dir).map_err(|e| {
        CliError::Input(format!("{}: cannot list the directory: {e}", dir.display()))
    })?;
    for entry in entries {
        let entry = entry.map_err(|e| {
            CliError::Input(format!("{}: cannot list the directory: {e}", dir.display()))
        })?;
        let kind = entry
            .file_type()
            .map_err(|e| CliError::Input(format!("{}: {e}", entry.path().display())))?;
        let path = entry.path();
        if kind.is_dir() {
            walk(&path, out)?;
        } else if kind.is_file() && is_mesh_file(&path) {
            out.push(path);
        }
    }
    Ok(())
}

/// The input files: directories walked, patterns expanded, files kept; sorted, unique.
fn input_files(inputs: &[String]) -> Result<Vec<PathBuf>, CliError> {
    let mut files = Vec::new();
    for input in inputs {
        let path = Path::new(input);
        if path.is_dir() {
            walk(path, &mut files)?;
        } else if path.exists() {
            files.push(path.to_path_buf());
        } else {
            let paths = glob::glob(input).map_err(|e| {
                CliError::Input(format!(
                    "{input}: neither a file, a directory nor a valid pattern: {e}"
                ))
            })?;
            let before = files.len();
            for p in paths {
                let p = p.map_err(|e| CliError::Input(format!("{input}: {e}")))?;
                if p.is_file() {
                    files.push(p);
                }
            }
            if files.len() == before {
                return Err(CliError::Input(format!(
                    "{input}: no such file, and no file matches it as a pattern"
                )));
            }
        }
    }
    files.sort();
    files.dedup();
    Ok(files)
}

/// The output path for `file` under `outdir`: the same file name with the task before the
/// extension (`x.off.gz` → `OUTDIR/x.reduce.off.gz`; quads of an STL file go to `.off`,
/// since STL holds triangles only). Files of the same name in different directories
/// would collide, so the path relative to the common input root is kept.
fn output_path(outdir: &Path, root: &Path, file: &Path, task: BatchTask) -> PathBuf {
    let rel = file.strip_prefix(root).unwrap_or(file);
    let name = rel
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let (stem, gz) = match name.strip_suffix(".gz") {
        Some(s) => (s.to_string(), ".gz"),
        None => (name.clone(), ""),
    };
    let (base, ext) = match stem.rsplit_once('.') {
        Some((b, e)) => (b.to_string(), e.to_ascii_lowercase()),
        None => (stem.clone(), "off".to_string()),
    };
    let ext = if task == BatchTask::Quad && ext == "stl" {
        "off".to_string()
    } else {
        ext
    };
    let dir = rel
        .parent()
        .map(|p| outdir.join(p))
        .unwrap_or_else(|| outdir.to_path_buf());
    dir.join(format!("{base}.{}.{ext}{gz}", task_name(task)))
}

/// The deepest directory containing every file (for output paths).
fn common_root(files: &[PathBuf]) -> PathBuf {
    let mut root: Option<PathBuf> = None;
    for f in files {
        let parent = f.parent().unwrap_or(Path::new("")).to_path_buf();
        root = Some(match root {
            None => parent,
            Some(r) => {
                let mut common = PathBuf::new();
                for (a, b) in r.components().zip(parent.components()) {
                    if a != b {
                        break;
                    }
                    common.push(a);
                }
                common
            }
        });
    }
    root.unwrap_or_default()
}

/// Parses `contractible TASK FILE [-o OUT] OPTIONS` with the task's own parser.
fn task_command(
    task: BatchTask,
    file: &Path,
    out: Option<&Path>,
    options: &[String],
) -> Result<Command, CliError> {
    let mut argv: Vec<std::ffi::OsString> =
        vec!["contractible".into(), task_name(task).into(), file.into()];
    if let Some(o) = out {
        argv.push("-o".into());
        argv.push(o.into());
    }
    argv.extend(options.iter().map(Into::into));
    Cli::try_parse_from(argv)
        .map(|c| c.command)
        .map_err(|e| CliError::Input(format!("task options: {}", e.render().to_string().trim())))
}

/// One file's report as JSON (when the task got that far) and its error (when it
/// failed). Runs quietly (no bars, no text).
fn run_task(cmd: &Command) -> (Option<Value>, Option<CliError>) {
    let ui = Ui {
        json: false,
        quiet: true,
    };
    fn value<T: serde::Serialize>(r: &T) -> Result<Value, CliError> {
        serde_json::to_value(r).map_err(|e| CliError::Failure(format!("cannot encode JSON: {e}")))
    }
    let r = match cmd {
        Command::Info(a) => info::compute(a, ui).and_then(|o| match o {
            info::Outcome::Surface(report) => Ok((value(&report)?, None)),
            info::Outcome::Diagnosis { report, error, .. } => Ok((value(&report)?, error)),
        }),
        Command::Reduce(a) => reduce::compute(a, ui).and_then(|report| Ok((value(&report)?, None))),
        Command::Quad(a) => quad::compute(a, ui).and_then(|report| Ok((value(&report)?, None))),
        Command::Simplify(a) => {
            simplify::compute(a, ui).and_then(|report| Ok((value(&report)?, None)))
        }
        Command::Decimate(a) => {
            decimate::compute(a, ui).and_then(|report| Ok((value(&report)?, None)))
        }
        _ => Err(CliError::Failure("not a batch task".into())),
    };
    match r {
        Ok((v, e)) => (Some(v), e),
        Err(e) => (None, Some(e)),
    }
}

/// The JSON line of one file: `ok`, the task's report as `result` (when there is one:
/// `info` on a broken mesh gives both the problems and an error) and the `error`.
fn line_of(file: &Path, task: BatchTask, cmd: Result<Command, CliError>) -> Value {
    let (result, error) = match cmd {
        Err(e) => (None, Some(e)),
        Ok(cmd) => catch_unwind(AssertUnwindSafe(|| run_task(&cmd))).unwrap_or_else(|p| {
            let what = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            (
                None,
                Some(CliError::Failure(format!(
                    "panic (a bug; please report it): {what}"
                ))),
            )
        }),
    };
    let mut line =
        json!({"file": file.display().to_string(), "task": task_name(task), "ok": error.is_none()});
    if let Some(r) = result {
        line["result"] = r;
    }
    if let Some(e) = error {
        let kind = match &e {
            CliError::Input(_) => "input",
            CliError::Failure(m) if m.starts_with("panic") => "panic",
            CliError::Failure(_) => "failure",
        };
        line["error"] = json!({"kind": kind, "exit_code": e.exit_code(), "message": e.message()});
    }
    line
}

/// The files that already have a complete line in `path` (for `--resume`).
fn done_files(path: &Path) -> Result<HashSet<String>, CliError> {
    let f = match std::fs::File::open(path) {
        Ok(f) => f,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(HashSet::new()),
        Err(e) => return Err(CliError::Input(format!("{}: {e}", path.display()))),
    };
    let mut done = HashSet::new();
    for line in std::io::BufReader::new(f).lines() {
        let line = line.map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
        // A line cut short by an interruption does not parse: that file runs again.
        if let Ok(v) = serde_json::from_str::<Value>(&line) {
            if let (Some(file), Some(_)) = (v["file"].as_str(), v["ok"].as_bool()) {
                done.insert(file.to_string());
            }
        }
    }
    Ok(done)
}

pub fn run(a: &BatchArgs, ui: Ui) -> Result<(), CliError> {
    if a.resume && a.jsonl.is_none() {
        return Err(CliError::Input(
            "--resume needs --jsonl FILE (the results to resume from)".into(),
        ));
    }
    if a.task == BatchTask::Info && a.output.is_some() {
        return Err(CliError::Input(
            "-o OUTDIR: the info task writes no mesh".into(),
        ));
    }
    let files = input_files(&a.inputs)?;
    if files.is_empty() {
        return Err(CliError::Input("no mesh file found in the inputs".into()));
    }
    // Bad task options fail here, before any work.
    let probe_out = a.output.as_ref().map(|o| o.join("probe.off"));
    if let Command::Decimate(d) = task_command(a.task, &files[0], probe_out.as_deref(), &a.options)?
    {
        // Every file would write the one file named.
        if d.maps.is_some() {
            return Err(CliError::Input(
                "task options: --maps names one file, and batch runs many: run `decimate \
                 --maps` per file"
                    .into(),
            ));
        }
    }
    if let Some(o) = &a.output {
        std::fs::create_dir_all(o).map_err(|e| {
            CliError::Input(format!(
                "{}: cannot create the output directory: {e}",
                o.display()
            ))
        })?;
    }
    let done = match (&a.jsonl, a.resume) {
        (Some(p), true) => done_files(p)?,
        _ => HashSet::new(),
    };
    let todo: Vec<PathBuf> = files
        .iter()
        .filter(|f| !done.contains(&f.display().to_string()))
        .cloned()
        .collect();
    let mut sink: Box<dyn Write> = match &a.jsonl {
        Some(p) => Box::new(
            std::fs::OpenOptions::new()
                .create(true)
                .append(a.resume)
                .write(true)
                .truncate(!a.resume)
                .open(p)
                .map_err(|e| CliError::Input(format!("{}: {e}", p.display())))?,
        ),
        None => Box::new(std::io::stdout()),
    };
    if let (Some(p), true) = (&a.jsonl, a.resume) {
        // A line cut short by an interruption has no newline: end it, so that the
        // appended lines stay one per line (the cut one stays unparseable, and its file
        // has run again).
        if last_byte(p).is_some_and(|c| c != b'\n') {
            writeln!(sink).map_err(|e| write_error(a, e))?;
        }
    }
    let root = common_root(&files);
    let jobs = a.jobs.unwrap_or_else(|| {
        std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
    });
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.max(1))
        .build()
        .map_err(|e| CliError::Failure(format!("cannot start {jobs} worker threads: {e}")))?;
    let pb = bar(
        ui,
        todo.len() as u64,
        format!("{} ({} jobs)", task_name(a.task), jobs),
    );
    let (tx, rx) = mpsc::channel::<(usize, Value)>();
    let started = std::time::Instant::now();
    let mut failed = 0usize;
    std::thread::scope(|scope| -> Result<(), CliError> {
        let todo = &todo;
        let root = &root;
        // Largest files first, one file per work item: the long ones start early
        // instead of ending the run alone on one thread (lines still come out in input
        // order).
        let mut order: Vec<(u64, usize)> = todo
            .iter()
            .enumerate()
            .map(|(i, f)| (std::fs::metadata(f).map_or(0, |m| m.len()), i))
            .collect();
        order.sort_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
        scope.spawn(move || {
            pool.install(|| {
                order
                    .par_iter()
                    .with_max_len(1)
                    .for_each_with(tx, |tx, &(_, i)| {
                        let file = &todo[i];
                        let out = a
                            .output
                            .as_ref()
                            .map(|o| output_path(o, root, file, a.task));
                        if let Some(parent) = out.as_ref().and_then(|o| o.parent()) {
                            let _ = std::fs::create_dir_all(parent);
                        }
                        let cmd = task_command(a.task, file, out.as_deref(), &a.options);
                        // The receiver lives until every line is in: a send cannot fail.
                        let _ = tx.send((i, line_of(file, a.task, cmd)));
                    });
            });
        });
        // Lines are written in input order as soon as all earlier ones are in.
        let mut pending = BTreeMap::new();
        let mut next = 0;
        for (i, line) in rx {
            pending.insert(i, line);
            while let Some(line) = pending.remove(&next) {
                if line["ok"] == false {
                    failed += 1;
                }
                writeln!(sink, "{line}")
                    .and_then(|()| sink.flush())
                    .map_err(|e| write_error(a, e))?;
                next += 1;
                pb.inc(1);
            }
        }
        Ok(())
    })?;
    pb.finish_and_clear();
    if !ui.quiet {
        eprintln!(
            "batch {}: {} files ({} skipped as already done), {} failed, {:.1} s with {} jobs",
            task_name(a.task),
            todo.len(),
            files.len() - todo.len(),
            failed,
            started.elapsed().as_secs_f64(),
            jobs
        );
    }
    if failed > 0 {
        return Err(CliError::Failure(format!(
            "{failed} of {} files failed (their lines carry the errors)",
            todo.len()
        )));
    }
    Ok(())
}

/// The last byte of the file `p` (`None` for an empty or unreadable file).
fn last_byte(p: &Path) -> Option<u8> {
    use std::io::{Read, Seek, SeekFrom};
    let mut f = std::fs::File::open(p).ok()?;
    f.seek(SeekFrom::End(-1)).ok()?;
    let mut b = [0u8; 1];
    f.read_exact(&mut b).ok()?;
    Some(b[0])
}

fn write_error(a: &BatchArgs, e: std::io::Error) -> CliError {
    if e.kind() == std::io::ErrorKind::BrokenPipe && a.jsonl.is_none() {
        super::signals::die_of_broken_pipe();
    }
    let to = a
        .jsonl
        .as_ref()
        .map_or("stdout".to_string(), |p| p.display().to_string());
    CliError::Failure(format!("cannot write to {to}: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesh_files_are_told_by_extension() {
        for yes in ["a.off", "a.OFF", "b.obj.gz", "c.ply", "d.stl", "x.y.off"] {
            assert!(is_mesh_file(Path::new(yes)), "{yes}");
        }
        for no in ["a.txt", "off", ".off", "a.gz", "a.off.bak", "README.md"] {
            assert!(!is_mesh_file(Path::new(no)), "{no}");
        }
    }

    #[test]
    fn output_paths_keep_the_relative_path_and_name_the_task() {
        let out = Path::new("/o");
        let root = Path::new("/in");
        assert_eq!(
            output_path(out, root, Path::new("/in/a/x.off.gz"), BatchTask::Reduce),
            PathBuf::from("/o/a/x.reduce.off.gz")
        );
        assert_eq!(
            output_path(out, root, Path::new("/in/y.stl"), BatchTask::Quad),
            PathBuf::from("/o/y.quad.off")
        );
        assert_eq!(
            output_path(out, root, Path::new("/in/y.stl"), BatchTask::Simplify),
            PathBuf::from("/o/y.simplify.stl")
        );
        assert_eq!(
            common_root(&[PathBuf::from("/in/a/x.off"), PathBuf::from("/in/b/y.off")]),
            PathBuf::from("/in")
        );
    }
}
