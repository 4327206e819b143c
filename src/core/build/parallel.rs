//! Phases 1-3 of the build on rayon's thread pool: the face scan and the grouping of
//! corners by vertex in runs of faces (one per thread), the edge classification (gluing,
//! links, components) in ranges of vertices of about equal corner counts.
//!
//! **Guarantee.** [`scan_faces`] and [`vertex_corners`] give the sequential phases'
//! results, the first bad face included. When [`classify_edges`] answers, the answer is
//! [`super::classify_edges`]'s, array for array (the union-find flattened: both make
//! the smallest vertex of each set its root). It answers for every surface without a
//! duplicate face or an edge in three or more faces, except closed ones with a
//! vertex-link problem; for those it returns `None` and the caller runs the sequential
//! pass, which finds the problem that pass's precedence reports. O(F + V) work, as the
//! sequential phases, over the pool, plus one `u32` per vertex and thread for the
//! counts of the runs.
//!
//! **Why it is sound to split.** A run's corners are counted, copied and placed by its
//! own thread; each run's corners of a vertex go after the earlier runs' (their counts
//! say where), so each vertex's corners stay increasing. Every edge is glued, classified
//! and joined by its smaller endpoint, so each corner's `opposite` entry is written by
//! exactly one range and no entry twice; the entries are scattered, hence atomics
//! (relaxed stores: the join at the end orders them before any read). Each vertex's link
//! check reads only its own faces when it has at most [`SMALL_LINK`] of them; larger
//! stars are walked after the join, when every edge is glued. The union-find links roots
//! by compare and swap, larger root under smaller, so the root of each set is its
//! smallest vertex, as in the sequential [`super::union`].

use super::{
    check_sizes, edge_runs, face_is_bad, face_problem, fans, gather_edges, link_cycles,
    link_problem, run_starts, BuildError, Classified, Scanned, VertexCorners, NONE, SMALL_LINK,
};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering::Relaxed};

/// Below this many faces the build stays sequential. Measured on 2 cores
/// (docs/benchmarks.md): from about 330k faces up the classification on the pool was
/// 1.2-1.3× faster; on the shared meshes of 80k-200k faces the gain was within the
/// noise or a loss (up to 1.2× slower), as waking the pool's threads and their cache
/// misses on each other's entries cost what the second core saves.
pub(super) const MIN_FACES: usize = 1 << 18;

/// Ranges per thread of the pool: more than one, so that a range of dense vertices
/// does not leave the other threads idle at the end.
const RANGES_PER_THREAD: usize = 4;

/// Phase 3 on the current rayon pool, when it has more than one thread and the
/// surface has at least [`MIN_FACES`] faces; `None` otherwise, or when the surface has
/// a problem (see the module's guarantee).
pub(super) fn classify_edges(
    scanned: &Scanned,
    by_vertex: &VertexCorners,
    faces: &[[u32; 3]],
) -> Option<Classified> {
    let threads = pool_threads(faces.len())?;
    classify_edges_in(scanned, by_vertex, threads * RANGES_PER_THREAD)
}

/// Whether the build runs its phases on the pool: more than one thread, and at least
/// [`MIN_FACES`] faces. The number of threads if so.
fn pool_threads(faces: usize) -> Option<usize> {
    let threads = rayon::current_num_threads();
    (threads >= 2 && faces >= MIN_FACES).then_some(threads)
}

/// Vertices per task when a pass over the vertices is split.
const VERTEX_RANGE: usize = 1 << 16;

/// Phase 1 on the pool (see [`pool_threads`]): [`super::scan_faces`]'s result, the same
/// first bad face included. One task per thread on a run of faces: each checks its
/// faces, copies them into the corner array and counts its corners at each vertex in
/// its own array; the counts are then summed by vertex ranges.
pub(super) fn scan_faces(
    vertex_count: usize,
    faces: &[[u32; 3]],
) -> Option<Result<Scanned, BuildError>> {
    let threads = pool_threads(faces.len())?;
    Some(scan_faces_in(vertex_count, faces, threads, VERTEX_RANGE))
}

