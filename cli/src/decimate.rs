//! `contractible decimate IN -o OUT [--faces N] [--keep F] [--max-error E |
//! --max-error-rel R]`: quadric-error edge collapse (Garland–Heckbert) to a face budget
//! or an error cap, every collapse passing the link condition, on every component,
//! closed or with boundary.
//!
//! Input problems are exit code 2 and write nothing: an unreadable or malformed file,
//! faces that are not a 2-manifold possibly with boundary (located), a mesh without
//! usable positions (as `simplify`), a bad flag value (a fraction kept outside [0, 1], a
//! negative or non-finite error cap, a locked vertex the file does not have), all checked
//! before the mesh is decimated.
//!
//! The output is checked before it is written, independently of the algorithm (the
//! library's `verify_decimation`, unless `--no-verify`): rebuilt from its faces, each
//! component descends from one input component with the same (χ, orientability,
//! boundary loops), the maps agree with the faces, locked vertices kept their positions.
//! A mismatch is an internal error (exit code 1) and writes nothing.
//!
//! `--maps FILE` writes the provenance in the file's own numbering (from 0 in every
//! format; through `--weld` and `--triangulate`), so that attributes can be carried to
//! the output: see [`maps_json`].

use std::path::Path;
use std::time::Instant;

use contractible::decimate::{Refusals, Schedule, Stats, Stopped, NO_VERTEX};
use contractible::{DecimateOptions, DecimateResult, MaxError, TriMesh};
use serde::Serialize;

use super::args::DecimateArgs;
use super::jobs::in_pool;
use super::meshio::{self, Names};
use super::progress::{finish, TaskBars};
use super::simplify::fmt_len;
use super::{print_json, CliError, Ui};

/// The targets as given on the command line (`null` for a flag not given).
#[derive(Serialize, Debug, Clone, Copy)]
pub struct Targets {
    /// `--faces`.
    pub faces: Option<usize>,
    /// `--keep`.
    pub keep: Option<f64>,
    /// `--max-error`.
    pub max_error: Option<f64>,
    /// `--max-error-rel`.
    pub max_error_rel: Option<f64>,
}

/// The JSON result of `decimate`: the options, every [`Stats`] field (flattened), and
/// the I/O around them.
#[derive(Serialize, Debug)]
pub struct DecimateReport {
    pub file: String,
    pub output: String,
    /// The `--maps` file, or `null`.
    pub maps: Option<String>,
    /// The targets as given; `target_faces` and `max_error_cap` are what they resolved to.
    pub targets: Targets,
    /// Diagonal of the bounding box of the vertices the faces use.
    pub bbox_diagonal: f64,
    pub placement: &'static str,
    /// `exact` or `passes`.
    pub schedule: &'static str,
    /// Whether the fold-over guard was on (`--allow-foldover` turns it off).
    pub guard: bool,
    pub lock_boundary: bool,
    /// The `--lock` vertices (ids of the file from 0), sorted, without repeats.
    pub locked: Vec<u32>,
    #[serde(flatten)]
    pub stats: Stats,
    /// Whether the output passed the independent check (`false` with `--no-verify`).
    pub verified: bool,
    /// Unused input vertices (dropped, as every command does).
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub welded_vertices: Option<usize>,

    pub seconds_read: f64,
    /// Validating the input (faces and positions).
    pub seconds_build: f64,
    /// The independent check of the output (absent with `--no-verify`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_verify: Option<f64>,
    pub seconds_write: f64,
    /// Writing the `--maps` file (absent without it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_write_maps: Option<f64>,
}

/// [`contractible::decimate`] with the command line's bars (a spinner while the input
/// is checked, a bar over the faces removed, then the verification).
pub fn decimate_with_bars(
    mesh: &TriMesh,
    options: DecimateOptions,
    ui: Ui,
) -> Result<DecimateResult, contractible::Error> {
    let (monitor, bars) = TaskBars::monitor(
        ui,
        "decimating",
        options.placement.name().to_string(),
        "verifying: the output rebuilt from its faces has the input's topology",
    );
    let r = contractible::decimate(mesh, &DecimateOptions { monitor, ..options });
    finish(&bars);
    r
}

/// A flag's value that must be a finite number in `range` (what it must be in words).
fn check_value(flag: &str, v: f64, ok: impl Fn(f64) -> bool, must: &str) -> Result<(), CliError> {
    if v.is_finite() && ok(v) {
        Ok(())
    } else {
        Err(CliError::Input(format!("{flag} {v:?}: {must}")))
    }
}

