//! Runtime checks of Frink's reduction (tri-quad paper, Appendix A), called by the
//! engine of [`super`]. Every hook begins with `if !ENABLED { return }`: type-checked in
//! every build, deleted by the optimiser when [`ENABLED`] is false. A failure panics with
//! `specification violated: <statement> (<where>): …`.
//!
//! | statement | paper | hook |
//! |---|---|---|
//! | F1 the chosen reduced graph is cubic, loop-free, connected and bridgeless | App. A (Frink: one of `H1`, `H2` is) | `after_reduction` |
//! | F2 the lifted matching is perfect on the current graph | App. A, cases (i)–(iv) | `after_lift`, `at_end` |
//! | F3 (Diks–Stańczyk) the forest the decision reads spans `H' = H − {u, v}`, and the connectivity structure's own invariants hold | DS (errata T13), HDT Sec. 2 | `ds_forest` |
//! | F4 (Biedl–Bose–Demaine–Lubiw) the 2-edge-connectivity structure holds exactly the current graph's edges, and its own invariants hold | BBDL, HDT Sec. 3 | `bbdl_structure` |
//!
//! Cost: F1 checks that the two new edges are no loops (O(1)) always, and while the
//! reduced graph has at most [`SMALL_NODES`] nodes checks it in full by a method
//! independent of the strategies' DFS: each live edge removed in turn and connectivity
//! tested by a plain BFS (O(n²) for `n ≤ 64`). F2 checks the whole matching while the
//! graph has at most [`FULL_LIFT_NODES`] nodes, and otherwise the nodes whose mate the
//! lift changed plus the pair count (which, with the untouched nodes checked at the
//! previous step, is the same statement by induction); [`at_end`] checks the whole
//! matching once.

use super::graph::{Candidate, Cubic, Reduction, NONE};
use crate::dyngraph::TwoEdge;
use crate::spec::ENABLED;

/// Node count up to which F1 runs the independent edge-removal test.
pub(crate) const SMALL_NODES: usize = 64;
/// Node count up to which F2 checks the whole matching after every lift.
pub(crate) const FULL_LIFT_NODES: usize = 4096;

macro_rules! spec_fail {
    ($stmt:literal, $where:expr, $($fmt:tt)*) => {
        panic!(
            "specification violated: {} ({}): {}",
            $stmt,
            $where,
            format!($($fmt)*)
        )
    };
}

/// The structure of `g` is consistent: every slot of a live node holds an edge with that
/// node as an end, a loop twice, other edges once, and the far end is live.
fn structure(g: &Cubic) -> Result<(), String> {
    for x in 0..g.node_capacity() as u32 {
        if !g.is_alive(x) {
            continue;
        }
        for e in g.incident(x) {
            let [a, b] = g.ends(e);
            if a != x && b != x {
                return Err(format!("edge {e} = {a}{b} in the slots of node {x}"));
            }
            let w = g.other(e, x);
            if !g.is_alive(w) {
                return Err(format!("edge {e} at {x} leads to removed node {w}"));
            }
            let times = g.incident(x).iter().filter(|&&f| f == e).count();
            if times != if a == b { 2 } else { 1 } {
                return Err(format!("edge {e} {times} times at node {x}"));
            }
        }
    }
    Ok(())
}

/// Number of live nodes reached from `start` by a BFS that never uses edge `skip`.
fn reach(g: &Cubic, start: u32, skip: u32) -> usize {
    let mut seen = vec![false; g.node_capacity()];
    seen[start as usize] = true;
    let mut queue = vec![start];
    let mut head = 0;
    while head < queue.len() {
        let x = queue[head];
        head += 1;
        for e in g.incident(x) {
            let w = g.other(e, x);
            if e != skip && !seen[w as usize] {
                seen[w as usize] = true;
                queue.push(w);
            }
        }
    }
    queue.len()
}

