//! `contractible reduce IN [-o OUT]`: irreducible triangulations per component.

use std::time::Instant;

use contractible::irreducible::{self, Algorithm, Options, Reduction};
use contractible::{SurfaceType, Surfaces, TriMesh};
use serde::Serialize;

use super::args::ReduceArgs;
use super::progress::{bar, StageBar};
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
    /// Whether the independent check found no contractible edge (`null`: not checked).
    pub irreducible: Option<bool>,
    /// How the output was checked: "naive" (the link condition by its definition on
    /// every edge) or "marked" (the marked-neighbour test on every edge, for large
    /// outputs); "naive+marked" in the totals when both were used; absent when not
    /// checked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verified_by: Option<&'static str>,
}

/// Outputs with at most this many edges are checked by the link condition's definition
/// (O(Σ d_u·d_v)); larger ones by the marked-neighbour test (O(Σ d_u + d_v)), which is
/// linear where the definition is quadratic in the degrees.
pub const NAIVE_MAX_EDGES: usize = 100_000;

/// The independent check that `tri` is irreducible (no edge passes the link
/// condition), on `tri` alone (nothing the algorithm kept): returns the verdict and the
/// method ([`NAIVE_MAX_EDGES`]).
pub fn check_irreducible(tri: &contractible::Triangulation) -> (bool, &'static str) {
    check_irreducible_with(tri, NAIVE_MAX_EDGES)
}

/// [`check_irreducible`] with the size limit of the naive check as a parameter.
fn check_irreducible_with(
    tri: &contractible::Triangulation,
    naive_max_edges: usize,
) -> (bool, &'static str) {
    if tri.edge_count() <= naive_max_edges {
        (tri.is_irreducible_naive(), "naive")
    } else {
        (tri.is_irreducible(), "marked")
    }
}

impl ReduceStats {
    /// The counters of `r`, the reduction of a surface of type `input` (not yet checked).
    fn of(r: &Reduction, input: SurfaceType) -> Self {
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
            irreducible: None,
            verified_by: None,
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
            verified_by: if irreducible.is_none() {
                None
            } else if parts.iter().all(|p| p.verified_by == Some("naive")) {
                Some("naive")
            } else if parts.iter().all(|p| p.verified_by == Some("marked")) {
                Some("marked")
            } else {
                Some("naive+marked")
            },
        }
    }
}

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
}

/// Reduces (a copy of) every component of `surfaces` with `algo`, with a bar that
/// follows the algorithm inside each component; then, when `verify`, checks every output
/// with [`check_irreducible`] as a step of its own. Returns the reductions and their
/// counters.
pub fn reduce_all(
    surfaces: &Surfaces,
    algo: Algorithm,
    seed: u64,
    verify: bool,
    ui: Ui,
) -> (Vec<Reduction>, Vec<ReduceStats>) {
    let n = surfaces.components.len();
    let options = Options {
        seed,
        count_retests: true,
    };
    let mut bar = StageBar::new(ui, component_prefix(VERB, algo.name(), 0, n));
    let mut reductions = Vec::with_capacity(n);
    let mut stats = Vec::with_capacity(n);
    for (i, c) in surfaces.components.iter().enumerate() {
        bar.set_prefix(component_prefix(VERB, algo.name(), i, n));
        let input = SurfaceType::of(&c.tri);
        let r =
            irreducible::reduce_observed(c.tri.clone(), algo, &options, &mut |p| bar.observe(p));
        stats.push(ReduceStats::of(&r, input));
        reductions.push(r);
    }
    bar.finish();
    if verify {
        let tris: Vec<&contractible::Triangulation> = reductions.iter().map(|r| &r.tri).collect();
        verify_all(&tris, &mut stats, ui);
    }
    (reductions, stats)
}

/// What the bar of the reductions says.
const VERB: &str = "reducing";

/// `VERB (ALGO)`, plus `, component i/n` when there are several.
pub fn component_prefix(verb: &str, algo: &str, i: usize, n: usize) -> String {
    if n > 1 {
        format!("{verb} ({algo}), component {}/{n}", i + 1)
    } else {
        format!("{verb} ({algo})")
    }
}

/// The verification step: checks every output with [`check_irreducible`] (a bar over
/// the components, announced as its own step), fills `irreducible` and `verified_by`,
/// and returns the seconds taken.
fn verify_all(tris: &[&contractible::Triangulation], stats: &mut [ReduceStats], ui: Ui) -> f64 {
    let t = Instant::now();
    let pb = bar(
        ui,
        tris.len() as u64,
        "verifying: no edge passes the link condition",
    );
    for (tri, s) in tris.iter().zip(stats.iter_mut()) {
        let (ok, how) = check_irreducible(tri);
        s.irreducible = Some(ok);
        s.verified_by = Some(how);
        pb.inc(1);
    }
    pb.finish_and_clear();
    t.elapsed().as_secs_f64()
}

