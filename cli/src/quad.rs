//! `contractible quad IN [-o OUT] [--pairs FILE] [--triangles FILE]`: tri-quad conversion
//! per component.

use std::path::Path;
use std::time::Instant;

use contractible::quad::Algorithm;
use contractible::task::QuadStats;
use contractible::{QuadOptions, QuadResult, TriMesh};
use serde::Serialize;

use super::args::QuadArgs;
use super::jobs::with_jobs;
use super::progress::{finish, TaskBars};
use super::{meshio, print_json, CliError, Ui};

/// The JSON result of `quad`: totals at the top level plus one entry per component.
#[derive(Serialize, Debug)]
pub struct QuadReport {
    pub file: String,
    pub output: Option<String>,
    pub pairs: Option<String>,
    /// The paired triangulation's file (absent without `--triangles`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangles: Option<String>,
    pub seed: u64,
    pub components: usize,
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub welded_vertices: Option<usize>,
    #[serde(flatten)]
    pub totals: QuadStats,
    pub component_list: Vec<QuadStats>,
    pub seconds_read: f64,
    pub seconds_build: f64,
    /// The independent check of every pairing (its own step, after the conversions).
    pub seconds_verify: f64,
    /// Writing the quad mesh (absent without `-o`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_write: Option<f64>,
    /// Writing the pairs file (absent without `--pairs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_write_pairs: Option<f64>,
    /// Writing the paired triangulation (absent without `--triangles`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_write_triangles: Option<f64>,
}

/// What the bar of the conversions says.
const VERB: &str = "pairing";

/// [`contractible::quadrangulate`] with the command line's bars (a spinner while the
/// input is checked, a bar following the algorithm inside each component, a bar over
/// the verification).
pub fn quadrangulate_with_bars(
    mesh: &TriMesh,
    algorithm: Algorithm,
    seed: u64,
    parallel: bool,
    ui: Ui,
) -> Result<QuadResult, contractible::Error> {
    let (monitor, bars) = TaskBars::monitor(
        ui,
        VERB,
        algorithm.to_string(),
        "verifying: perfect pairings of adjacent faces",
    );
    let r = contractible::quadrangulate(
        mesh,
        &QuadOptions {
            algorithm,
            seed,
            verify: true,
            parallel,
            monitor,
        },
    );
    finish(&bars);
    r
}

/// Runs the command without printing its report (warnings and bars follow `ui`).
pub fn compute(a: &QuadArgs, ui: Ui) -> Result<QuadReport, CliError> {
    let output = match &a.output {
        Some(out) => {
            let o = meshio::check_output(out, a.output_format.map(Into::into), &[&a.input])?;
            if o.format == contractible::io::Format::Stl {
                return Err(CliError::Input(format!(
                    "{}: STL holds triangles only; write the quad mesh as .off, .obj or .ply",
                    o.display()
                )));
            }
            Some(o)
        }
        None => None,
    };
    if let Some(p) = &a.pairs {
        let on_stdout = output.as_ref().is_some_and(|o| o.path.is_none());
        meshio::check_index_pairs_output(p, "--pairs", on_stdout, &[&a.input])?;
    }
    let triangles = match &a.triangles {
        Some(t) => {
            if t.as_os_str() == "-" {
                return Err(CliError::Input(
                    "--triangles writes a mesh file: give it a file name, not -".into(),
                ));
            }
            let o = meshio::check_output(t, None, &[&a.input])?;
            if output.as_ref().is_some_and(|out| out.path == o.path) {
                return Err(CliError::Input(format!(
                    "{}: -o and --triangles name the same file",
                    o.display()
                )));
            }
            Some(o)
        }
        None => None,
    };
    let (mesh, seconds_read, welded_vertices, names) =
        meshio::read_input(&a.input, &a.input_opts, ui)?;
    let r = with_jobs(a.jobs, |parallel| {
        quadrangulate_with_bars(&mesh, a.algo, a.seed, parallel, ui)
    })?
    .map_err(|e| meshio::task_error(&mesh, &names, "quad", e))?;
    meshio::warn_dropped(&names, r.dropped_vertices, ui);
    drop(mesh);
    let seconds_write = match &output {
        Some(out) => Some(meshio::write(out, &r.mesh, ui)?),
        None => None,
    };
    let mut seconds_write_pairs = None;
    if let Some(path) = &a.pairs {
        let t = Instant::now();
        meshio::write_index_pairs(path, &r.pairs)?;
        seconds_write_pairs = Some(t.elapsed().as_secs_f64());
    }
    let seconds_write_triangles = match &triangles {
        Some(out) => {
            let k = TriMesh {
                vertex_count: r.mesh.vertex_count,
                positions: r.mesh.positions.clone(),
                faces: r.triangles.clone(),
            };
            Some(meshio::write(out, &k, ui)?)
        }
        None => None,
    };
    Ok(QuadReport {
        file: a.input.display().to_string(),
        output: output.as_ref().map(meshio::Output::display),
        pairs: a.pairs.as_deref().map(|p: &Path| p.display().to_string()),
        triangles: triangles.as_ref().map(meshio::Output::display),
        seed: a.seed,
        components: r.components.len(),
        dropped_vertices: r.dropped_vertices,
        welded_vertices,
        component_list: r.components.iter().map(|c| c.stats.clone()).collect(),
        totals: r.totals,
        seconds_read,
        seconds_build: r.seconds_build,
        seconds_verify: r.seconds_verify.unwrap_or(0.0),
        seconds_write,
        seconds_write_pairs,
        seconds_write_triangles,
    })
}

pub fn run(a: &QuadArgs, ui: Ui) -> Result<(), CliError> {
    let report = compute(a, ui)?;
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        let t = &report.totals;
        outln!(
            "{} ({}): {} triangles -> {} quads; initial {:.4} s, {:.3} % paired ({} unpaired); \
             completion {:.4} s ({} augmenting paths, {} phases); total {:.4} s; {} flips",
            report.file,
            t.algorithm,
            t.faces,
            t.quads,
            t.initial_seconds,
            t.initial_paired_percent,
            t.initial_unpaired,
            t.completion_seconds,
            t.augmenting_paths,
            t.phases,
            t.total_seconds,
            t.flips
        );
        let mut steps = vec![
            format!("read {:.3} s", report.seconds_read),
            format!("check input {:.3} s", report.seconds_build),
            format!("{} {:.3} s", t.algorithm, t.total_seconds),
            format!("verify {:.3} s", report.seconds_verify),
        ];
        if let Some(w) = report.seconds_write {
            steps.push(format!("write {w:.3} s"));
        }
        if let Some(w) = report.seconds_write_pairs {
            steps.push(format!("write pairs {w:.3} s"));
        }
        if let Some(w) = report.seconds_write_triangles {
            steps.push(format!("write triangles {w:.3} s"));
        }
        outln!("time: {}", steps.join(", "));
        for o in [&report.output, &report.pairs, &report.triangles]
            .into_iter()
            .flatten()
        {
            outln!("wrote {o}");
        }
    }
    Ok(())
}
