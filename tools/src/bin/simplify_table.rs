//! The Pepko–Borisenko Table 1 comparison: simplifies the regenerated workloads (torus
//! 16,772 vertices / 33,544 faces, hyperboloid 56,288 / 111,140 and 111,332) with both
//! modes and prints a Markdown table: vertices and faces before and after, contractions,
//! discs removed, short edges left by reason (link condition / non-disc / fold-over) and
//! the median time of 5 runs.
//!
//! `cargo run --release -p contractible-tools --bin simplify_table` prints rows at ε = 1 %
//! and 3 % of the bounding-box diagonal and at the ε (found by bisection on the nested mode) whose output
//! has the paper's vertex count (torus 4,985, hyperboloid 18,106; the paper does not
//! state its ε).

use std::time::Instant;

use contractible::gen::{isosurface, paper_hyperboloid, paper_torus, Tessellation};
use contractible::simplify::{bbox_diagonal, simplify, Mode, Options, Simplified};
use contractible::TriMesh;

fn run(mesh: &TriMesh, mode: Mode, eps: f64) -> Simplified {
    let opts = Options {
        mode,
        ..Options::new(eps)
    };
    simplify(mesh, &opts).expect("a valid surface")
}

/// The median wall time of 5 runs, in seconds.
fn median_time(mesh: &TriMesh, mode: Mode, eps: f64) -> f64 {
    let mut t: Vec<f64> = (0..5)
        .map(|_| {
            let start = Instant::now();
            run(mesh, mode, eps);
            start.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[2]
}

/// The ε whose nested output has about `target` vertices (bisection on log ε).
fn matching_eps(mesh: &TriMesh, diag: f64, target: usize) -> f64 {
    let (mut lo, mut hi) = (1e-5 * diag, 0.1 * diag);
    for _ in 0..30 {
        let mid = (lo * hi).sqrt();
        if run(mesh, Mode::Nested, mid).stats.vertices_out > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo * hi).sqrt()
}

fn main() {
    println!("| input | tessellation | ε / diagonal | mode | V before | F before | V after | F after | contracted | discs (vertices inside) | short edges left (link / non-disc / fold-over) | passes | median s |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for tess in [Tessellation::BodyCentred, Tessellation::SixTetrahedra] {
        for (name, params, paper_v) in [
            ("torus", paper_torus(tess), 4_985),
            ("hyperboloid", paper_hyperboloid(tess), 18_106),
        ] {
            let mesh = isosurface(&params).expect("the preset is valid");
            let diag = bbox_diagonal(mesh.positions.as_deref().unwrap_or(&[]).iter().copied());
            let matched = matching_eps(&mesh, diag, paper_v);
            for (label, eps) in [
                (format!("{:.5} (paper's V)", matched / diag), matched),
                ("0.01".to_string(), 0.01 * diag),
                ("0.03".to_string(), 0.03 * diag),
            ] {
                for mode in [Mode::Naive, Mode::Nested] {
                    let s = run(&mesh, mode, eps).stats;
                    let t = median_time(&mesh, mode, eps);
                    println!(
                        "| {name} | {tess:?} | {label} | {mode:?} | {} | {} | {} | {} | {} | {} ({}) | {} / {} / {} | {} | {t:.3} |",
                        s.vertices_in,
                        s.faces_in,
                        s.vertices_out,
                        s.faces_out,
                        s.edges_contracted,
                        s.discs_removed,
                        s.vertices_removed_inside,
                        s.remaining.link_condition,
                        s.remaining.non_disc,
                        s.remaining.foldover,
                        s.passes,
                    );
                }
            }
        }
    }
}