/// One line with the time of every step that ran.
fn timings(r: &ReduceReport) -> String {
    let mut steps = vec![
        format!("read {:.3} s", r.seconds_read),
        format!("check input {:.3} s", r.seconds_build),
        format!("{} {:.3} s", r.totals.algo, r.totals.seconds),
    ];
    if let (Some(t), Some(how)) = (r.seconds_verify, r.totals.verified_by) {
        steps.push(format!("verify {t:.3} s ({how} link test on every edge)"));
    }
    if let Some(t) = r.seconds_write {
        steps.push(format!("write {t:.3} s"));
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
    let mut bar = StageBar::new(ui, component_prefix(VERB, algo.name(), 0, n));
    let mut parts = Vec::with_capacity(n);
    let mut stats = Vec::with_capacity(n);
    for (i, c) in surfaces.components.into_iter().enumerate() {
        bar.set_prefix(component_prefix(VERB, algo.name(), i, n));
        let input = SurfaceType::of(&c.tri);
        let r = irreducible::reduce_observed(c.tri, algo, &options, &mut |p| bar.observe(p));
        stats.push(ReduceStats::of(&r, input));
        parts.push((r.tri, c.vertex_origin));
    }
    bar.finish();
    let seconds_verify = (!a.no_verify).then(|| {
        let tris: Vec<&contractible::Triangulation> = parts.iter().map(|(t, _)| t).collect();
        verify_all(&tris, &mut stats, ui)
    });
    let totals = ReduceStats::total(algo, &stats);
    let mut seconds_write = None;
    // A reducible output is an internal error: reported below, and not written.
    if let (Some(out), false) = (&output, totals.irreducible == Some(false)) {
        // The survivors keep their original coordinates, renumbered in original order.
        let parts = parts.iter().map(|(t, origin)| (t, &origin[..]));
        let m = TriMesh::reassemble(vertex_count, positions, parts).ok_or_else(|| {
            CliError::Failure(format!(
                "{}: inconsistent mesh after validation",
                a.input.display()
            ))
        })?;
        seconds_write = Some(meshio::write(out, &m, ui)?);
    }
    let report = ReduceReport {
        file: a.input.display().to_string(),
        output: output.as_ref().map(meshio::Output::display),
        seed: a.seed,
        components: stats.len(),
        dropped_vertices,
        welded_vertices,
        totals,
        component_list: stats,
        seconds_read,
        seconds_build,
        seconds_verify,
        seconds_write,
    };
    Ok(report)
}

pub fn run(a: &ReduceArgs, ui: Ui) -> Result<(), CliError> {
    let report = compute(a, ui)?;
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        outln!("{} ({}):", report.file, report.totals.algo);
        print_table(&report.component_list, &report.totals, 20);
        outln!("{}", timings(&report));
        if let (Some(o), Some(_)) = (&report.output, report.seconds_write) {
            outln!("wrote {o}");
        }
    }
    failure(&report).map_or(Ok(()), Err)
}

/// The error of a report whose output failed the independent irreducibility check.
pub fn failure(report: &ReduceReport) -> Option<CliError> {
    if report.totals.irreducible != Some(false) {
        return None;
    }
    let bad: Vec<String> = report
        .component_list
        .iter()
        .enumerate()
        .filter(|(_, s)| s.irreducible == Some(false))
        .map(|(i, _)| i.to_string())
        .collect();
    Some(CliError::Failure(format!(
        "{}: output of component(s) {} still has a contractible edge (independent link test); nothing written",
        report.file,
        bad.join(", ")
    )))
}

#[cfg(test)]
mod tests {
    use super::*;
    use contractible::gen;

    // Both checks, on irreducible and on reducible surfaces: they agree, and each can
    // say "no" (the marked one is what large outputs get).
    #[test]
    fn the_naive_and_the_marked_checks_agree_and_can_fail() {
        let cases = [
            ("tetrahedron", gen::tetrahedron(), true),
            ("torus7", gen::torus7(), true),
            ("rp2", gen::projective_plane6(), true),
            ("octahedron", gen::octahedron(), false),
            ("icosahedron", gen::icosahedron(), false),
        ];
        for (name, mesh, irreducible) in cases {
            let s = Surfaces::from_mesh(&mesh).expect("a surface");
            let t = &s.components[0].tri;
            assert_eq!(
                check_irreducible_with(t, usize::MAX),
                (irreducible, "naive"),
                "{name}"
            );
            assert_eq!(
                check_irreducible_with(t, 0),
                (irreducible, "marked"),
                "{name}"
            );
        }
    }
}