/// Whether the live part of `g` is connected and bridgeless, by the definition: it is
/// connected, and stays connected with any one edge removed. O(n·m).
pub(crate) fn connected_bridgeless_by_definition(g: &Cubic) -> bool {
    let Some(start) = (0..g.node_capacity() as u32).find(|&x| g.is_alive(x)) else {
        return true;
    };
    if reach(g, start, NONE) != g.node_count() {
        return false;
    }
    (0..g.node_capacity() as u32)
        .filter(|&x| g.is_alive(x))
        .flat_map(|x| g.incident(x))
        .all(|e| {
            let [a, _] = g.ends(e);
            reach(g, a, e) == g.node_count()
        })
}

/// F1 after the reduction `r` was applied to `g`.
pub(crate) fn after_reduction(g: &Cubic, r: &Reduction) {
    if !ENABLED {
        return;
    }
    let at = format!("reduction at {}{}, {:?}", r.cand.u, r.cand.v, r.recon);
    for e in r.new {
        let [a, b] = g.ends(e);
        if a == b {
            spec_fail!("F1 (App. A)", at, "new edge {e} is a loop at {a}");
        }
    }
    if g.node_count() > SMALL_NODES {
        return;
    }
    if let Err(m) = structure(g) {
        spec_fail!("F1 (App. A)", at, "not a cubic multigraph: {m}");
    }
    if !connected_bridgeless_by_definition(g) {
        spec_fail!(
            "F1 (App. A)",
            at,
            "the reduced graph ({} nodes) is disconnected or has a bridge",
            g.node_count()
        );
    }
}

/// F3: after the five edges of the reduction `cand` of `g` (not yet applied) are deleted
/// from the Diks–Stańczyk strategy's connectivity structure, its forest (`is_tree`) is a
/// spanning forest of `H' = g − {u, v}`: every forest edge is an edge of `H'`, the forest
/// is acyclic, and it has one edge fewer than the nodes of `H'` per component of `H'`
/// (components counted by a union–find over the edges of `H'`, independent of the
/// structure); and `check` (the structure's own invariant check) passed. Up to
/// [`SMALL_NODES`] live nodes; O(n · α(n)).
pub(crate) fn ds_forest(
    g: &Cubic,
    cand: &Candidate,
    is_tree: impl Fn(u32) -> bool,
    check: impl FnOnce() -> Result<(), String>,
) {
    if !ENABLED || g.node_count() > SMALL_NODES {
        return;
    }
    let at = format!("reduction at {}{}", cand.u, cand.v);
    if let Err(m) = check() {
        spec_fail!("F3 (DS)", at, "the connectivity structure: {m}");
    }
    let removed = [cand.e, cand.a[0], cand.a[1], cand.b[0], cand.b[1]];
    let n = g.node_capacity();
    let mut parent: Vec<u32> = (0..n as u32).collect();
    fn find(p: &mut [u32], mut x: u32) -> u32 {
        while p[x as usize] != x {
            p[x as usize] = p[p[x as usize] as usize];
            x = p[x as usize];
        }
        x
    }
    let in_h = |x: u32| g.is_alive(x) && x != cand.u && x != cand.v;
    let mut edges_h = Vec::new();
    for x in (0..n as u32).filter(|&x| in_h(x)) {
        for e in g.incident(x) {
            let [a, b] = g.ends(e);
            if a == x && in_h(b) && !removed.contains(&e) {
                edges_h.push(e);
            }
        }
    }
    for e in (0..g.ends.len() as u32).filter(|&e| is_tree(e)) {
        if !edges_h.contains(&e) {
            spec_fail!("F3 (DS)", at, "forest edge {e} is not an edge of H'");
        }
    }
    let mut tree_edges = 0;
    for &e in edges_h.iter().filter(|&&e| is_tree(e)) {
        let [a, b] = g.ends(e);
        let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
        if ra == rb {
            spec_fail!("F3 (DS)", at, "forest edge {e} closes a cycle");
        }
        parent[ra as usize] = rb;
        tree_edges += 1;
    }
    let mut full: Vec<u32> = (0..n as u32).collect();
    for &e in &edges_h {
        let [a, b] = g.ends(e);
        let (ra, rb) = (find(&mut full, a), find(&mut full, b));
        full[ra as usize] = rb;
    }
    let nodes = (0..n as u32).filter(|&x| in_h(x)).count();
    let components = (0..n as u32)
        .filter(|&x| in_h(x) && find(&mut full, x) == x)
        .count();
    if tree_edges + components != nodes {
        spec_fail!(
            "F3 (DS)",
            at,
            "{tree_edges} forest edges for {nodes} nodes in {components} components: not spanning"
        );
    }
}

