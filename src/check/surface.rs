//! What a face list is, decided from the list alone: the checker's own analysis, sharing
//! no code with the core's corner table or the algorithms.
//!
//! **Guarantee.** [`analyse`] reports every face that is degenerate (a repeated corner),
//! out of range or repeated (the same three vertices as an earlier face), every edge in
//! more than two faces, and every vertex whose faces do not form one fan; on a list with
//! none of these (a surface, possibly with boundary), the connected components (by shared
//! edges, numbered by their smallest face) with V, E, F, χ, orientability and boundary
//! loops each, and the boundary loop of every boundary vertex. **Complexity.**
//! O(F log F) time, O(F) memory.

use super::{Failure, FailureKind};

/// One connected component of a surface.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Part {
    /// Its vertices, increasing.
    pub vertices: Vec<u32>,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Its smallest face index.
    pub first_face: usize,
    /// Whether its faces can be oriented coherently.
    pub orientable: bool,
    /// The cycles of its boundary edges.
    pub boundary_loops: usize,
}

impl Part {
    /// V − E + F.
    pub fn euler(&self) -> i64 {
        self.vertices.len() as i64 - self.edges as i64 + self.faces as i64
    }
}

/// A face list known to be a surface (possibly with boundary).
pub(super) struct Analysis {
    /// Per face: its component.
    pub part_of_face: Vec<usize>,
    pub parts: Vec<Part>,
    /// Every edge `(a, b)`, `a < b`, increasing, with its one or two opposite vertices
    /// (`u32::MAX` for the missing one of a boundary edge) and a face holding it.
    pub edges: Vec<((u32, u32), [u32; 2], u32)>,
    /// Per vertex (by id, `vertex_count` of them): its neighbours, increasing, as a
    /// range of `neighbours`.
    pub neighbour_start: Vec<usize>,
    pub neighbours: Vec<u32>,
    /// Per vertex (by id): its boundary loop (numbered from 0 in the order of their
    /// smallest edge, over all parts), `u32::MAX` for a vertex on no boundary edge.
    pub loop_of: Vec<u32>,
}

impl Analysis {
    /// The neighbours of `v`, increasing.
    pub fn neighbours_of(&self, v: u32) -> &[u32] {
        let v = v as usize;
        &self.neighbours[self.neighbour_start[v]..self.neighbour_start[v + 1]]
    }

