//! `contractible simplify IN -o OUT (--eps X | --eps-rel F)`: topology-preserving
//! short-edge simplification (Pepko–Borisenko) of every component, closed or with
//! boundary.
//!
//! Input problems are exit code 2 and write nothing: an unreadable or malformed file
//! (the readers already refuse NaN and infinite coordinates, located), faces that are not
//! a 2-manifold possibly with boundary (located), a bad ε, and a mesh without usable
//! positions. A mesh read from a file always has positions (every format requires
//! them); one whose vertices all lie at a single point — what `gen random` writes, since
//! its surfaces have no coordinates — is refused as carrying none: every edge would have
//! length 0, so ε could not select anything and `--eps-rel` would give ε = 0.
//!
//! The output is checked before it is written, independently of the algorithm: it is
//! rebuilt from its face list and must be a union of surfaces with the input's number of
//! components and the same multiset of (χ, orientability, boundary loops), with no
//! unused vertex. A mismatch is an internal error (exit code 1) and writes nothing.

use contractible::simplify::Stats;
use contractible::{Eps, SimplifyOptions, SimplifyResult, TriMesh};
use serde::Serialize;

use super::args::SimplifyArgs;
use super::jobs::with_jobs;
use super::progress::{finish, TaskBars};
use super::{meshio, print_json, CliError, Ui};

/// The JSON result of `simplify`: the options, every [`Stats`] field (flattened), and
/// the I/O around them.
#[derive(Serialize, Debug)]
pub struct SimplifyReport {
    pub file: String,
    pub output: String,
    /// The ε used (absolute).
    pub eps: f64,
    /// `--eps-rel` when given, else `null`.
    pub eps_rel: Option<f64>,
    /// Diagonal of the bounding box of the vertices the faces use.
    pub bbox_diagonal: f64,
    pub mode: &'static str,
    pub side: &'static str,
    pub position: &'static str,
    /// Whether the fold-over guard was on (`--allow-foldover` turns it off).
    pub guard: bool,
    #[serde(flatten)]
    pub stats: Stats,
    /// Unused input vertices (dropped, as every command does).
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub welded_vertices: Option<usize>,

    pub seconds_read: f64,
    /// Validating the input (faces and positions).
    pub seconds_build: f64,
    /// The independent topology check of the output.
    pub seconds_verify: f64,
    pub seconds_write: f64,
}

/// [`contractible::simplify`] with the command line's bars (a spinner while the input is
/// checked, a bar that follows the scan of every pass of every component, naming the
/// component and the pass, then the verification).
pub fn simplify_with_bars(
    mesh: &TriMesh,
    options: SimplifyOptions,
    ui: Ui,
) -> Result<SimplifyResult, contractible::Error> {
    let (monitor, bars) = TaskBars::monitor(
        ui,
        "simplifying",
        options.mode.to_string(),
        "verifying: the output rebuilt from its faces has the input's topology",
    );
    let r = contractible::simplify(mesh, &SimplifyOptions { monitor, ..options });
    finish(&bars);
    r
}

/// A length for people: 6 significant digits, scientific outside [1e-3, 1e6).
pub fn fmt_len(x: f64) -> String {
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        let digits = if x == 0.0 {
            0
        } else {
            (5 - x.abs().log10().floor() as i32).max(0) as usize
        };
        format!("{x:.digits$}")
    } else {
        format!("{x:.5e}")
    }
}

fn check_eps(flag: &str, what: &str, v: f64) -> Result<(), CliError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(CliError::Input(format!(
            "{flag} {v:?}: {what} must be a finite number > 0"
        )))
    }
}

