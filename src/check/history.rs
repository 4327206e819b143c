//! The replay of a stated contraction history ([`super::reduce_history`]).
//!
//! **Guarantee.** Each step `[u, v]` (contract `v` into `u`, input ids) is judged on the
//! surface as the steps before it left it: `u` and `v` are distinct vertices still in
//! it, `uv` is an edge (two faces), and the edge passes the link condition as the
//! definition states it, Lk(u) ∩ Lk(v) = Lk(uv) = {x, y}: the ends have no common
//! neighbour but the two opposite vertices `x`, `y`, and the edge `xy` is not in both
//! links (faces `uxy` and `vxy`, the tetrahedron). The step then removes the two faces of
//! `uv` and renames `v` to `u`. The first wrong step is reported (`invalid_history`) and
//! ends the replay; after a whole replay, its faces and the output's (in input ids) must
//! be the same set of triangles (`history_mismatch` for each one on one side only).
//!
//! Faces and per-vertex face lists only: no corner table, nothing of the core.
//!
//! **Complexity.** O(F) to start, then per step O(d(u) + d(v)) face visits (each list
//! holds only live faces: dead ones are dropped as the list is read); O(F log F) for the
//! final comparison.

use super::{Failure, FailureKind, Verdict};

const NONE: u32 = u32::MAX;

/// The surface being replayed.
struct Replay {
    faces: Vec<[u32; 3]>,
    alive: Vec<bool>,
    /// Per vertex, the live faces holding it (dead ones are dropped when read).
    at: Vec<Vec<u32>>,
    /// Per vertex, the step that removed it (`NONE`: still there).
    removed_by: Vec<u32>,
    /// Per vertex, the step whose neighbour scan last marked it.
    mark: Vec<u32>,
}

impl Replay {
    fn new(vertex_count: usize, faces: &[[u32; 3]]) -> Self {
        let mut at = vec![Vec::new(); vertex_count];
        for (i, f) in faces.iter().enumerate() {
            for &v in f {
                at[v as usize].push(i as u32);
            }
        }
        Replay {
            faces: faces.to_vec(),
            alive: vec![true; faces.len()],
            at,
            removed_by: vec![NONE; vertex_count],
            mark: vec![NONE; vertex_count],
        }
    }

    /// The live faces at `w`, with the dead ones dropped from its list.
    fn live(&mut self, w: u32) -> &[u32] {
        let alive = &self.alive;
        let list = &mut self.at[w as usize];
        list.retain(|&f| alive[f as usize]);
        list
    }

    /// Step `step` contracts `v` into `u`: `Err` with the reason when it may not.
    fn step(&mut self, step: u32, [u, v]: [u32; 2]) -> Result<(), String> {
        let n = self.at.len();
        for w in [u, v] {
            if w as usize >= n {
                return Err(format!(
                    "step {step} ([{u}, {v}]): vertex {w} is beyond the input's {n} vertices"
                ));
            }
            if self.removed_by[w as usize] != NONE {
                return Err(format!(
                    "step {step} ([{u}, {v}]): vertex {w} was removed by step {}",
                    self.removed_by[w as usize]
                ));
            }
        }
        if u == v {
            return Err(format!("step {step} contracts vertex {u} with itself"));
        }
        // The faces of uv and their third vertices.
        let faces_u = self.live(u).to_vec();
        let mut edge_faces: Vec<u32> = Vec::with_capacity(2);
        let mut opposite: Vec<u32> = Vec::with_capacity(2);
        for &f in &faces_u {
            let face = self.faces[f as usize];
            if face.contains(&v) {
                edge_faces.push(f);
                opposite.extend(face.iter().copied().filter(|&w| w != u && w != v));
            }
        }
        let [x, y] = opposite[..] else {
            return Err(format!(
                "step {step}: [{u}, {v}] is no edge of the surface the steps before it left \
                 ({} faces hold both)",
                edge_faces.len()
            ));
        };
        // Lk(u) ∩ Lk(v), vertices: the ends' common neighbours must be x and y.
        for &f in &faces_u {
            for w in self.faces[f as usize] {
                self.mark[w as usize] = step;
            }
        }
        let faces_v = self.live(v).to_vec();
        let mut link_edge = (false, false);
        for &f in &faces_v {
            let face = self.faces[f as usize];
            for w in face {
                if w != u && w != v && w != x && w != y && self.mark[w as usize] == step {
                    return Err(format!(
                        "step {step}: [{u}, {v}] fails the link condition: vertex {w} is a \
                         common neighbour of its ends besides the opposite vertices {x} and {y}"
                    ));
                }
            }
            link_edge.1 |= face.contains(&x) && face.contains(&y);
        }
        // Lk(u) ∩ Lk(v), edges: xy in both links (faces uxy and vxy) is the tetrahedron.
        link_edge.0 = faces_u.iter().any(|&f| {
            let face = self.faces[f as usize];
            face.contains(&x) && face.contains(&y)
        });
        if link_edge == (true, true) {
            return Err(format!(
                "step {step}: [{u}, {v}] fails the link condition: the edge [{x}, {y}] is in \
                 the links of both ends (a tetrahedron)"
            ));
        }
        for f in edge_faces {
            self.alive[f as usize] = false;
        }
        for f in self.live(v).to_vec() {
            for w in &mut self.faces[f as usize] {
                if *w == v {
                    *w = u;
                }
            }
            self.at[u as usize].push(f);
        }
        self.at[v as usize].clear();
        self.removed_by[v as usize] = step;
        Ok(())
    }