/// Whether `mate` is a perfect matching of the live part of `g` at the nodes `nodes`:
/// each has a live incident edge as mate, which is no loop and is the far end's mate.
fn matched_at(g: &Cubic, mate: &[u32], nodes: impl Iterator<Item = u32>) -> Result<(), String> {
    for x in nodes {
        if !g.is_alive(x) {
            continue;
        }
        let m = mate[x as usize];
        if m == NONE || !g.incident(x).contains(&m) {
            return Err(format!("node {x} has mate edge {m}, not one of its edges"));
        }
        let w = g.other(m, x);
        if w == x || mate[w as usize] != m {
            return Err(format!("edge {m} is the mate of {x} but not of {w}"));
        }
    }
    Ok(())
}

/// F2 after a lift: `pairs` matched edges, `changed` the nodes whose mate it set.
pub(crate) fn after_lift(g: &Cubic, mate: &[u32], pairs: usize, changed: &[u32], r: &Reduction) {
    if !ENABLED {
        return;
    }
    let at = format!("lift of the reduction at {}{}", r.cand.u, r.cand.v);
    if 2 * pairs != g.node_count() {
        spec_fail!(
            "F2 (App. A)",
            at,
            "{pairs} pairs on {} nodes",
            g.node_count()
        );
    }
    let result = if g.node_count() <= FULL_LIFT_NODES {
        matched_at(g, mate, 0..g.node_capacity() as u32)
    } else {
        matched_at(g, mate, changed.iter().copied())
    };
    if let Err(m) = result {
        spec_fail!("F2 (App. A)", at, "{m}");
    }
}

/// F2 on the final matching, in full.
pub(crate) fn at_end(g: &Cubic, mate: &[u32], pairs: usize) {
    if !ENABLED {
        return;
    }
    if 2 * pairs != g.node_count() {
        spec_fail!(
            "F2 (App. A)",
            "end",
            "{pairs} pairs on {} nodes",
            g.node_count()
        );
    }
    if let Err(m) = matched_at(g, mate, 0..g.node_capacity() as u32) {
        spec_fail!("F2 (App. A)", "end", "{m}");
    }
}

/// F4: after a reduction is applied, the Biedl–Bose–Demaine–Lubiw strategy's
/// 2-edge-connectivity structure `te` holds exactly the live edges of `g` with their
/// ends, and its own invariant check ([`TwoEdge::check`], O(n·m)) passes. Up to
/// [`SMALL_NODES`] live nodes.
pub(crate) fn bbdl_structure(g: &Cubic, te: &mut TwoEdge) {
    if !ENABLED || g.node_count() > SMALL_NODES {
        return;
    }
    let at = format!("{} live nodes", g.node_count());
    if let Err(m) = te.check() {
        spec_fail!("F4 (BBDL)", at, "the 2-edge structure: {m}");
    }
    let mut live = Vec::new();
    for x in (0..g.node_capacity() as u32).filter(|&x| g.is_alive(x)) {
        for e in g.incident(x) {
            if !live.contains(&e) {
                live.push(e);
            }
        }
    }
    for &e in &live {
        let mine = g.ends(e);
        let theirs = te.ends(e);
        if theirs != Some(mine) && theirs != Some([mine[1], mine[0]]) {
            spec_fail!("F4 (BBDL)", at, "edge {e} = {mine:?} held as {theirs:?}");
        }
    }
    let count = te.edge_count();
    if live.len() != count {
        spec_fail!(
            "F4 (BBDL)",
            at,
            "the graph has {} edges, the structure {count}",
            live.len()
        );
    }
}