/// Runs the command without printing its report (warnings and bars follow `ui`).
pub fn compute(a: &SimplifyArgs, ui: Ui) -> Result<SimplifyReport, CliError> {
    let output = meshio::check_output(&a.output, a.output_format.map(Into::into), &[&a.input])?;
    if let Some(e) = a.eps {
        check_eps("--eps", "ε", e)?;
    }
    if let Some(r) = a.eps_rel {
        check_eps("--eps-rel", "the fraction of the bounding-box diagonal", r)?;
    }
    let path = &a.input;
    let (mesh, seconds_read, welded_vertices, names) = meshio::read_input(path, &a.input_opts, ui)?;
    let eps = match (a.eps, a.eps_rel) {
        (Some(e), _) => Eps::Absolute(e),
        (None, Some(r)) => Eps::Relative(r),
        // clap's required group gives one of the two.
        (None, None) => {
            return Err(CliError::Input(
                "one of --eps and --eps-rel is required".into(),
            ))
        }
    };
    let options = SimplifyOptions {
        eps,
        mode: a.mode,
        side: a.side,
        position: a.position,
        allow_foldover: a.allow_foldover,
        ..SimplifyOptions::default()
    };
    let out = with_jobs(a.jobs, |parallel| {
        simplify_with_bars(
            &mesh,
            SimplifyOptions {
                parallel,
                ..options.clone()
            },
            ui,
        )
    })?
    .map_err(|e| match e {
        // The flags themselves were checked above: what is left is a relative ε that
        // gives no usable absolute one.
        contractible::Error::BadOption { expected, .. } => {
            CliError::Input(format!("--eps-rel {expected}"))
        }
        e => meshio::task_error(&mesh, &names, "simplify", e),
    })?;
    if !out.verified {
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
    Ok(SimplifyReport {
        file: path.display().to_string(),
        output: output.display(),
        eps: out.eps,
        eps_rel: out.eps_rel,
        bbox_diagonal: out.bbox_diagonal,
        mode: options.mode.name(),
        side: options.side.name(),
        position: options.position.name(),
        guard: !options.allow_foldover,
        stats: out.stats,
        dropped_vertices: out.dropped_vertices,
        welded_vertices,
        seconds_read,
        seconds_build: out.seconds_build,
        seconds_verify: out.seconds_verify.unwrap_or(0.0),
        seconds_write,
    })
}

pub fn run(a: &SimplifyArgs, ui: Ui) -> Result<(), CliError> {
    let report = compute(a, ui)?;
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        print_human(&report);
    }
    Ok(())
}

fn print_human(r: &SimplifyReport) {
    let s = &r.stats;
    outln!(
        "{} -> {}: {} mode, {} side, {} positions, fold-over guard {}",
        r.file,
        r.output,
        r.mode,
        r.side,
        r.position,
        if r.guard { "on" } else { "off" }
    );
    match r.eps_rel {
        Some(rel) => outln!(
            "  ε = {} ({} × the bounding-box diagonal {})",
            fmt_len(r.eps),
            rel,
            fmt_len(r.bbox_diagonal)
        ),
        None => outln!(
            "  ε = {} (bounding-box diagonal {})",
            fmt_len(r.eps),
            fmt_len(r.bbox_diagonal)
        ),
    }
    let plural =
        |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    outln!(
        "  vertices {} -> {}, faces {} -> {}; {}, {} (kept, checked independently)",
        s.vertices_in,
        s.vertices_out,
        s.faces_in,
        s.faces_out,
        plural(s.components, "component", "components"),
        plural(s.boundary_loops, "boundary loop", "boundary loops")
    );
    outln!(
        "  contractions {}; discs removed {} ({} vertices inside); passes {}",
        s.edges_contracted,
        s.discs_removed,
        s.vertices_removed_inside,
        s.passes
    );
    outln!(
        "  skipped (events over all passes): link condition {}, non-disc {}, fold-over {}, \
         frozen {}",
        s.skipped.link_condition,
        s.skipped.non_disc,
        s.skipped.foldover,
        s.skipped.frozen
    );
    outln!(
        "  edges shorter than ε remaining: {} (link condition {}, non-disc {}, fold-over {})",
        s.short_edges_remaining,
        s.remaining.link_condition,
        s.remaining.non_disc,
        s.remaining.foldover
    );
    outln!(
        "  shortest remaining edge {}; {:.4} s",
        s.shortest_remaining_edge
            .map_or_else(|| "-".to_string(), fmt_len),
        s.seconds
    );
    outln!(
        "  time: read {:.3} s, check input {:.3} s, simplify {:.3} s, verify {:.3} s, write {:.3} s",
        r.seconds_read,
        r.seconds_build,
        s.seconds,
        r.seconds_verify,
        r.seconds_write
    );
    outln!("wrote {}", r.output);
}