/// The flags' values that can be checked without the mesh.
fn check_flags(a: &DecimateArgs) -> Result<(), CliError> {
    if let Some(k) = a.keep {
        check_value(
            "--keep",
            k,
            |k| (0.0..=1.0).contains(&k),
            "the fraction of the faces kept must be a number in [0, 1]",
        )?;
    }
    if let Some(e) = a.max_error {
        check_value(
            "--max-error",
            e,
            |e| e >= 0.0,
            "the error cap must be a finite number >= 0",
        )?;
    }
    if let Some(r) = a.max_error_rel {
        check_value(
            "--max-error-rel",
            r,
            |r| r >= 0.0,
            "the fraction of the bounding-box diagonal must be a finite number >= 0",
        )?;
    }
    Ok(())
}

/// The `--lock` ids (the file's, from 0) as mesh vertices; exit code 2 for an id the
/// file does not have. Returns the file ids sorted without repeats, and the mesh ids.
fn locked_vertices(
    a: &DecimateArgs,
    names: &Names,
    mesh: &TriMesh,
    ui: Ui,
) -> Result<(Vec<u32>, Vec<u32>), CliError> {
    let mut ids = a.lock.clone();
    ids.sort_unstable();
    ids.dedup();
    let n = names.file_vertex_count(mesh.vertex_count);
    let mut used = vec![false; mesh.vertex_count];
    if !ids.is_empty() {
        for f in &mesh.faces {
            for &v in f {
                if let Some(u) = used.get_mut(v as usize) {
                    *u = true;
                }
            }
        }
    }
    let mut mesh_ids = Vec::with_capacity(ids.len());
    for &v in &ids {
        let Some(m) = names.mesh_vertex(v, mesh.vertex_count) else {
            let last = match n {
                0 => "it has none".to_string(),
                n => format!("the last is {}", n - 1),
            };
            return Err(CliError::Input(format!(
                "--lock {v}: {} has {n} vertices, counted from 0 in every format ({last})",
                names.shown
            )));
        };
        if !used.get(m as usize).copied().unwrap_or(false) {
            ui.warn(&format!(
                "{}: --lock {v}: no face uses this vertex; it is dropped like every unused vertex",
                names.shown
            ));
        }
        mesh_ids.push(m);
    }
    mesh_ids.sort_unstable();
    mesh_ids.dedup();
    Ok((ids, mesh_ids))
}

/// The command line's message for a library error about an option (the flags were
/// checked before: what is left is a relative cap that gives no finite absolute one).
fn option_error(a: &DecimateArgs, option: &str, value: &str, expected: &str) -> CliError {
    let flag = match option {
        "keep" => "--keep",
        "locked" => "--lock",
        "max_error" if a.max_error_rel.is_some() => "--max-error-rel",
        "max_error" => "--max-error",
        other => other,
    };
    if flag == "--max-error-rel" {
        // The library's words start with the value: `1e308 times the diagonal ...`.
        CliError::Input(format!("{flag} {expected}"))
    } else {
        CliError::Input(format!("{flag} {value}: {expected}"))
    }
}

/// The `--maps` document: where every output vertex and face comes from, in the input
/// file's numbering (from 0 in every format, OBJ included), one array per line:
///
/// - `vertex_map[o]`: the file's vertex that survives as output vertex `o` (with
///   `--weld`, the lowest-numbered vertex of its group); increasing;
/// - `collapse_map[i]`: the output vertex that the file's vertex `i` went into (every
///   vertex of the file has an entry; `null` for a vertex no face uses);
/// - `face_origin[k]`: the file's face that output face `k` descends from (the same
///   face with its corners renamed by the collapses; with `--triangulate`, the polygon
///   its triangle was cut from, so several output faces may share one).
pub fn maps_json(report_file: &str, output: &str, names: &Names, r: &DecimateResult) -> String {
    let mesh_vertices = r.collapse_map.len();
    let vertex_map: Vec<u32> = r.vertex_map.iter().map(|&v| names.file_vertex(v)).collect();
    let collapse_map: Vec<Option<u32>> = (0..names.file_vertex_count(mesh_vertices))
        .map(|i| {
            names
                .mesh_vertex(i as u32, mesh_vertices)
                .and_then(|m| r.collapse_map.get(m as usize).copied())
                .filter(|&o| o != NO_VERTEX)
        })
        .collect();
    let face_origin: Vec<usize> = r
        .face_origin
        .iter()
        .map(|&f| names.file_face_index(f as usize))
        .collect();
    // Compact arrays, one per line: readable, and small beside the mesh.
    format!(
        "{{\n  \"file\": {},\n  \"output\": {},\n  \"index_base\": 0,\n  \"vertex_map\": {},\n  \
         \"collapse_map\": {},\n  \"face_origin\": {}\n}}\n",
        compact(report_file),
        compact(output),
        compact(&vertex_map),
        compact(&collapse_map),
        compact(&face_origin)
    )
}

