//! `contractible demo`: the main job on built-in inputs.

use std::path::Path;

use contractible::gen::{self, Implicit, IsoParams, RandomParams, SurfaceKind, Tessellation};
use contractible::irreducible::Algorithm;
use contractible::quad;
use contractible::simplify::{bbox_diagonal, Mode, Stats};
use contractible::task::{QuadStats, ReduceStats};
use contractible::{ConedSurfaces, Eps, SimplifyOptions, Surfaces, TriMesh};
use serde::Serialize;

use super::args::DemoArgs;
use super::info::Report;
use super::progress::spinner;
use super::quad::quadrangulate_with_bars;
use super::reduce::reduce_with_bars;
use super::simplify::{fmt_len, simplify_with_bars};
use super::{print_json, CliError, Ui};

#[derive(Serialize)]
struct DemoInput {
    name: String,
    info: Report,
    runs: Vec<ReduceStats>,
    /// Tri-quad conversions of the same input, one per algorithm (`quads` is the number
    /// of quads in every other report, hence this name).
    quad_runs: Vec<QuadStats>,
}

/// One simplification of a [`DemoIsosurface`].
#[derive(Serialize)]
struct DemoSimplifyRun {
    mode: &'static str,
    #[serde(flatten)]
    stats: Stats,
    /// The output rebuilt from its faces has the input's components and topology.
    verified: bool,
}

/// A generated marching-tetrahedra surface simplified with both modes.
#[derive(Serialize)]
struct DemoIsosurface {
    name: String,
    info: Report,
    eps_rel: f64,
    eps: f64,
    runs: Vec<DemoSimplifyRun>,
}

#[derive(Serialize)]
struct DemoReport {
    seed: u64,
    inputs: Vec<DemoInput>,
    /// Short-edge simplifications of generated isosurfaces (both modes).
    simplified: Vec<DemoIsosurface>,
    /// Every reduction passed the naive link test (no contractible edge) and kept χ and
    /// orientability, every tri-quad conversion passed its independent check, and every
    /// simplification kept each component's topology (checked on the output rebuilt from
    /// its faces) with the nested mode contracting at least as many edges as the naive
    /// one.
    verified: bool,
}

/// ε of the demo's simplifications, as a fraction of the bounding-box diagonal.
const DEMO_EPS_REL: f64 = 0.01;

/// The demo's isosurfaces: a closed genus-2 surface and the open two-sheeted
/// hyperboloid (two discs), marching tetrahedra on the body-centred tessellation.
fn isosurfaces(ui: Ui) -> Result<Vec<(String, TriMesh)>, CliError> {
    let pb = spinner(ui, "generating the demo isosurfaces");
    let cases = [
        (
            "isosurface genus 2 (bcc, resolution 64)",
            Implicit::GenusG { g: 2 },
            64,
        ),
        (
            "isosurface two-sheeted hyperboloid, open (bcc, resolution 40)",
            Implicit::TwoSheetHyperboloid {
                c: 0.3,
                half_width: 1.2,
                half_height: 1.5,
            },
            40,
        ),
    ];
    let mut v = Vec::new();
    for (name, implicit, resolution) in cases {
        let params = IsoParams::new(implicit, Tessellation::BodyCentred, resolution);
        let mesh = gen::isosurface(&params)
            .map_err(|e| CliError::Failure(format!("built-in input {name}: {e}")))?;
        v.push((name.to_string(), mesh));
    }
    pb.finish_and_clear();
    Ok(v)
}

