//! The simplifier's executable specification: runtime checks under `debug_assertions`
//! or the `invariants` feature ([`crate::spec::ENABLED`]), each re-deriving its statement
//! from the triangulation without the algorithm's bookkeeping.
//!
//! | statement | claim | check |
//! |---|---|---|
//! | D1 | a region the nested mode removes is a closed disc bounded by the 3-cycle `p q x`, with no boundary loop inside | [`disc`], before every removal |
//! | D2 | after every pass the component is a valid closed triangulation of the type it started with, with the same number of boundary loops | [`pass_end`] |
//! | D3 | at the end, every edge shorter than ε has a reason not to be processed | [`unaccounted`], in the final sweep |
//!
//! D1 is the guarantee the paper lacks (its side heuristics remove a side without
//! checking that it is a disc); the tests below show each check failing on a corrupted
//! input.

use super::state::Simplifier;
use crate::core::SurfaceType;
use crate::core::{FaceId, VertexId};
pub(super) use crate::spec::ENABLED;

/// D1: `region` is a closed disc whose boundary is exactly the cycle `[p, q, x]`: every
/// edge of its faces is in two of them except the three cycle edges (in one each),
/// V − E + F = 1, and no vertex but possibly `x` is a cone apex. O(|region| log |region|).
///
/// The faces are then connected through shared edges, so that is not checked apart: on a
/// surface, the edges in exactly one face of an edge-connected set of faces meet every
/// vertex an even number of times (each arc of a vertex's fan has two end edges), and a
/// proper subset of a 3-cycle's edges does not. So one edge-connected part of the region
/// holds the three cycle edges and any other part has no such edge at all: it would be a
/// closed surface inside the component, that is the whole (connected) component, which
/// has no edge in one face of it.
pub(super) fn disc(sim: &Simplifier<'_>, cycle: [VertexId; 3], region: &[FaceId]) {
    if !ENABLED {
        return;
    }
    let fail = |why: String| -> ! {
        panic!(
            "specification violated: D1 (disc removal) on the cycle {:?}: {why}",
            cycle
        )
    };
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(3 * region.len());
    let mut verts: Vec<u32> = Vec::with_capacity(3 * region.len());
    for &f in region {
        if !sim.tri.is_face(f) {
            fail(format!("face {} is not live", f.0));
        }
        let vs = sim.tri.face_vertices(f);
        for k in 0..3 {
            let (a, b) = (vs[k].0, vs[(k + 1) % 3].0);
            edges.push((a.min(b), a.max(b)));
            verts.push(vs[k].0);
        }
    }
    edges.sort_unstable();
    verts.sort_unstable();
    verts.dedup();
    let mut boundary = Vec::new();
    let mut distinct = 0usize;
    let mut i = 0;
    while i < edges.len() {
        let mut j = i;
        while j < edges.len() && edges[j] == edges[i] {
            j += 1;
        }
        distinct += 1;
        match j - i {
            1 => boundary.push(edges[i]),
            2 => {}
            n => fail(format!("edge {:?} is in {n} faces of the region", edges[i])),
        }
        i = j;
    }
    let mut expected: Vec<(u32, u32)> = [(0, 1), (1, 2), (2, 0)]
        .iter()
        .map(|&(s, t)| {
            let (a, b) = (cycle[s].0, cycle[t].0);
            (a.min(b), a.max(b))
        })
        .collect();
    expected.sort_unstable();
    boundary.sort_unstable();
    if boundary != expected {
        fail(format!("the boundary is {boundary:?}"));
    }
    let chi = verts.len() as i64 - distinct as i64 + region.len() as i64;
    if chi != 1 {
        fail(format!("Euler characteristic {chi}"));
    }
    if let Some(&w) = verts
        .iter()
        .find(|&&w| w != cycle[2].0 && sim.is_virtual(VertexId(w)))
    {
        fail(format!("the boundary loop of cone apex {w} is inside"));
    }
}