/// [`scan_faces`] in `runs` runs of faces (at least 1), summing the counts in ranges of
/// `vertex_range` vertices (at least 1).
pub(super) fn scan_faces_in(
    vertex_count: usize,
    faces: &[[u32; 3]],
    runs: usize,
    vertex_range: usize,
) -> Result<Scanned, BuildError> {
    check_sizes(vertex_count, faces)?;
    let n = vertex_count;
    let run = faces.len().div_ceil(runs).max(1);
    let mut corner_vertex = vec![0u32; 3 * faces.len()];
    let counts: Vec<Result<Vec<u32>, usize>> = faces
        .par_chunks(run)
        .zip(corner_vertex.par_chunks_mut(3 * run))
        .enumerate()
        .map(|(k, (faces, out))| {
            let mut count = vec![0u32; n];
            for (i, (&f, out)) in faces.iter().zip(out.chunks_exact_mut(3)).enumerate() {
                if face_is_bad(f, n) {
                    return Err(k * run + i);
                }
                let [a, b, c] = f.map(|v| v as usize);
                count[a] += 1;
                count[b] += 1;
                count[c] += 1;
                out.copy_from_slice(&f);
            }
            Ok(count)
        })
        .collect();
    let counts: Vec<Vec<u32>> = match counts.into_iter().collect() {
        Ok(counts) => counts,
        // The runs are in face order: the first run with a bad face has the first.
        Err(i) => return Err(face_problem(vertex_count, i, faces[i])),
    };
    let mut counts = counts.into_iter();
    let mut degree = counts.next().unwrap_or_else(|| vec![0; n]);
    let rest: Vec<Vec<u32>> = counts.collect();
    degree
        .par_chunks_mut(vertex_range)
        .enumerate()
        .for_each(|(k, d)| {
            for count in &rest {
                for (d, &c) in d.iter_mut().zip(&count[k * vertex_range..]) {
                    *d += c;
                }
            }
        });
    Ok(Scanned {
        corner_vertex,
        degree,
    })
}

/// Phase 2 on the pool (see [`pool_threads`]): [`super::vertex_corners`]'s result, the
/// corners of each vertex increasing. A counting sort in parallel: each thread counts
/// the corners of its run at each vertex, each run's corners of vertex `v` start where
/// the earlier runs' end, and each thread writes its run's corners there (scattered
/// entries, no entry written twice: relaxed atomic stores).
pub(super) fn vertex_corners(corner_vertex: &[u32], degree: &[u32]) -> Option<VertexCorners> {
    let threads = pool_threads(corner_vertex.len() / 3)?;
    Some(vertex_corners_in(
        corner_vertex,
        degree,
        threads,
        VERTEX_RANGE,
    ))
}

/// [`vertex_corners`] in `runs` runs of corners (at least 1), the slots computed in
/// ranges of `vertex_range` vertices (at least 1).
pub(super) fn vertex_corners_in(
    corner_vertex: &[u32],
    degree: &[u32],
    runs: usize,
    vertex_range: usize,
) -> VertexCorners {
    let n = degree.len();
    let run = corner_vertex.len().div_ceil(runs).max(1);
    let mut counts: Vec<Vec<u32>> = corner_vertex
        .par_chunks(run)
        .map(|corners| {
            let mut count = vec![0u32; n];
            for &v in corners {
                count[v as usize] += 1;
            }
            count
        })
        .collect();
    let mut end = run_starts(degree);
    // Each run's first slot at each vertex, in place of its count.
    let mut ranges: Vec<Vec<&mut [u32]>> =
        (0..n.div_ceil(vertex_range)).map(|_| Vec::new()).collect();
    for count in counts.iter_mut() {
        for (k, part) in count.chunks_mut(vertex_range).enumerate() {
            ranges[k].push(part);
        }
    }
    ranges
        .into_par_iter()
        .enumerate()
        .for_each(|(k, mut parts)| {
            let begin = &end[k * vertex_range..];
            for (i, &b) in begin.iter().take(vertex_range).enumerate() {
                let mut slot = b;
                for part in parts.iter_mut() {
                    let c = part[i];
                    part[i] = slot;
                    slot += c;
                }
            }
        });
    let corners: Vec<AtomicU32> = vec![0u32; corner_vertex.len()]
        .into_iter()
        .map(AtomicU32::new)
        .collect();
    corner_vertex
        .par_chunks(run)
        .zip(counts.par_iter_mut())
        .enumerate()
        .for_each(|(k, (run_vertices, slot))| {
            for (i, &v) in run_vertices.iter().enumerate() {
                let s = &mut slot[v as usize];
                corners[*s as usize].store((k * run + i) as u32, Relaxed);
                *s += 1;
            }
        });
    for (e, &d) in end.iter_mut().zip(degree) {
        *e += d;
    }
    VertexCorners {
        end,
        corners: corners.into_iter().map(AtomicU32::into_inner).collect(),
    }
}

