//! The verdict on an output of the tri-quad conversion: quads that pair every triangle of
//! the input (or of a stated triangulation K of the same surface on the same vertices)
//! with an edge-neighbour, each triangle once.
//!
//! Each quad `[v0, v1, v2, v3]` (a cycle) is two triangles split along one of its two
//! diagonals: `{v0 v1 v2, v0 v2 v3}` or `{v1 v2 v3, v1 v3 v0}`. A quad passes when one of
//! its splits is two faces of K (both splits are only when the component is the
//! tetrahedron, and then the quads take the split whose faces are still free). The
//! quad mesh is then a closed polygon surface of K's χ per component without a check of
//! its own: a K edge that is no diagonal lies in two K faces of two different quads (two
//! faces of one quad share one edge, K having no repeated face), so every quad edge is
//! in two quads, and V − (E − F/2) + F/2 = V − E + F.

use std::borrow::Cow;
use std::collections::HashMap;

use super::surface::{analyse, Sets};
use super::{
    closed_input, match_vertices, no_matching, same_components, Failure, FailureKind, Matching,
    Verdict,
};
use crate::{Error, QuadMesh, TriMesh};

/// What an answer states besides its quads: the paired triangulation and the pairs.
///
/// # Example
/// ```
/// use contractible::check::QuadCheck;
/// // An answer of an algorithm that flips edges states the triangulation it paired:
/// let k = [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]];
/// let stated = QuadCheck { triangles: Some(&k), ..QuadCheck::default() };
/// assert!(stated.pairs.is_none());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct QuadCheck<'a> {
    /// The paired triangulation K, in the output's vertex ids; `None`: the input's faces
    /// (an algorithm that flips edges, as LRS does, must state it).
    pub triangles: Option<&'a [[u32; 3]]>,
    /// Per quad, in the quads' order, the two rows of K (of the input's faces when
    /// `triangles` is `None`) it joins; `None`: inferred from the quads.
    pub pairs: Option<&'a [[u32; 2]]>,
}

fn sorted(a: u32, b: u32, c: u32) -> [u32; 3] {
    let mut t = [a, b, c];
    t.sort_unstable();
    t
}

/// The output's used vertices grouped by the quads that join them, each group
/// increasing, groups in the order of their smallest vertex.
fn vertex_groups(output: &QuadMesh) -> Vec<Vec<u32>> {
    let mut sets = Sets::new(output.vertex_count);
    let mut used = vec![false; output.vertex_count];
    for q in &output.faces {
        for &v in q {
            used[v as usize] = true;
            sets.union(q[0], v);
        }
    }
    let mut group_of_root: HashMap<u32, usize> = HashMap::new();
    let mut groups: Vec<Vec<u32>> = Vec::new();
    for v in (0..output.vertex_count as u32).filter(|&v| used[v as usize]) {
        let g = *group_of_root.entry(sets.find(v)).or_insert_with(|| {
            groups.push(Vec::new());
            groups.len() - 1
        });
        groups[g].push(v);
    }
    groups
}