/// D2: the component is a valid triangulation (every invariant of
/// [`crate::Triangulation::validate`]) of the type it had at the start, and still has
/// one live cone apex per boundary loop. O(F).
pub(super) fn pass_end(sim: &Simplifier<'_>) {
    if !ENABLED {
        return;
    }
    if let Err(e) = sim.tri.validate() {
        panic!("specification violated: D2 (surface kept): invalid triangulation: {e}");
    }
    let now = SurfaceType::of(&sim.tri);
    if Some(now) != sim.surface {
        panic!(
            "specification violated: D2 (surface kept): {:?} became {:?}",
            sim.surface, now
        );
    }
    let apexes = (sim.first_virtual as usize..sim.tri.vertex_capacity())
        .filter(|&w| sim.tri.is_vertex(VertexId(w as u32)))
        .count();
    if apexes != sim.loop_count() {
        panic!(
            "specification violated: D2 (surface kept): {apexes} cone apexes for {} boundary loops",
            sim.loop_count()
        );
    }
}

/// D3: the short edge `[p, q]` left at the end could still be processed (so the last
/// pass missed it). Panics when the checks are on; otherwise the caller counts it in
/// `remaining.frozen`, which the documentation promises is 0.
pub(super) fn unaccounted(_sim: &Simplifier<'_>, p: VertexId, q: VertexId) {
    if !ENABLED {
        return;
    }
    panic!(
        "specification violated: D3 (short edges accounted): [{p}, {q}] could still be processed"
    );
}

/// Corrupted-state tests of D1–D3, compiled only where the checks are (elsewhere every
/// check returns at once and nothing would be tested).
#[cfg(all(test, any(debug_assertions, feature = "invariants")))]
mod tests {
    use super::*;
    use crate::simplify::{state::Simplifier, Options};
    use crate::spec::testing::assert_fails;
    use crate::{gen, ConedSurfaces};

    fn simplifier<'o>(mesh: &crate::TriMesh, opts: &'o Options) -> Simplifier<'o> {
        let mut s = ConedSurfaces::from_mesh(mesh).expect("a surface");
        let c = s.components.remove(0);
        let n = c.tri.vertex_capacity();
        Simplifier::new(c, &vec![[0.0; 3]; n], opts)
    }

    #[test]
    fn d1_accepts_a_disc_and_fails_on_a_side_with_genus() {
        let opts = Options::new(1.0);
        let mesh = gen::torus7();
        let sim = simplifier(&mesh, &opts);
        let f0 = FaceId(0);
        let cycle = sim.tri.face_vertices(f0);
        // One face is a disc bounded by its own 3-cycle.
        disc(&sim, cycle, &[f0]);
        // Its complement has the same boundary but carries the torus's handle (χ = -1):
        // exactly the side the paper's heuristics could pick.
        let rest: Vec<FaceId> = sim.tri.faces().filter(|&f| f != f0).collect();
        assert_fails("D1", || disc(&sim, cycle, &rest));
        // Two faces sharing an edge: a disc, but bounded by a 4-cycle.
        let g = sim.tri.face_neighbours(f0)[0];
        assert_fails("D1", || disc(&sim, cycle, &[f0, g]));
    }

    #[test]
    fn d1_fails_on_a_boundary_loop_inside() {
        // A disc of two triangles closed by one cone: the region of all faces but a
        // real one is a disc bounded by that face's cycle, with the apex inside.
        let mesh = crate::TriMesh::combinatorial(4, vec![[0, 1, 2], [0, 2, 3]]);
        let opts = Options::new(1.0);
        let sim = simplifier(&mesh, &opts);
        let apex = VertexId(sim.first_virtual);
        // The region holding the apex strictly inside: all faces but a real one.
        let real = sim
            .tri
            .faces()
            .find(|&f| !sim.tri.face_vertices(f).contains(&apex))
            .expect("a real face");
        let rest: Vec<FaceId> = sim.tri.faces().filter(|&f| f != real).collect();
        let cycle = sim.tri.face_vertices(real);
        assert_fails("D1", || disc(&sim, cycle, &rest));
    }

    #[test]
    fn d2_fails_on_a_changed_surface_and_d3_always() {
        let opts = Options::new(1.0);
        let mesh = gen::octahedron();
        let mut sim = simplifier(&mesh, &opts);
        pass_end(&sim);
        sim.surface = SurfaceType::new(0, true);
        assert_fails("D2", || pass_end(&sim));
        assert_fails("D3", || unaccounted(&sim, VertexId(0), VertexId(1)));
    }
}