/// What one range of vertices found, when it found no problem that stops the pass.
struct RangeOut {
    /// Corners opposite boundary edges, in edge order.
    boundary: Vec<u32>,
    /// The first boundary edge of the range.
    first_boundary: Option<BuildError>,
    /// A vertex whose link (of at most [`SMALL_LINK`] faces) is not one cycle of at
    /// least three faces; meaningless where there is a boundary edge.
    link_problem: bool,
    /// Vertices with more than [`SMALL_LINK`] faces, whose links are checked after the
    /// join.
    large: Vec<u32>,
}

/// Phase 3 with the vertices split into about `ranges` ranges of about equal corner
/// counts (any number ≥ 1; the tests force small surfaces into many).
pub(super) fn classify_edges_in(
    scanned: &Scanned,
    by_vertex: &VertexCorners,
    ranges: usize,
) -> Option<Classified> {
    let vertex_count = scanned.degree.len();
    let corner_count = scanned.corner_vertex.len();
    // Zeroed and converted in place (no pass over the memory): every entry is written.
    let opposite: Vec<AtomicU32> = vec![0u32; corner_count]
        .into_iter()
        .map(AtomicU32::new)
        .collect();
    let parent: Vec<AtomicU32> = (0..vertex_count as u32).map(AtomicU32::new).collect();
    let mut vertex_corner = vec![NONE; vertex_count];
    let failed = AtomicBool::new(false);

    let starts = range_starts(&by_vertex.end, ranges);
    let mut tasks = Vec::with_capacity(starts.len() - 1);
    let mut rest = &mut vertex_corner[..];
    for w in starts.windows(2) {
        let (mine, tail) = rest.split_at_mut(w[1] - w[0]);
        tasks.push((w[0], mine));
        rest = tail;
    }
    let shared = Shared {
        corner_vertex: &scanned.corner_vertex,
        by_vertex,
        opposite: &opposite,
        parent: &parent,
        failed: &failed,
    };
    let outs: Vec<Option<RangeOut>> = tasks
        .into_par_iter()
        .map(|(first, vertex_corner)| shared.classify_range(first, vertex_corner))
        .collect();
    let outs: Vec<RangeOut> = outs.into_iter().collect::<Option<_>>()?;

    let opposite: Vec<u32> = opposite.into_iter().map(AtomicU32::into_inner).collect();
    let parent: Vec<u32> = parent.into_iter().map(AtomicU32::into_inner).collect();
    let first_boundary = outs.iter().find_map(|o| o.first_boundary.clone());
    let boundary: Vec<u32> = outs
        .iter()
        .flat_map(|o| o.boundary.iter().copied())
        .collect();
    if boundary.is_empty() {
        if outs.iter().any(|o| o.link_problem) {
            return None;
        }
        // Every edge is glued now: the large stars can be walked.
        for &v in outs.iter().flat_map(|o| &o.large) {
            let corners = by_vertex.corners_of(v);
            let cycles = fans(&scanned.corner_vertex, &opposite, v, corners);
            if link_problem(v, cycles, corners.len()).is_some() {
                return None;
            }
        }
    }
    Some(Classified {
        opposite,
        clean: boundary.is_empty(),
        boundary,
        duplicate: None,
        bad_edge: None,
        first_boundary,
        first_link: None,
        parent,
        vertex_corner,
    })
}