/// Judges `output` as a conversion of `input` with what the answer states: see
/// [`quad`](super::quad()).
pub(super) fn check(
    input: &TriMesh,
    output: &QuadMesh,
    stated: &QuadCheck<'_>,
) -> Result<Verdict, Error> {
    let inp = closed_input(input, "quad")?;
    let mut verdict = Verdict::new("quad");
    let n = output.vertex_count as u64;
    for (i, q) in output.faces.iter().enumerate() {
        if let Some(&v) = q.iter().find(|&&v| u64::from(v) >= n) {
            verdict.fail(
                Failure::new(
                    FailureKind::VertexOutOfRange,
                    format!(
                        "output quad {i} names vertex {v}, beyond the {} vertices",
                        output.vertex_count
                    ),
                )
                .face(i)
                .vertex(v),
            );
        } else if (0..4).any(|a| (a + 1..4).any(|b| q[a] == q[b])) {
            verdict.fail(
                Failure::new(
                    FailureKind::DegenerateFace,
                    format!("output quad {i} {q:?} repeats a vertex"),
                )
                .face(i),
            );
        }
    }
    for (i, t) in stated.triangles.unwrap_or_default().iter().enumerate() {
        if let Some(&v) = t.iter().find(|&&v| u64::from(v) >= n) {
            verdict.fail(
                Failure::new(
                    FailureKind::VertexOutOfRange,
                    format!(
                        "stated triangle {i} names vertex {v}, beyond the output's {} vertices",
                        output.vertex_count
                    ),
                )
                .vertex(v),
            );
        }
    }
    if !verdict.passed() {
        return Ok(verdict);
    }
    let groups = vertex_groups(output);
    let group_refs: Vec<&[u32]> = groups.iter().map(Vec::as_slice).collect();
    let Some(matching) = match_vertices(input, output, &inp, &group_refs, &mut verdict) else {
        verdict.fail(no_matching(input, output.vertex_count));
        return Ok(verdict);
    };
    // Per output vertex, its input vertex (`u32::MAX`: none, already reported).
    let to_input = |v: u32| -> u32 {
        match &matching {
            Matching::ById => v,
            Matching::ByPosition(m) => m[v as usize],
        }
    };
    let k_faces: Cow<'_, [[u32; 3]]> = match stated.triangles {
        None => Cow::Borrowed(&input.faces),
        Some(k) => {
            let mapped: Vec<[u32; 3]> = k.iter().map(|t| t.map(to_input)).collect();
            if mapped.iter().any(|t| t.contains(&u32::MAX)) {
                // The stated triangulation uses a vertex that is no input vertex (the
                // matching named it if a quad uses it too).
                if verdict.passed() {
                    verdict.fail(Failure::new(
                        FailureKind::UnknownVertex,
                        "the stated triangulation uses a vertex that is no input vertex".into(),
                    ));
                }
                return Ok(verdict);
            }
            if !stated_surface(input, &inp, &mapped, &mut verdict) {
                return Ok(verdict);
            }
            Cow::Owned(mapped)
        }
    };
    let (which, hint) = if stated.triangles.is_some() {
        ("stated triangle", "")
    } else {
        (
            "input face",
            " (a conversion that flips edges must state the triangulation it paired)",
        )
    };
    let row: HashMap<[u32; 3], u32> = k_faces
        .iter()
        .enumerate()
        .map(|(i, t)| (sorted(t[0], t[1], t[2]), i as u32))
        .collect();
    if let Some(p) = stated.pairs {
        if p.len() != output.faces.len() {
            verdict.fail(Failure::new(
                FailureKind::WrongPair,
                format!("{} pairs for {} quads", p.len(), output.faces.len()),
            ));
        }
    }
    let mut uses = vec![0u32; k_faces.len()];
    let mut both: Vec<[[u32; 2]; 2]> = Vec::new();
    for (i, q) in output.faces.iter().enumerate() {
        let m = q.map(to_input);
        if m.contains(&u32::MAX) {
            continue;
        }
        let splits = [
            [sorted(m[0], m[1], m[2]), sorted(m[0], m[2], m[3])],
            [sorted(m[1], m[2], m[3]), sorted(m[1], m[3], m[0])],
        ];
        let rows: Vec<[u32; 2]> = splits
            .iter()
            .filter_map(|[s, t]| Some([*row.get(s)?, *row.get(t)?]))
            .collect();
        match (stated.pairs, stated.pairs.and_then(|p| p.get(i))) {
            (Some(_), Some(&[a, b])) => {
                if rows.iter().any(|r| *r == [a, b] || *r == [b, a]) {
                    uses[a as usize] += 1;
                    uses[b as usize] += 1;
                } else {
                    verdict.fail(
                        Failure::new(
                            FailureKind::WrongPair,
                            format!(
                                "pair {i} [{a}, {b}] is not two {which}s whose union is output \
                                 quad {i} {q:?}"
                            ),
                        )
                        .face(i),
                    );
                }
            }
            // More quads than pairs: reported above.
            (Some(_), None) => {}
            (None, _) => match rows.as_slice() {
                [] => verdict.fail(
                    Failure::new(
                        FailureKind::QuadNotTwoTriangles,
                        format!(
                            "output quad {i} {q:?} is not two {which}s sharing one of its \
                             diagonals{hint}"
                        ),
                    )
                    .face(i),
                ),
                [r] => {
                    uses[r[0] as usize] += 1;
                    uses[r[1] as usize] += 1;
                }
                _ => both.push([rows[0], rows[1]]),
            },
        }
    }
    // Both splits are faces only on a tetrahedron: take a split still free.
    for rows in both {
        let r = rows
            .iter()
            .find(|r| uses[r[0] as usize] == 0 && uses[r[1] as usize] == 0)
            .unwrap_or(&rows[0]);
        uses[r[0] as usize] += 1;
        uses[r[1] as usize] += 1;
    }
    for (r, &u) in uses.iter().enumerate() {
        let t = k_faces[r];
        if u > 1 {
            verdict.fail(Failure::new(
                FailureKind::TriangleUsedTwice,
                format!("{which} {r} {t:?} is in {u} quads"),
            ));
        } else if u == 0 {
            verdict.fail(Failure::new(
                FailureKind::TriangleUnused,
                format!("{which} {r} {t:?} is in no quad"),
            ));
        }
    }
    Ok(verdict)
}

/// Whether the stated triangulation `k` (in input ids) is a closed surface on the
/// input's vertices with the input's surface per component; the reasons in `verdict`
/// when not.
fn stated_surface(
    input: &TriMesh,
    inp: &super::surface::Analysis,
    k: &[[u32; 3]],
    verdict: &mut Verdict,
) -> bool {
    let a = match analyse(input.vertex_count, k, "stated triangulation") {
        Ok(a) => a,
        Err((failures, counts)) => {
            verdict.absorb(failures, counts);
            return false;
        }
    };
    for &((x, y), _, f) in a.edges.iter().filter(|(_, o, _)| o[1] == u32::MAX) {
        verdict.fail(
            Failure::new(
                FailureKind::BoundaryEdge,
                format!("stated triangulation edge [{x}, {y}] is in one face only (face {f})"),
            )
            .edge([x, y]),
        );
    }
    if !verdict.passed() {
        return false;
    }
    let mut in_k = vec![false; input.vertex_count];
    for p in &a.parts {
        for &v in &p.vertices {
            in_k[v as usize] = true;
        }
    }
    for p in &inp.parts {
        for &v in p.vertices.iter().filter(|&&v| !in_k[v as usize]) {
            verdict.fail(
                Failure::new(
                    FailureKind::MissingVertex,
                    format!("input vertex {v} is in no triangle of the stated triangulation"),
                )
                .vertex(v),
            );
        }
    }
    same_components(input, inp, &a, &|v| Some(v), true, false, verdict);
    verdict.passed()
}