/// `v` as compact JSON (strings and integer arrays, which always encode).
fn compact<T: Serialize + ?Sized>(v: &T) -> String {
    serde_json::to_string(v).unwrap_or_else(|_| "null".to_string())
}

/// Writes the maps document to `path`, atomically, or to stdout for `-`.
fn write_maps(path: &Path, text: &str) -> Result<(), CliError> {
    use std::io::Write;
    if path.as_os_str() == "-" {
        let mut out = std::io::stdout().lock();
        return match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
                super::signals::die_of_broken_pipe()
            }
            Err(e) => Err(CliError::Failure(format!("-: cannot write to stdout: {e}"))),
        };
    }
    meshio::write_side_file(path, |w| w.write_all(text.as_bytes()))
}

/// Runs the command without printing its report (warnings and bars follow `ui`).
pub fn compute(a: &DecimateArgs, ui: Ui) -> Result<DecimateReport, CliError> {
    let output = meshio::check_output(&a.output, a.output_format.map(Into::into), &[&a.input])?;
    check_flags(a)?;
    if let Some(p) = &a.maps {
        if p.as_os_str() == "-" {
            if output.path.is_none() {
                return Err(CliError::Input(
                    "-o - and --maps - would both write to stdout: send one to a file".into(),
                ));
            }
            super::report_to_stderr();
        } else {
            meshio::check_side_file(p, &[&a.input])?;
        }
    }
    let path = &a.input;
    let (mesh, seconds_read, welded_vertices, names) = meshio::read_input(path, &a.input_opts, ui)?;
    let (locked, locked_mesh) = locked_vertices(a, &names, &mesh, ui)?;
    let max_error = match (a.max_error, a.max_error_rel) {
        (Some(e), _) => Some(MaxError::Absolute(e)),
        (None, Some(r)) => Some(MaxError::Relative(r)),
        (None, None) => None,
    };
    let options = DecimateOptions {
        faces: a.faces,
        keep: a.keep,
        max_error,
        placement: a.placement,
        schedule: a.schedule,
        allow_foldover: a.allow_foldover,
        lock_boundary: a.lock_boundary,
        locked: locked_mesh,
        skip_verify: a.no_verify,
        ..DecimateOptions::default()
    };
    let out = in_pool(a.jobs, || decimate_with_bars(&mesh, options, ui))?.map_err(|e| match e {
        contractible::Error::BadOption {
            option,
            value,
            expected,
        } => option_error(a, option, &value, &expected),
        e => meshio::task_error(&mesh, &names, "decimate", e),
    })?;
    if !a.no_verify && !out.verified {
        return Err(CliError::Failure(format!(
            "internal error: {}: the output was not verified; nothing written",
            path.display()
        )));
    }
    // A valid mesh of closed surfaces is no soup (a soup's triangles are open discs),
    // and skipping it spares the position hashing on every large closed input.
    if !ui.quiet && out.stats.boundary_loops > 0 {
        if let Some(hint) = meshio::soup_hint(&mesh, &names) {
            ui.warn(&hint);
        }
    }
    meshio::warn_dropped(&names, out.dropped_vertices, ui);
    drop(mesh);
    let seconds_write = meshio::write(&output, &out.mesh, ui)?;
    let file = path.display().to_string();
    let mut seconds_write_maps = None;
    if let Some(p) = &a.maps {
        let t = Instant::now();
        write_maps(p, &maps_json(&file, &output.display(), &names, &out))?;
        seconds_write_maps = Some(t.elapsed().as_secs_f64());
    }
    Ok(DecimateReport {
        file,
        output: output.display(),
        maps: a.maps.as_deref().map(|p| p.display().to_string()),
        targets: Targets {
            faces: a.faces,
            keep: a.keep,
            max_error: a.max_error,
            max_error_rel: a.max_error_rel,
        },
        bbox_diagonal: out.bbox_diagonal,
        placement: a.placement.name(),
        schedule: a.schedule.name(),
        guard: !a.allow_foldover,
        lock_boundary: a.lock_boundary,
        locked,
        stats: out.stats,
        verified: out.verified,
        dropped_vertices: out.dropped_vertices,
        welded_vertices,
        seconds_read,
        seconds_build: out.seconds_build,
        seconds_verify: out.seconds_verify,
        seconds_write,
        seconds_write_maps,
    })
}

pub fn run(a: &DecimateArgs, ui: Ui) -> Result<(), CliError> {
    let report = compute(a, ui)?;
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        print_human(&report);
    }
    Ok(())
}

fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// The edges refused, by guard, in the order a reader asks about them.
fn by_guard(r: &Refusals) -> String {
    format!(
        "link condition {}, fold-over {}, lock {}, boundary {}, error cap {}",
        r.link_condition, r.foldover, r.lock, r.boundary, r.error
    )
}

