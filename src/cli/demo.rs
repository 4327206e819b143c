//! `contractible demo`: the main job on built-in inputs.

use std::path::Path;

use contractible::gen::{self, RandomParams, SurfaceKind};
use contractible::irreducible::Algorithm;
use contractible::quad;
use contractible::{Surfaces, TriMesh};
use serde::Serialize;

use super::args::DemoArgs;
use super::info::Report;
use super::progress::spinner;
use super::quad::{quad_all, QuadStats};
use super::reduce::{reduce_all, ReduceStats};
use super::{print_json, CliError, Ui};

#[derive(Serialize)]
struct DemoInput {
    name: String,
    info: Report,
    runs: Vec<ReduceStats>,
    /// Tri-quad conversions of the same input, one per algorithm.
    quads: Vec<QuadStats>,
}

#[derive(Serialize)]
struct DemoReport {
    seed: u64,
    inputs: Vec<DemoInput>,
    /// Every reduction passed the naive link test (no contractible edge) and kept χ and
    /// orientability, and every tri-quad conversion passed its independent check.
    verified: bool,
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
            gen::paper_family('B', 7),
        ),
    ];
    pb.finish_and_clear();
    v
}

pub fn run(a: &DemoArgs, ui: Ui) -> Result<(), CliError> {
    let mut report = DemoReport {
        seed: a.seed,
        inputs: Vec::new(),
        verified: true,
    };
    for (name, mesh) in inputs(a.seed, ui) {
        let surfaces = Surfaces::from_mesh(&mesh)
            .map_err(|e| CliError::Failure(format!("built-in input {name}: {e}")))?;
        let info = Report::of(Path::new(&name), &surfaces, 0.0, 0.0);
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
            let algo: Algorithm = algo.into();
            let (reductions, stats) = reduce_all(&surfaces, algo, a.seed, true, ui);
            let s = ReduceStats::total(algo, &stats);
            let same_topology = surfaces.components.iter().zip(&reductions).all(|(c, r)| {
                c.tri.euler_characteristic() == r.tri.euler_characteristic()
                    && c.tri.is_orientable() == r.tri.is_orientable()
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
            quad::Algorithm::Ps,
            quad::Algorithm::Sg,
            quad::Algorithm::Matching,
        ] {
            let s = QuadStats::total(algo, &quad_all(&surfaces, algo, a.seed, ui));
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
            quads,
        });
    }
    if ui.json {
        print_json(&report)?;
    } else if ui.human() && report.verified {
        outln!(
            "all reductions verified irreducible by the naive link test (χ and orientability \
             kept); all tri-quad pairings perfect, on the input's vertices and surface"
        );
    }
    if !report.verified {
        return Err(CliError::Failure(
            "an output failed verification (reducible, topology changed, or an imperfect or\
             invalid pairing)"
                .into(),
        ));
    }
    Ok(())
}
