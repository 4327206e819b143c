//! `contractible reduce IN [-o OUT]`: irreducible triangulations per component.

use std::path::Path;

use contractible::irreducible::{self, Algorithm, Options, Reduction};
use contractible::{SurfaceType, Surfaces, TriMesh};
use serde::Serialize;

use super::args::ReduceArgs;
use super::progress::bar;
use super::{meshio, print_json, CliError, Ui};

/// Counters of one reduction (one component, or the totals over all of them).
#[derive(Serialize, Debug, Clone)]
pub struct ReduceStats {
    pub algo: &'static str,
    pub vertices_in: usize,
    pub edges_in: usize,
    pub faces_in: usize,
    pub euler_characteristic: i64,
    pub orientable: bool,
    /// Orientable genus (sum over components); `null` if any component is non-orientable.
    pub genus: Option<i64>,
    /// `2 - χ` (summed over components).
    pub euler_genus: i64,
    pub vertices_out: usize,
    pub edges_out: usize,
    pub faces_out: usize,
    /// ℓ: link-condition tests.
    pub link_tests: u64,
    /// ε: edges tested more than once.
    pub edges_tested_more_than_once: u64,
    pub contractions: u64,
    /// Time in the algorithm proper (no I/O, no validation).
    pub seconds: f64,
    /// Whether the naive link test found no contractible edge (`null`: not checked).
    pub irreducible: Option<bool>,
}

impl ReduceStats {
    /// The counters of `r`, the reduction of a surface of type `input`.
    fn of(r: &Reduction, input: SurfaceType, irreducible: Option<bool>) -> Self {
        let s = &r.stats;
        ReduceStats {
            algo: r.algorithm.name(),
            vertices_in: s.vertices_in,
            edges_in: s.edges_in,
            faces_in: s.faces_in,
            euler_characteristic: input.euler_characteristic(),
            orientable: input.is_orientable(),
            genus: input.orientable_genus(),
            euler_genus: input.euler_genus(),
            vertices_out: s.vertices_out,
            edges_out: r.tri.edge_count(),
            faces_out: s.faces_out,
            link_tests: s.link_tests,
            edges_tested_more_than_once: s.edges_tested_more_than_once,
            contractions: s.contractions,
            seconds: s.seconds,
            irreducible,
        }
    }

    pub fn total(algo: Algorithm, parts: &[ReduceStats]) -> Self {
        let orientable = parts.iter().all(|p| p.orientable);
        let sum = |f: fn(&ReduceStats) -> usize| parts.iter().map(f).sum::<usize>();
        let sum64 = |f: fn(&ReduceStats) -> u64| parts.iter().map(f).sum::<u64>();
        let chi: i64 = parts.iter().map(|p| p.euler_characteristic).sum();
        let irreducible = parts
            .iter()
            .map(|p| p.irreducible)
            .try_fold(true, |acc, x| x.map(|b| acc && b));
        ReduceStats {
            algo: algo.name(),
            vertices_in: sum(|p| p.vertices_in),
            edges_in: sum(|p| p.edges_in),
            faces_in: sum(|p| p.faces_in),
            euler_characteristic: chi,
            orientable,
            genus: orientable.then(|| parts.iter().filter_map(|p| p.genus).sum()),
            euler_genus: parts.iter().map(|p| p.euler_genus).sum(),
            vertices_out: sum(|p| p.vertices_out),
            edges_out: sum(|p| p.edges_out),
            faces_out: sum(|p| p.faces_out),
            link_tests: sum64(|p| p.link_tests),
            edges_tested_more_than_once: sum64(|p| p.edges_tested_more_than_once),
            contractions: sum64(|p| p.contractions),
            seconds: parts.iter().map(|p| p.seconds).sum(),
            irreducible,
        }
    }
}

/// The JSON result of `reduce`: totals at the top level plus one entry per component.
#[derive(Serialize, Debug)]
pub struct ReduceReport {
    pub file: String,
    pub output: Option<String>,
    pub seed: u64,
    pub component_count: usize,
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub welded_vertices: Option<usize>,
    #[serde(flatten)]
    pub totals: ReduceStats,
    pub components: Vec<ReduceStats>,
    pub seconds_read: f64,
    pub seconds_build: f64,
}

