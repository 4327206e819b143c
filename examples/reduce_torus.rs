//! Build a triangulation from a face list, contract an edge, undo it, then reduce the
//! surface to an irreducible triangulation with the RS algorithm.
//!
//! Run with `cargo run --release --example reduce_torus`.

use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::irreducible::{reduce, Algorithm, Options};
use contractible::{History, Triangulation, VertexId};

fn main() {
    // The boundary of the octahedron, from a plain face list (vertex ids 0..6).
    let faces = [
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    let mut t = Triangulation::from_faces(6, &faces).expect("a closed surface");
    println!(
        "octahedron: V={} E={} F={} χ={}",
        t.vertex_count(),
        t.edge_count(),
        t.face_count(),
        t.euler_characteristic()
    );

    // Contract the edge [0, 2] (it satisfies the link condition), then undo it.
    let before = t.clone();
    let mut history = History::new();
    t.contract(VertexId(0), VertexId(2), &mut history)
        .expect("[0, 2] is an edge that passes the link condition");
    println!(
        "after contracting [0, 2]: V={} F={}",
        t.vertex_count(),
        t.face_count()
    );
    history.undo_all(&mut t);
    assert_eq!(t, before);
    println!("undone: back to V={}", t.vertex_count());

    // A random genus-2 surface with 5,000 faces, reduced by RS.
    let surface = random(&RandomParams {
        surface: SurfaceKind::Orientable(2),
        min_faces: 5_000,
        flip_percent: 30,
        seed: 7,
    })
    .expect("a random surface within the limits");
    let r = reduce(surface, Algorithm::Rs, &Options::default());
    println!(
        "genus 2: {} → {} vertices in {} contractions, ℓ = {}, irreducible: {}",
        r.stats.vertices_in,
        r.stats.vertices_out,
        r.stats.contractions,
        r.stats.link_tests,
        r.tri.is_irreducible_naive()
    );
    // The history replays back to the input exactly.
    assert_eq!(r.expand().vertex_count(), r.stats.vertices_in);
}