/// Simplifies `mesh` with both modes at [`DEMO_EPS_REL`], checks each output, prints the
/// rows. Returns the entry and whether everything was verified.
fn simplify_demo(name: String, mesh: &TriMesh, ui: Ui) -> Result<(DemoIsosurface, bool), CliError> {
    let surfaces = ConedSurfaces::from_mesh(mesh)
        .map_err(|e| CliError::Failure(format!("built-in input {name}: {e}")))?;
    let info = Report::of_coned(Path::new(&name), &surfaces, None, None);
    drop(surfaces);
    let diagonal = bbox_diagonal(mesh.positions.iter().flatten().copied());
    let eps = DEMO_EPS_REL * diagonal;
    if ui.human() {
        info.print_human(5);
        outln!(
            "  simplify at ε = {} (1 % of the bounding-box diagonal)",
            fmt_len(eps)
        );
        outln!(
            "  {:<9} {:>7} {:>7} {:>10} {:>6} {:>7} {:>7} {:>6} {:>9}",
            "mode",
            "V out",
            "F out",
            "contracted",
            "discs",
            "inside",
            "short",
            "passes",
            "seconds"
        );
    }
    let mut runs: Vec<DemoSimplifyRun> = Vec::new();
    for mode in [Mode::Naive, Mode::Nested] {
        let options = SimplifyOptions {
            eps: Eps::Absolute(eps),
            mode,
            ..SimplifyOptions::default()
        };
        // The library checks every output (rebuilt from its faces: the input's
        // components and topology) and reports a failed check as an error.
        let out = simplify_with_bars(mesh, options, ui);
        let (s, kept) = match out {
            Ok(out) => (out.stats, Ok(())),
            Err(e @ contractible::Error::Unverified { .. }) => {
                ui.warn(&format!("{name} ({mode}): {e}"));
                (Stats::default(), Err(()))
            }
            Err(e) => return Err(CliError::Failure(format!("built-in input {name}: {e}"))),
        };
        if ui.human() {
            outln!(
                "  {:<9} {:>7} {:>7} {:>10} {:>6} {:>7} {:>7} {:>6} {:>9.4}{}",
                mode.name(),
                s.vertices_out,
                s.faces_out,
                s.edges_contracted,
                s.discs_removed,
                s.vertices_removed_inside,
                s.short_edges_remaining,
                s.passes,
                s.seconds,
                if kept.is_ok() {
                    ""
                } else {
                    "  FAILED VERIFICATION"
                }
            );
        }
        runs.push(DemoSimplifyRun {
            mode: mode.name(),
            stats: s,
            verified: kept.is_ok(),
        });
    }
    // The nested mode runs the naive passes first, so it contracts at least as much.
    let monotone = match runs.as_slice() {
        [naive, nested] => nested.stats.edges_contracted >= naive.stats.edges_contracted,
        _ => false,
    };
    if !monotone {
        ui.warn(&format!(
            "{name}: the nested mode contracted fewer edges than the naive one"
        ));
    }
    let ok = monotone && runs.iter().all(|r| r.verified);
    if ui.human() {
        outln!();
    }
    Ok((
        DemoIsosurface {
            name,
            info,
            eps_rel: DEMO_EPS_REL,
            eps,
            runs,
        },
        ok,
    ))
}

/// The built-in inputs: a random genus-3 surface (~20k faces), a random non-orientable
/// surface of Euler genus 3 (~10k faces), and the paper's brick B7 (genus 0, 3,844
/// cavities, ~32k faces).
fn inputs(seed: u64, ui: Ui) -> Vec<(String, TriMesh)> {
    let pb = spinner(ui, "generating the demo surfaces");
    let random = |surface, min_faces| {
        gen::random(&RandomParams {
            surface,
            min_faces,
            flip_percent: 30,
            seed,
        })
        .expect("a random surface within the limits")
        .to_mesh()
    };
    let v = vec![
        (
            format!("random genus 3, 20k faces, seed {seed}"),
            random(SurfaceKind::Orientable(3), 20_000),
        ),
        (
            format!("random non-orientable genus 3, 10k faces, seed {seed}"),
            random(SurfaceKind::NonOrientable(3), 10_000),
        ),
        (
            "paper brick B7 (3,844 cavities)".to_string(),
            gen::paper_family('B', 7).expect("valid brick parameters"),
        ),
    ];
    pb.finish_and_clear();
    v
}

