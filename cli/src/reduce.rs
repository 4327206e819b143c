//! `contractible reduce IN [-o OUT]`: irreducible triangulations per component.

use contractible::irreducible::Algorithm;
use contractible::task::ReduceStats;
use contractible::{ReduceOptions, ReduceResult, TriMesh};
use serde::Serialize;

use super::args::ReduceArgs;
use super::jobs::with_jobs;
use super::progress::{finish, TaskBars};
use super::{meshio, print_json, CliError, Ui};

/// The JSON result of `reduce`: totals at the top level plus one entry per component.
#[derive(Serialize, Debug)]
pub struct ReduceReport {
    pub file: String,
    pub output: Option<String>,
    pub seed: u64,
    pub components: usize,
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub welded_vertices: Option<usize>,
    #[serde(flatten)]
    pub totals: ReduceStats,
    pub component_list: Vec<ReduceStats>,
    pub seconds_read: f64,
    pub seconds_build: f64,
    /// The independent check of the outputs (absent with `--no-verify`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_verify: Option<f64>,
    /// Writing the output (absent without `-o`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_write: Option<f64>,
    /// Where the contractions went (absent without `--history`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub history: Option<String>,
    /// Writing the contractions (absent without `--history`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_write_history: Option<f64>,
}

/// What the bar of the reductions says.
const VERB: &str = "reducing";

/// [`contractible::reduce`] with the command line's bars (a spinner while the input is
/// checked, a bar following the algorithm inside each component, a bar over the
/// verification), ε counted, the outputs verified unless `no_verify`, the contractions
/// kept when `history`.
pub fn reduce_with_bars(
    mesh: &TriMesh,
    algorithm: Algorithm,
    seed: u64,
    no_verify: bool,
    history: bool,
    parallel: bool,
    ui: Ui,
) -> Result<ReduceResult, contractible::Error> {
    let (monitor, bars) = TaskBars::monitor(
        ui,
        VERB,
        algorithm.to_string(),
        "verifying: no edge passes the link condition",
    );
    let r = contractible::reduce(
        mesh,
        &ReduceOptions {
            algorithm,
            seed,
            count_retests: true,
            // Only `--history` writes the contractions: without it, no memory for them.
            keep_history: history,
            verify: !no_verify,
            parallel,
            monitor,
        },
    );
    finish(&bars);
    r
}

/// One line with the time of every step that ran.
fn timings(r: &ReduceReport) -> String {
    let mut steps = vec![
        format!("read {:.3} s", r.seconds_read),
        format!("check input {:.3} s", r.seconds_build),
        format!("{} {:.3} s", r.totals.algorithm, r.totals.seconds),
    ];
    if let (Some(t), Some(how)) = (r.seconds_verify, r.totals.verified_by) {
        steps.push(format!("verify {t:.3} s ({how} link test on every edge)"));
    }
    if let Some(t) = r.seconds_write {
        steps.push(format!("write {t:.3} s"));
    }
    if let Some(t) = r.seconds_write_history {
        steps.push(format!("write history {t:.3} s"));
    }
    format!("time: {}", steps.join(", "))
}

fn print_table(stats: &[ReduceStats], totals: &ReduceStats, max_rows: usize) {
    outln!(
        "{:>9} {:>10} {:>9} {:>9} {:>10} {:>6} {:>12} {:>9} {:>10}",
        "component",
        "surface",
        "V in",
        "V out",
        "ℓ",
        "ε",
        "contractions",
        "seconds",
        "irreducible"
    );
    let surface = |s: &ReduceStats| match s.genus {
        Some(g) => format!("g={g}"),
        None => format!("h={} (n.o.)", s.euler_genus),
    };
    let verdict = |s: &ReduceStats| match s.irreducible {
        Some(true) => "yes",
        Some(false) => "NO",
        None => "-",
    };
    let row = |name: String, s: &ReduceStats| {
        outln!(
            "{:>9} {:>10} {:>9} {:>9} {:>10} {:>6} {:>12} {:>9.4} {:>10}",
            name,
            surface(s),
            s.vertices_in,
            s.vertices_out,
            s.link_tests,
            s.edges_tested_more_than_once,
            s.contractions,
            s.seconds,
            verdict(s)
        )
    };
    for (i, s) in stats.iter().enumerate().take(max_rows) {
        row(i.to_string(), s);
    }
    if stats.len() > max_rows {
        outln!("{:>9}", format!("({} more)", stats.len() - max_rows));
    }
    row("total".into(), totals);
}

/// Runs the command without printing its report (warnings and bars follow `ui`).
pub fn compute(a: &ReduceArgs, ui: Ui) -> Result<ReduceReport, CliError> {
    let output = a
        .output
        .as_deref()
        .map(|o| meshio::check_output(o, a.output_format.map(Into::into), &[&a.input]))
        .transpose()?;
    if let Some(h) = &a.history {
        let on_stdout = output.as_ref().is_some_and(|o| o.path.is_none());
        meshio::check_index_pairs_output(h, "--history", on_stdout, &[&a.input])?;
    }
    let (mesh, seconds_read, welded_vertices, names) =
        meshio::read_input(&a.input, &a.input_opts, ui)?;
    let keep = a.history.is_some();
    let r = with_jobs(a.jobs, |parallel| {
        reduce_with_bars(&mesh, a.algo, a.seed, a.no_verify, keep, parallel, ui)
    })?
    .map_err(|e| meshio::task_error(&mesh, &names, "reduce", e))?;
    meshio::warn_dropped(&names, r.dropped_vertices, ui);
    drop(mesh);
    let seconds_write = match &output {
        Some(out) => Some(meshio::write(out, &r.mesh, ui)?),
        None => None,
    };
    let seconds_write_history = match &a.history {
        Some(path) => {
            let t = std::time::Instant::now();
            meshio::write_index_pairs(path, &r.contractions())?;
            Some(t.elapsed().as_secs_f64())
        }
        None => None,
    };
    Ok(ReduceReport {
        file: a.input.display().to_string(),
        output: output.as_ref().map(meshio::Output::display),
        seed: a.seed,
        components: r.components.len(),
        dropped_vertices: r.dropped_vertices,
        welded_vertices,
        component_list: r.components.iter().map(|c| c.stats.clone()).collect(),
        totals: r.totals,
        seconds_read,
        seconds_build: r.seconds_build,
        seconds_verify: r.seconds_verify,
        seconds_write,
        history: a.history.as_deref().map(|p| p.display().to_string()),
        seconds_write_history,
    })
}

pub fn run(a: &ReduceArgs, ui: Ui) -> Result<(), CliError> {
    let report = compute(a, ui)?;
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        outln!("{} ({}):", report.file, report.totals.algorithm);
        print_table(&report.component_list, &report.totals, 20);
        outln!("{}", timings(&report));
        if let (Some(o), Some(_)) = (&report.output, report.seconds_write) {
            outln!("wrote {o}");
        }
        if let Some(h) = report.history.as_deref().filter(|&h| h != "-") {
            outln!("wrote {h}");
        }
    }
    Ok(())
}
