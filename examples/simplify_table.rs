//! Simplifies the regenerated Table 1 workloads (Pepko–Borisenko) with both modes and
//! prints a Markdown table: vertices and faces before and after, contractions, discs
//! removed, skipped edges and time. `cargo run --release --example simplify_table [eps_rel]`
//! (ε as a fraction of the bounding-box diagonal, default 0.01).

use contractible::gen::{isosurface, paper_hyperboloid, paper_torus, Tessellation};
use contractible::simplify::{bbox_diagonal, simplify, Mode, Options};

fn main() {
    let rel: f64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(0.01);
    println!("| input | tessellation | mode | V before | F before | V after | F after | contracted | discs | skipped (link / non-disc / fold-over) | seconds |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for tess in [Tessellation::BodyCentred, Tessellation::SixTetrahedra] {
        for (name, params) in [
            ("torus", paper_torus(tess)),
            ("hyperboloid", paper_hyperboloid(tess)),
        ] {
            let mesh = isosurface(&params).expect("the preset is valid");
            let diag = bbox_diagonal(mesh.positions.as_deref().unwrap_or(&[]).iter().copied());
            for mode in [Mode::Naive, Mode::Nested] {
                let opts = Options {
                    mode,
                    ..Options::new(rel * diag)
                };
                let out = simplify(&mesh, &opts).expect("a valid surface");
                let s = &out.stats;
                println!(
                    "| {name} | {tess:?} | {mode:?} | {} | {} | {} | {} | {} | {} | {} / {} / {} | {:.3} |",
                    s.vertices_before,
                    s.faces_before,
                    s.vertices_after,
                    s.faces_after,
                    s.edges_contracted,
                    s.discs_removed,
                    s.remaining.link_condition,
                    s.remaining.non_disc,
                    s.remaining.foldover,
                    s.seconds
                );
            }
        }
    }
}