pub fn run(a: &DemoArgs, ui: Ui) -> Result<(), CliError> {
    let mut report = DemoReport {
        seed: a.seed,
        inputs: Vec::new(),
        simplified: Vec::new(),
        verified: true,
    };
    for (name, mesh) in inputs(a.seed, ui) {
        let surfaces = Surfaces::from_mesh(&mesh)
            .map_err(|e| CliError::Failure(format!("built-in input {name}: {e}")))?;
        let info = Report::of(Path::new(&name), &surfaces, None, None);
        if ui.human() {
            info.print_human(5);
            outln!(
                "  {:<9} {:>9} {:>6} {:>12} {:>7} {:>10}",
                "algorithm",
                "ℓ",
                "ε",
                "contractions",
                "V out",
                "seconds"
            );
        }
        let mut runs = Vec::new();
        for &algo in &a.algos {
            let algo: Algorithm = algo;
            // The library checks every output by the naive link test and reports a
            // reducible one as an error.
            let r = reduce_with_bars(&mesh, algo, a.seed, false, false, false, ui)
                .map_err(|e| CliError::Failure(format!("built-in input {name}: {e}")))?;
            let s = r.totals;
            let same_topology = surfaces.components.iter().zip(&r.components).all(|(c, r)| {
                let t = &r.reduction.tri;
                c.tri.euler_characteristic() == t.euler_characteristic()
                    && c.tri.is_orientable() == t.is_orientable()
            });
            let ok = s.irreducible == Some(true) && same_topology;
            report.verified &= ok;
            if ui.human() {
                outln!(
                    "  {:<9} {:>9} {:>6} {:>12} {:>7} {:>10.4}{}",
                    algo.name(),
                    s.link_tests,
                    s.edges_tested_more_than_once,
                    s.contractions,
                    s.vertices_out,
                    s.seconds,
                    if ok { "" } else { "  FAILED VERIFICATION" }
                );
            }
            runs.push(s);
        }
        if ui.human() {
            outln!(
                "  {:<9} {:>9} {:>9} {:>10} {:>9} {:>10} {:>9}",
                "tri-quad",
                "quads",
                "% paired",
                "unpaired",
                "flips",
                "aug.paths",
                "seconds"
            );
        }
        let mut quads = Vec::new();
        for algo in [
            quad::Algorithm::Lrs,
            quad::Algorithm::PulliSegal,
            quad::Algorithm::SimpleGreedy,
            quad::Algorithm::Matching,
            quad::Algorithm::DiksStanczyk,
            quad::Algorithm::BiedlBoseDemaineLubiw,
        ] {
            let s = quadrangulate_with_bars(&mesh, algo, a.seed, false, ui)
                .map_err(|e| CliError::Failure(format!("built-in input {name}: {e}")))?
                .totals;
            report.verified &= s.verified;
            if ui.human() {
                outln!(
                    "  {:<9} {:>9} {:>9.3} {:>10} {:>9} {:>10} {:>9.4}{}",
                    algo.name(),
                    s.quads,
                    s.initial_paired_percent,
                    s.initial_unpaired,
                    s.flips,
                    s.augmenting_paths,
                    s.total_seconds,
                    if s.verified {
                        ""
                    } else {
                        "  FAILED VERIFICATION"
                    }
                );
            }
            quads.push(s);
        }
        if ui.human() {
            outln!();
        }
        report.inputs.push(DemoInput {
            name,
            info,
            runs,
            quad_runs: quads,
        });
    }
    for (name, mesh) in isosurfaces(ui)? {
        let (entry, ok) = simplify_demo(name, &mesh, ui)?;
        report.verified &= ok;
        report.simplified.push(entry);
    }
    if ui.json {
        print_json(&report)?;
    } else if ui.human() && report.verified {
        outln!(
            "all reductions verified irreducible by the naive link test (χ and orientability \
             kept); all tri-quad pairings perfect, on the input's vertices and surface; all \
             simplifications kept every component's χ, orientability and boundary loops \
             (output rebuilt from its faces), nested contracting at least as many edges as \
             naive"
        );
    }
    if !report.verified {
        return Err(CliError::Failure(
            "an output failed verification (reducible, topology changed, an imperfect or \
             invalid pairing, or a simplification that changed the surface or contracted \
             less in the nested mode)"
                .into(),
        ));
    }
    Ok(())
}