/// Reduces (a copy of) every component of `surfaces` with `algo`; verifies each output
/// with the naive link test when `verify`. Returns the reductions and their counters.
pub fn reduce_all(
    surfaces: &Surfaces,
    algo: Algorithm,
    seed: u64,
    verify: bool,
    ui: Ui,
) -> (Vec<Reduction>, Vec<ReduceStats>) {
    let n = surfaces.components.len();
    let pb = bar(ui, n as u64, format!("reducing ({})", algo.name()));
    let options = Options {
        seed,
        count_retests: true,
    };
    let mut reductions = Vec::with_capacity(n);
    let mut stats = Vec::with_capacity(n);
    for c in &surfaces.components {
        let input = SurfaceType::of(&c.tri);
        let r = irreducible::reduce(c.tri.clone(), algo, &options);
        let irr = verify.then(|| r.tri.is_irreducible_naive());
        stats.push(ReduceStats::of(&r, input, irr));
        reductions.push(r);
        pb.inc(1);
    }
    pb.finish_and_clear();
    (reductions, stats)
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

pub fn run(a: &ReduceArgs, ui: Ui) -> Result<(), CliError> {
    if let Some(out) = &a.output {
        meshio::check_output(out)?;
    }
    let (mesh, seconds_read, welded_vertices, names) =
        meshio::read_input(&a.input, &a.input_opts, ui)?;
    let (surfaces, seconds_build) = meshio::build_closed(&mesh, &names, ui, "reduce")?;
    // Keep only what the output needs: the big face list and the triangulations are
    // consumed as the components are reduced (peak memory matters on 4M-face inputs).
    let TriMesh {
        vertex_count,
        positions,
        faces,
    } = mesh;
    drop(faces);
    let dropped_vertices = surfaces.dropped_vertices.len();
    let algo: Algorithm = a.algo.into();
    let options = Options {
        seed: a.seed,
        count_retests: true,
    };
    let n = surfaces.components.len();
    let pb = bar(ui, n as u64, format!("reducing ({})", algo.name()));
    let mut parts = Vec::with_capacity(n);
    let mut stats = Vec::with_capacity(n);
    for c in surfaces.components {
        let input = SurfaceType::of(&c.tri);
        let r = irreducible::reduce(c.tri, algo, &options);
        let irr = (!a.no_verify).then(|| r.tri.is_irreducible_naive());
        stats.push(ReduceStats::of(&r, input, irr));
        parts.push((r.tri, c.vertex_origin));
        pb.inc(1);
    }
    pb.finish_and_clear();
    let totals = ReduceStats::total(algo, &stats);
    if let Some(out) = &a.output {
        // The survivors keep their original coordinates, renumbered in original order.
        let parts = parts.iter().map(|(t, origin)| (t, &origin[..]));
        let m = TriMesh::reassemble(vertex_count, positions, parts).ok_or_else(|| {
            CliError::Failure(format!(
                "{}: inconsistent mesh after validation",
                a.input.display()
            ))
        })?;
        meshio::write(out, &m, ui)?;
    }
    let report = ReduceReport {
        file: a.input.display().to_string(),
        output: a.output.as_deref().map(|p: &Path| p.display().to_string()),
        seed: a.seed,
        component_count: stats.len(),
        dropped_vertices,
        welded_vertices,
        totals,
        components: stats,
        seconds_read,
        seconds_build,
    };
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        outln!("{} ({}):", report.file, algo.name());
        print_table(&report.components, &report.totals, 20);
        if let Some(o) = &report.output {
            outln!("wrote {o}");
        }
    }
    if report.totals.irreducible == Some(false) {
        let bad: Vec<String> = report
            .components
            .iter()
            .enumerate()
            .filter(|(_, s)| s.irreducible == Some(false))
            .map(|(i, _)| i.to_string())
            .collect();
        return Err(CliError::Failure(format!(
            "{}: output of component(s) {} still has a contractible edge (naive link test)",
            report.file,
            bad.join(", ")
        )));
    }
    Ok(())
}