/// Where the vertex ranges start, then the vertex count: range `k` is the vertices
/// `starts[k]..starts[k + 1]`, cut after the vertex where the corner count passes each
/// multiple of `corner_count / ranges`. Non-empty ranges in increasing order, at most
/// `max(ranges, 1)` of them (fewer where one vertex holds more than a range's share, or
/// there are fewer vertices), each holding at most a range's share of the corners plus
/// one vertex's. `end[v]` is the end of vertex `v`'s corners ([`VertexCorners::end`]).
fn range_starts(end: &[u32], ranges: usize) -> Vec<usize> {
    let (vertex_count, corner_count) = (end.len(), end.last().map_or(0, |&e| e as usize));
    let ranges = ranges.max(1);
    let mut starts = vec![0usize];
    for k in 1..ranges {
        let target = (corner_count * k / ranges) as u32;
        let v = end.partition_point(|&e| e <= target);
        if v > *starts.last().unwrap_or(&0) && v < vertex_count {
            starts.push(v);
        }
    }
    starts.push(vertex_count);
    starts
}

/// What every range reads or writes.
struct Shared<'a> {
    corner_vertex: &'a [u32],
    by_vertex: &'a VertexCorners,
    /// Written at the corners of the edges whose smaller endpoint is in the range.
    opposite: &'a [AtomicU32],
    parent: &'a [AtomicU32],
    /// Set by the range that meets a problem, so that the others stop early.
    failed: &'a AtomicBool,
}

impl Shared<'_> {
    /// The vertices `first..first + vertex_corner.len()`: the sequential pass's loop,
    /// `None` at the first duplicate face or edge in three or more faces (or when
    /// another range met one).
    fn classify_range(&self, first: usize, vertex_corner: &mut [u32]) -> Option<RangeOut> {
        let corner_vertex = self.corner_vertex;
        let mut out = RangeOut {
            boundary: Vec::new(),
            first_boundary: None,
            link_problem: false,
            large: Vec::new(),
        };
        let mut bucket: Vec<u64> = Vec::new();
        let mut ends: Vec<(u32, u32)> = Vec::new();
        for (k, slot) in vertex_corner.iter_mut().enumerate() {
            let lo = (first + k) as u32;
            let corners = self.by_vertex.corners_of(lo);
            if corners.is_empty() {
                continue;
            }
            if self.failed.load(Relaxed) {
                return None;
            }
            *slot = corners[0];
            gather_edges(corner_vertex, lo, corners, &mut bucket, &mut ends);
            for run in edge_runs(&bucket) {
                let hi = (run[0] >> 32) as u32;
                union(self.parent, lo, hi);
                let p = (run[0] & 0xffff_ffff) as usize;
                match *run {
                    [_, q] => {
                        let q = (q & 0xffff_ffff) as usize;
                        if corner_vertex[p] == corner_vertex[q] {
                            self.failed.store(true, Relaxed);
                            return None;
                        }
                        self.opposite[p].store(q as u32, Relaxed);
                        self.opposite[q].store(p as u32, Relaxed);
                    }
                    [_] => {
                        self.opposite[p].store(NONE, Relaxed);
                        out.boundary.push(p as u32);
                        if out.first_boundary.is_none() {
                            out.first_boundary = Some(BuildError::BoundaryEdge {
                                a: lo,
                                b: hi,
                                face: p / 3,
                            });
                        }
                    }
                    _ => {
                        self.failed.store(true, Relaxed);
                        return None;
                    }
                }
            }
            // With a boundary edge in the range, the links are not read (nor in the
            // sequential pass, which stops checking them at the first).
            if out.first_boundary.is_none() && !out.link_problem {
                if ends.len() <= SMALL_LINK {
                    let cycles = link_cycles(&ends);
                    out.link_problem = link_problem(lo, cycles, ends.len()).is_some();
                } else {
                    out.large.push(lo);
                }
            }
        }
        Some(out)
    }
}