/// At most this many components are listed one per line.
const MAX_COMPONENT_ROWS: usize = 20;

fn print_human(r: &DecimateReport) {
    let s = &r.stats;
    let mut how = vec![
        format!("{} placement", r.placement),
        format!("fold-over guard {}", if r.guard { "on" } else { "off" }),
    ];
    if r.schedule != Schedule::Exact.name() {
        how.push(format!("{} schedule", r.schedule));
    }
    if r.lock_boundary {
        how.push("boundary locked".into());
    }
    if !r.locked.is_empty() {
        how.push(format!(
            "{} locked",
            plural(r.locked.len(), "vertex", "vertices")
        ));
    }
    outln!("{} -> {}: {}", r.file, r.output, how.join(", "));
    outln!(
        "  faces {} -> {}, vertices {} -> {}; {}, {} ({})",
        s.faces_in,
        s.faces_out,
        s.vertices_in,
        s.vertices_out,
        plural(s.components, "component", "components"),
        plural(s.boundary_loops, "boundary loop", "boundary loops"),
        if r.verified {
            "kept, checked independently"
        } else {
            "not checked: --no-verify"
        }
    );
    // The targets, as given and as resolved.
    let mut targets = Vec::new();
    if let Some(t) = s.target_faces {
        let mut given = Vec::new();
        if let Some(n) = r.targets.faces {
            given.push(format!("--faces {n}"));
        }
        if let Some(k) = r.targets.keep {
            given.push(format!("--keep {k}"));
        }
        targets.push(format!(
            "{} ({})",
            plural(t, "face", "faces"),
            given.join(", ")
        ));
    }
    if let Some(cap) = s.max_error_cap {
        targets.push(match r.targets.max_error_rel {
            Some(rel) => format!(
                "error cap {} ({rel} × the bounding-box diagonal {})",
                fmt_len(cap),
                fmt_len(r.bbox_diagonal)
            ),
            None => format!("error cap {}", fmt_len(cap)),
        });
    }
    if targets.is_empty() {
        outln!("  target: none, as far as the guards allow");
    } else {
        outln!("  target: {}", targets.join(", "));
    }
    let short = match s.target_faces {
        Some(t) if s.stopped != Stopped::Target => format!(" ({t} faces not reached)"),
        _ => String::new(),
    };
    match s.stopped {
        Stopped::Target => outln!("  stopped: target reached"),
        Stopped::Error => outln!(
            "  stopped: error cap, every edge left would exceed it or is refused by a guard{short}"
        ),
        Stopped::Blocked => {
            outln!("  stopped: blocked, every edge left is refused by a guard{short}")
        }
    }
    if s.stopped != Stopped::Target {
        outln!(
            "  edges left {}, refused by: {}",
            s.remaining.total(),
            by_guard(&s.remaining)
        );
        if s.component_list.len() > 1 {
            for (k, c) in s.component_list.iter().enumerate().take(MAX_COMPONENT_ROWS) {
                outln!(
                    "    component {k}: faces {} -> {}; edges left {}: {}",
                    c.faces_in,
                    c.faces_out,
                    c.remaining.total(),
                    by_guard(&c.remaining)
                );
            }
            if s.component_list.len() > MAX_COMPONENT_ROWS {
                outln!(
                    "    ({} more components)",
                    s.component_list.len() - MAX_COMPONENT_ROWS
                );
            }
        }
    }
    // The refusals on the way (`refused`) stay in the JSON: they count the queue's
    // re-checks, which say more about the method than about the result.
    let passes = if s.passes > 0 {
        format!(" in {}", plural(s.passes, "pass", "passes"))
    } else {
        String::new()
    };
    outln!(
        "  collapses {}{passes}; largest error {}; {:.4} s",
        s.collapses,
        fmt_len(s.max_error),
        s.seconds
    );
    let mut steps = vec![
        format!("read {:.3} s", r.seconds_read),
        format!("check input {:.3} s", r.seconds_build),
        format!("decimate {:.3} s", s.seconds),
    ];
    if let Some(t) = r.seconds_verify {
        steps.push(format!("verify {t:.3} s"));
    }
    steps.push(format!("write {:.3} s", r.seconds_write));
    if let Some(t) = r.seconds_write_maps {
        steps.push(format!("write maps {t:.3} s"));
    }
    outln!("  time: {}", steps.join(", "));
    outln!("wrote {}", r.output);
    if let Some(m) = &r.maps {
        outln!("wrote {m}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refusals_are_listed_in_one_order() {
        let r = Refusals {
            lock: 1,
            boundary: 2,
            error: 3,
            link_condition: 4,
            foldover: 5,
        };
        assert_eq!(
            by_guard(&r),
            "link condition 4, fold-over 5, lock 1, boundary 2, error cap 3"
        );
    }
}