    /// The live faces, each sorted, in sorted order.
    fn sorted_faces(&self) -> Vec<[u32; 3]> {
        let mut out: Vec<[u32; 3]> = (self.faces.iter().zip(&self.alive))
            .filter(|(_, &a)| a)
            .map(|(f, _)| sorted(*f))
            .collect();
        out.sort_unstable();
        out
    }
}

fn sorted(mut f: [u32; 3]) -> [u32; 3] {
    f.sort_unstable();
    f
}

/// The surface after a whole replay: its faces, each sorted, in sorted order, and the
/// vertices they use, in increasing order.
pub(super) struct Replayed {
    pub faces: Vec<[u32; 3]>,
    pub survivors: Vec<u32>,
}

/// Replays `history` on the closed surface `input_faces` (over `vertex_count` ids): the
/// surface it ends at, or `None` with the first invalid step's reason in `verdict`.
pub(super) fn replay(
    vertex_count: usize,
    input_faces: &[[u32; 3]],
    history: &[[u32; 2]],
    verdict: &mut Verdict,
) -> Option<Replayed> {
    let mut r = Replay::new(vertex_count, input_faces);
    for (i, &e) in history.iter().enumerate() {
        if let Err(message) = r.step(i as u32, e) {
            verdict.fail(Failure::new(FailureKind::InvalidHistory, message));
            return None;
        }
    }
    let faces = r.sorted_faces();
    let mut survivors: Vec<u32> = faces.iter().flatten().copied().collect();
    survivors.sort_unstable();
    survivors.dedup();
    Some(Replayed { faces, survivors })
}

/// Compares the replayed faces with `output_faces` (the output's faces in input ids):
/// each face on one side only is a `history_mismatch`. `steps` is the history's length.
pub(super) fn compare(
    ours: &[[u32; 3]],
    output_faces: &[[u32; 3]],
    steps: usize,
    verdict: &mut Verdict,
) {
    let mut theirs: Vec<([u32; 3], usize)> = (output_faces.iter().enumerate())
        .map(|(i, &f)| (sorted(f), i))
        .collect();
    theirs.sort_unstable();
    let (mut a, mut b) = (0, 0);
    while a < ours.len() || b < theirs.len() {
        let next_ours = ours.get(a);
        let next_theirs = theirs.get(b).map(|(f, _)| f);
        match (next_ours, next_theirs) {
            (Some(p), Some(q)) if p == q => {
                a += 1;
                b += 1;
            }
            (Some(p), q) if q.is_none_or(|q| p < q) => {
                verdict.fail(Failure::new(
                    FailureKind::HistoryMismatch,
                    format!(
                        "the replay of the {steps} steps keeps the face {p:?} (input ids), which \
                         the output does not have"
                    ),
                ));
                a += 1;
            }
            _ => {
                let (q, i) = theirs[b];
                verdict.fail(
                    Failure::new(
                        FailureKind::HistoryMismatch,
                        format!(
                            "output face {i} ({q:?} in input ids) is not a face of the replay \
                             of the {steps} steps"
                        ),
                    )
                    .face(i),
                );
                b += 1;
            }
        }
    }
}