    /// A common neighbour of `a` and `b` that is not in `opposite`, if there is one (the
    /// smallest): the link condition's witness. O(d_a + d_b), the two sorted lists
    /// walked together.
    pub fn other_common_neighbour(&self, a: u32, b: u32, opposite: [u32; 2]) -> Option<u32> {
        let (na, nb) = (self.neighbours_of(a), self.neighbours_of(b));
        let (mut i, mut j) = (0, 0);
        while i < na.len() && j < nb.len() {
            match na[i].cmp(&nb[j]) {
                std::cmp::Ordering::Less => i += 1,
                std::cmp::Ordering::Greater => j += 1,
                std::cmp::Ordering::Equal => {
                    if !opposite.contains(&na[i]) {
                        return Some(na[i]);
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
        None
    }
}

/// Union–find over `0..n`, by size, with path halving.
pub(super) struct Sets {
    parent: Vec<u32>,
    size: Vec<u32>,
}

impl Sets {
    pub(super) fn new(n: usize) -> Self {
        Sets {
            parent: (0..n as u32).collect(),
            size: vec![1; n],
        }
    }
    pub(super) fn find(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let g = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = g;
            x = g;
        }
        x
    }
    pub(super) fn union(&mut self, a: u32, b: u32) {
        let (mut a, mut b) = (self.find(a), self.find(b));
        if a == b {
            return;
        }
        if self.size[a as usize] < self.size[b as usize] {
            std::mem::swap(&mut a, &mut b);
        }
        self.parent[b as usize] = a;
        self.size[a as usize] += self.size[b as usize];
    }
}

/// At most this many failures of one kind are listed (the count says how many there
/// were).
pub(super) const LISTED: usize = 20;

/// Adds `f` to `out` unless `LISTED` of its kind are already there; counts it anyway.
pub(super) fn push(out: &mut Vec<Failure>, counts: &mut Vec<(FailureKind, usize)>, f: Failure) {
    match counts.iter_mut().find(|(k, _)| *k == f.kind) {
        Some((_, n)) => {
            *n += 1;
            if *n > LISTED {
                return;
            }
        }
        None => counts.push((f.kind, 1)),
    }
    out.push(f);
}

/// The defects that make a face list no surface: the failures listed and the counts per
/// kind.
pub(super) type Defects = (Vec<Failure>, Vec<(FailureKind, usize)>);

/// Analyses `faces` over `vertex_count` vertices; `Err` with every defect found (the
/// list is not a surface) otherwise.
pub(super) fn analyse(
    vertex_count: usize,
    faces: &[[u32; 3]],
    which: &'static str,
) -> Result<Analysis, Defects> {
    let mut failures = Vec::new();
    let mut counts = Vec::new();
    let n = vertex_count as u64;
    for (i, f) in faces.iter().enumerate() {
        if let Some(&v) = f.iter().find(|&&v| u64::from(v) >= n) {
            let failure = Failure::new(
                FailureKind::VertexOutOfRange,
                format!("{which} face {i} names vertex {v}, beyond the {vertex_count} vertices"),
            )
            .face(i)
            .vertex(v);
            push(&mut failures, &mut counts, failure);
        } else if f[0] == f[1] || f[1] == f[2] || f[0] == f[2] {
            let failure = Failure::new(
                FailureKind::DegenerateFace,
                format!("{which} face {i} {f:?} repeats a vertex"),
            )
            .face(i);
            push(&mut failures, &mut counts, failure);
        }
    }
    if !failures.is_empty() {
        return Err((failures, counts));
    }
    // Repeated faces: the same vertex set twice.
    let mut sorted: Vec<([u32; 3], usize)> = faces
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let mut s = *f;
            s.sort_unstable();
            (s, i)
        })
        .collect();
    sorted.sort_unstable();
    for w in sorted.windows(2) {
        if w[0].0 == w[1].0 {
            let failure = Failure::new(
                FailureKind::RepeatedFace,
                format!(
                    "{which} faces {} and {} have the same vertices {:?}",
                    w[0].1, w[1].1, w[1].0
                ),
            )
            .face(w[1].1);
            push(&mut failures, &mut counts, failure);
        }
    }
    drop(sorted);
    // Half-edges (low, high, face, opposite vertex, runs low → high).
    let mut half: Vec<(u32, u32, u32, u32, bool)> = Vec::with_capacity(3 * faces.len());
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b, c) = (f[k], f[(k + 1) % 3], f[(k + 2) % 3]);
            half.push((a.min(b), a.max(b), i as u32, c, a < b));
        }
    }
    half.sort_unstable();
    let mut edges = Vec::with_capacity(half.len() / 2 + 1);
    // Faces joined across edges (for components) and corners joined at vertices (for
    // fans): a corner is (face, vertex), numbered 3·face + position.
    let mut parts = Sets::new(faces.len());
    let mut fans = Sets::new(3 * faces.len());
    let corner = |face: u32, v: u32| -> u32 {
        let f = faces[face as usize];
        let k = f.iter().position(|&x| x == v).unwrap_or(0);
        3 * face + k as u32
    };
    let mut i = 0;
    while i < half.len() {
        let (a, b) = (half[i].0, half[i].1);
        let mut j = i;
        while j < half.len() && (half[j].0, half[j].1) == (a, b) {
            j += 1;
        }
        let group = &half[i..j];
        if group.len() > 2 {
            let failure = Failure::new(
                FailureKind::NonManifoldEdge,
                format!("{which} edge [{a}, {b}] is in {} faces", group.len()),
            )
            .face(group[0].2 as usize)
            .edge([a, b]);
            push(&mut failures, &mut counts, failure);
        } else if group.len() == 2 {
            let (f, g) = (group[0].2, group[1].2);
            parts.union(f, g);
            fans.union(corner(f, a), corner(g, a));
            fans.union(corner(f, b), corner(g, b));
            edges.push(((a, b), [group[0].3, group[1].3], group[0].2));
        } else {
            edges.push(((a, b), [group[0].3, u32::MAX], group[0].2));
        }
        i = j;
    }
    // Fans: the corners at each vertex must form one class.
    let mut first_class: Vec<u32> = vec![u32::MAX; vertex_count];
    let mut pinched: Vec<bool> = vec![false; vertex_count];
    for (fi, f) in faces.iter().enumerate() {
        for (k, &v) in f.iter().enumerate() {
            let class = fans.find(3 * fi as u32 + k as u32);
            let seen = &mut first_class[v as usize];
            if *seen == u32::MAX {
                *seen = class;
            } else if *seen != class && !pinched[v as usize] {
                pinched[v as usize] = true;
                let failure = Failure::new(
                    FailureKind::NonManifoldVertex,
                    format!("{which} vertex {v}: its faces form more than one fan"),
                )
                .face(fi)
                .vertex(v);
                push(&mut failures, &mut counts, failure);
            }
        }
    }
    if !failures.is_empty() {
        return Err((failures, counts));
    }
    // Components, numbered by their smallest face.
    let mut part_of_face = vec![usize::MAX; faces.len()];
    let mut part_of_root: Vec<usize> = vec![usize::MAX; faces.len()];
    let mut out: Vec<Part> = Vec::new();
    for fi in 0..faces.len() {
        let root = parts.find(fi as u32) as usize;
        if part_of_root[root] == usize::MAX {
            part_of_root[root] = out.len();
            out.push(Part {
                vertices: Vec::new(),
                edges: 0,
                faces: 0,
                first_face: fi,
                orientable: true,
                boundary_loops: 0,
            });
        }
        part_of_face[fi] = part_of_root[root];
        let p = &mut out[part_of_face[fi]];
        p.faces += 1;
        p.vertices.extend_from_slice(&faces[fi]);
    }
    for p in &mut out {
        p.vertices.sort_unstable();
        p.vertices.dedup();
    }
    // Edges per part, and orientability: a face's sign flips across an edge both faces
    // run the same way; a part is orientable when the signs are consistent.
    let mut sign: Vec<i8> = vec![0; faces.len()];
    let mut across: Vec<Vec<(u32, bool)>> = vec![Vec::new(); faces.len()];
    let mut i = 0;
    while i < half.len() {
        let mut j = i;
        while j < half.len() && (half[j].0, half[j].1) == (half[i].0, half[i].1) {
            j += 1;
        }
        out[part_of_face[half[i].2 as usize]].edges += 1;
        if j - i == 2 {
            let (f, g) = (half[i].2, half[i + 1].2);
            let same = half[i].4 == half[i + 1].4;
            across[f as usize].push((g, same));
            across[g as usize].push((f, same));
        }
        i = j;
    }
    for start in 0..faces.len() {
        if sign[start] != 0 {
            continue;
        }
        sign[start] = 1;
        let mut stack = vec![start as u32];
        while let Some(f) = stack.pop() {
            let s = sign[f as usize];
            for &(g, same) in &across[f as usize] {
                // Two faces running an edge the same way need opposite signs.
                let want = if same { -s } else { s };
                if sign[g as usize] == 0 {
                    sign[g as usize] = want;
                    stack.push(g);
                } else if sign[g as usize] != want {
                    out[part_of_face[f as usize]].orientable = false;
                }
            }
        }
    }
    drop(across);
    // Boundary loops: the boundary edges' graph is a union of cycles on a surface.
    let boundary: Vec<(u32, u32, u32)> = edges
        .iter()
        .filter(|(_, o, _)| o[1] == u32::MAX)
        .map(|&((a, b), _, f)| (a, b, f))
        .collect();
    let mut loop_of = vec![u32::MAX; vertex_count];
    if !boundary.is_empty() {
        let mut loops = Sets::new(vertex_count);
        for &(a, b, _) in &boundary {
            loops.union(a, b);
        }
        // Per root: its loop's number.
        let mut number = vec![u32::MAX; vertex_count];
        let mut next = 0u32;
        for &(a, b, f) in &boundary {
            let r = loops.find(a) as usize;
            if number[r] == u32::MAX {
                number[r] = next;
                next += 1;
                out[part_of_face[f as usize]].boundary_loops += 1;
            }
            loop_of[a as usize] = number[r];
            loop_of[b as usize] = number[r];
        }
    }
    // Neighbours per vertex (CSR), increasing.
    let mut degree = vec![0usize; vertex_count + 1];
    for &((a, b), _, _) in &edges {
        degree[a as usize + 1] += 1;
        degree[b as usize + 1] += 1;
    }
    for v in 0..vertex_count {
        degree[v + 1] += degree[v];
    }
    let neighbour_start = degree;
    let mut fill = neighbour_start.clone();
    let mut neighbours = vec![0u32; 2 * edges.len()];
    for &((a, b), _, _) in &edges {
        neighbours[fill[a as usize]] = b;
        fill[a as usize] += 1;
        neighbours[fill[b as usize]] = a;
        fill[b as usize] += 1;
    }
    for v in 0..vertex_count {
        neighbours[neighbour_start[v]..neighbour_start[v + 1]].sort_unstable();
    }
    Ok(Analysis {
        part_of_face,
        parts: out,
        edges,
        neighbour_start,
        neighbours,
        loop_of,
    })
}