/// The root of `x`'s set, halving the path on the way: each step points a vertex at its
/// grandparent, by compare and swap, so a pointer only ever moves to an ancestor (a
/// smaller vertex of the same set).
fn find(parent: &[AtomicU32], mut x: u32) -> u32 {
    loop {
        let p = parent[x as usize].load(Relaxed);
        if p == x {
            return x;
        }
        let g = parent[p as usize].load(Relaxed);
        if g != p {
            let _ = parent[x as usize].compare_exchange_weak(p, g, Relaxed, Relaxed);
        }
        x = g;
    }
}

/// Joins the sets of `x` and `y`: the larger root is linked under the smaller by
/// compare and swap, which fails (and the union retries) if another range linked that
/// root meanwhile. Parents are smaller than their children, so each set's root is its
/// smallest vertex and one increasing pass flattens the forest.
fn union(parent: &[AtomicU32], x: u32, y: u32) {
    let (mut x, mut y) = (x, y);
    loop {
        let (rx, ry) = (find(parent, x), find(parent, y));
        if rx == ry {
            return;
        }
        let (big, small) = (rx.max(ry), rx.min(ry));
        if parent[big as usize]
            .compare_exchange(big, small, Relaxed, Relaxed)
            .is_ok()
        {
            return;
        }
        (x, y) = (big, small);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    /// The ranges are non-empty, in order, cover every vertex, number at most the ranges
    /// asked for (exactly that many when the corners are spread evenly enough), and each
    /// holds at most a range's share of the corners plus one vertex's: on random degree
    /// sequences (unused vertices and one heavy vertex included) cut into 1 to 12 ranges.
    #[test]
    fn ranges_are_ordered_cover_the_vertices_and_share_the_corners() {
        let mut rng = Rng::new(4);
        for round in 0..400 {
            let n = 1 + rng.index(60);
            let mut degree: Vec<u32> = (0..n).map(|_| rng.index(8) as u32).collect();
            if round % 5 == 0 {
                degree[rng.index(n)] = 100;
            }
            let end: Vec<u32> = degree
                .iter()
                .scan(0, |sum, &d| {
                    *sum += d;
                    Some(*sum)
                })
                .collect();
            let total = *end.last().unwrap_or(&0) as usize;
            let heaviest = *degree.iter().max().unwrap_or(&0) as usize;
            let ranges = 1 + rng.index(12);
            let starts = range_starts(&end, ranges);
            assert_eq!(
                (starts[0], starts[starts.len() - 1]),
                (0, n),
                "round {round}"
            );
            assert!(
                starts.windows(2).all(|w| w[0] < w[1]),
                "round {round}: {starts:?}"
            );
            assert!(starts.len() - 1 <= ranges, "round {round}: {starts:?}");
            let corners = |w: &[usize]| {
                let before = if w[0] == 0 { 0 } else { end[w[0] - 1] };
                (end[w[1] - 1] - before) as usize
            };
            for w in starts.windows(2) {
                assert!(
                    corners(w) <= total / ranges + heaviest + 1,
                    "round {round}: {starts:?} over {degree:?}"
                );
            }
            if degree.iter().all(|&d| d == 1) && ranges <= n {
                assert_eq!(starts.len() - 1, ranges, "round {round}");
            }
        }
        // Even degrees: exactly the ranges asked for, of equal size.
        let end: Vec<u32> = (1..=12).map(|v| 3 * v).collect();
        assert_eq!(range_starts(&end, 4), vec![0, 3, 6, 9, 12]);
        assert_eq!(range_starts(&end, 1), vec![0, 12]);
        assert_eq!(range_starts(&end, 0), vec![0, 12]);
    }
}
