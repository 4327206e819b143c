//! Tri-quad conversion (Lemos–Ramaswami–Siqueira): a perfect pairing of edge-adjacent
//! triangles of a closed triangulation, so that every pair is a quadrilateral on the
//! same vertices. One module per algorithm, sharing the result type [`Quadrangulation`]:
//!
//! - [`greedy`]: the simple greedy SG (Sec. 3.1), random edge order;
//! - [`pulli_segal`]: the Pulli–Segal greedy PS (Sec. 3.1), four priority sets;
//! - [`augment`]: completion of any pairing into a perfect one by augmenting paths with
//!   blossoms (multi-source Edmonds on flat arrays), used by every algorithm;
//! - [`matching`]: the graph route, Edmonds on the whole dual graph;
//! - [`lrs`]: the paper's contraction/expansion algorithm with edge flips.
//!
//! A pairing exists on every closed triangulation (the dual graph is cubic and
//! bridgeless, so Petersen's theorem gives a perfect matching), so every algorithm's
//! output is perfect; only LRS changes the triangulation (by flips), the others pair the
//! input `K = T` itself.

use std::time::Instant;

use crate::core::{FaceId, Triangulation};
use crate::mesh::QuadMesh;

pub mod augment;
pub mod frink;
pub mod greedy;
pub mod lrs;
pub mod matching;
pub mod pulli_segal;

/// Which algorithm to run.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, Default)]
pub enum Algorithm {
    /// The paper's contraction/expansion algorithm ([`lrs`]; the default).
    #[default]
    Lrs,
    /// Pulli–Segal greedy ([`pulli_segal`]).
    PulliSegal,
    /// Simple greedy ([`greedy`]).
    SimpleGreedy,
    /// Edmonds on the whole dual graph ([`matching`]).
    Matching,
    /// Frink's reduction with the naive DFS strategy ([`frink::Naive`], O(F²); the
    /// reference of the tri-quad paper's DS route). Perfect directly: no completion.
    DsNaive,
    /// Frink's reduction with the link–cut cover-count strategy ([`frink::CoverTree`]).
    /// Perfect directly: no completion.
    FrinkLct,
    /// Frink's reduction with the Diks–Stańczyk strategy ([`frink::DiksStanczyk`]: a
    /// travelling forbidden edge, dynamic connectivity and link–cut LCA; O(F log² F)).
    /// Perfect directly: no completion.
    DiksStanczyk,
    /// Frink's reduction with the Biedl–Bose–Demaine–Lubiw strategy
    /// ([`frink::BiedlBoseDemaineLubiw`]: the travelling forbidden edge, the choice by
    /// fully dynamic 2-edge-connectivity queries; this crate's structure is not
    /// polylogarithmic, O(F² log F) in the worst case, see [`frink::TwoEdge`]). Perfect
    /// directly: no completion.
    BiedlBoseDemaineLubiw,
}

impl Algorithm {
    /// Every algorithm, in the order the documentation lists them.
    pub const ALL: [Algorithm; 8] = [
        Algorithm::Lrs,
        Algorithm::PulliSegal,
        Algorithm::SimpleGreedy,
        Algorithm::Matching,
        Algorithm::DiksStanczyk,
        Algorithm::BiedlBoseDemaineLubiw,
        Algorithm::FrinkLct,
        Algorithm::DsNaive,
    ];

    /// The short name used on the command line, in Python and in JSON (the one list of
    /// names: [`Display`](std::fmt::Display) writes it, [`FromStr`](std::str::FromStr)
    /// reads it).
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Lrs => "lrs",
            Algorithm::PulliSegal => "ps",
            Algorithm::SimpleGreedy => "sg",
            Algorithm::Matching => "matching",
            Algorithm::DsNaive => "ds-naive",
            Algorithm::FrinkLct => "frink-lct",
            Algorithm::DiksStanczyk => "ds",
            Algorithm::BiedlBoseDemaineLubiw => "bbdl",
        }
    }

    /// One line on what the algorithm is (the command line's help).
    pub fn summary(self) -> &'static str {
        match self {
            Algorithm::Lrs => {
                "Lemos–Ramaswami–Siqueira: RS contraction, expansion with flips, completion"
            }
            Algorithm::PulliSegal => "Pulli–Segal greedy, then completion",
            Algorithm::SimpleGreedy => "Simple greedy, then completion",
            Algorithm::Matching => "Edmonds' matching on the whole dual graph",
            Algorithm::DsNaive => {
                "Frink's reduction, naive DFS strategy (quadratic: refused above 100,000 \
                 faces per component)"
            }
            Algorithm::FrinkLct => "Frink's reduction, link–cut cover-count strategy",
            Algorithm::DiksStanczyk => {
                "Frink's reduction, Diks–Stańczyk strategy (dynamic connectivity, \
                 O(F log² F))"
            }
            Algorithm::BiedlBoseDemaineLubiw => {
                "Frink's reduction, Biedl–Bose–Demaine–Lubiw strategy (dynamic \
                 2-edge-connectivity; this crate's structure is O(F² log F) in the worst case)"
            }
        }
    }

    /// Whether the initial step pairs every face itself (Frink's reduction), so that no
    /// completion runs.
    pub fn is_perfect_directly(self) -> bool {
        matches!(
            self,
            Algorithm::DsNaive
                | Algorithm::FrinkLct
                | Algorithm::DiksStanczyk
                | Algorithm::BiedlBoseDemaineLubiw
        )
    }
}

crate::names::named_choice!(Algorithm, "tri-quad algorithm");

/// The largest component [`crate::quadrangulate`] (and so the command line and the
/// Python package) runs [`Algorithm::DsNaive`] on: its naive strategy is O(F²) (about a
/// minute at this size on the reference machine), so larger inputs are refused with a
/// pointer to [`Algorithm::FrinkLct`]. [`convert`] itself runs any size.
pub const DS_NAIVE_MAX_FACES: usize = 100_000;

/// Why [`convert`] produced no quadrangulation. On a valid closed triangulation only
/// [`ConvertError::TooLarge`] can happen; the other variants mean the input broke the
/// triangulation's invariants.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ConvertError {
    /// The dual graph has more nodes than the chosen Frink strategy's structures hold
    /// ([`frink::Strategy::max_nodes`]).
    #[error("{algorithm}: {faces} faces are more than its structures hold (at most {limit})")]
    TooLarge {
        /// The algorithm.
        algorithm: Algorithm,
        /// The faces of the input.
        faces: usize,
        /// The most faces the algorithm's structures hold.
        limit: usize,
    },
    /// Frink's reduction failed on the dual graph.
    #[error("{algorithm}: {source}")]
    Frink {
        /// The algorithm.
        algorithm: Algorithm,
        /// What failed.
        source: frink::FrinkError,
    },
    /// The completion refused the initial pairing.
    #[error("{algorithm}: {source}")]
    Completion {
        /// The algorithm.
        algorithm: Algorithm,
        /// What failed.
        source: augment::NotAPairing,
    },
}

/// Options shared by the algorithms.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// Seed of the documented stream ([`crate::rng`]) for the randomised orders of SG and
    /// PS (the paper randomises both, Sec. 4). LRS and matching are deterministic.
    pub seed: u64,
}

/// Counters and timings of one conversion: the columns of the paper's Tables 4.3–4.4,
/// (a) initial pairing time, (b) % paired, (c) unpaired count, (d) completion time,
/// (e) total, plus the work of each step.
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Stats {
    /// Triangles of the input (and of `K`).
    pub faces: usize,
    /// (a) Seconds of the initial pairing step (for LRS: contraction and expansion).
    pub initial_seconds: f64,
    /// (b) Percentage of the triangles paired by the initial step.
    pub initial_paired_percent: f64,
    /// (c) Triangles left unpaired by the initial step.
    pub initial_unpaired: usize,
    /// (d) Seconds of the completion by augmenting paths.
    pub completion_seconds: f64,
    /// (e) Total seconds (a + d).
    pub total_seconds: f64,
    /// Edge flips (LRS only; `K` differs from the input exactly by these).
    pub flips: usize,
    /// Augmenting paths applied by the completion.
    pub augmenting_paths: usize,
    /// Searches of the completion: its phases (from all unpaired triangles at once) and
    /// the single-root searches of its sparse pass ([`augment::Completion::phases`]).
    pub phases: usize,
}

/// The result of a conversion: the triangulation `K` that is paired (the input itself,
/// or for LRS the input with some edges flipped: same vertex ids, same counts), a
/// perfect pairing of `K`, and the statistics.
#[derive(Clone, Debug)]
pub struct Quadrangulation {
    /// Which algorithm produced it.
    pub algorithm: Algorithm,
    /// The paired triangulation.
    pub tri: Triangulation,
    /// A perfect pairing of `tri`.
    pub pairing: Pairing,
    /// Counters.
    pub stats: Stats,
}

impl Quadrangulation {
    /// The quad mesh over `tri`'s vertex ids ([`quad_mesh`]); `None` only if the
    /// fields were changed so that the pairing is no longer a perfect pairing of `tri`.
    pub fn quad_mesh(&self) -> Option<QuadMesh> {
        quad_mesh(&self.tri, &self.pairing)
    }
}

/// The statistics (a)–(c) of an initial pairing `initial` of `tri` computed in
/// `seconds`; the completion fields are zero.
pub fn initial_stats(tri: &Triangulation, initial: &Pairing, seconds: f64) -> Stats {
    let faces = tri.face_count();
    let paired = 2 * initial.len();
    Stats {
        faces,
        initial_seconds: seconds,
        initial_paired_percent: if faces == 0 {
            100.0
        } else {
            100.0 * paired as f64 / faces as f64
        },
        initial_unpaired: faces - paired,
        ..Stats::default()
    }
}

/// Runs `algorithm` on `tri` (consumed: LRS flips in place): the initial pairing step,
/// timed as (a), then the completion by [`augment::complete`], timed as (d). The output
/// pairing is perfect (a closed triangulation's dual is cubic and bridgeless, so a
/// perfect matching exists, and the completion finds one); only LRS changes the
/// triangulation, by the flips it counts.
///
/// Deterministic: the result (all but the timings) is a function of the input (ids and
/// corner slots included), the algorithm and `options.seed`.
///
/// # Errors
/// [`ConvertError::TooLarge`] for [`Algorithm::DiksStanczyk`] and [`Algorithm::BiedlBoseDemaineLubiw`] above their
/// structures' node limits; the other errors only on a triangulation that broke its
/// invariants.
pub fn convert(
    tri: Triangulation,
    algorithm: Algorithm,
    options: &Options,
) -> Result<Quadrangulation, ConvertError> {
    convert_observed(tri, algorithm, options, &mut crate::progress::ignore)
}

/// The stage of [`convert_observed`]'s reports during the initial step.
pub const INITIAL: &str = "initial pairing (faces paired)";

/// [`convert`], reporting progress to `observer`: the initial step as one unit (stage
/// [`INITIAL`]: 0 faces when it starts, the faces it paired when it ends), then the
/// completion's faces paired after its linear pass and after every phase
/// ([`augment::complete_observed`]). Same result as [`convert`].
pub fn convert_observed(
    tri: Triangulation,
    algorithm: Algorithm,
    options: &Options,
    observer: &mut dyn FnMut(crate::progress::Progress),
) -> Result<Quadrangulation, ConvertError> {
    use crate::progress::Progress;
    let faces = tri.face_count() as u64;
    observer(Progress::new(INITIAL, 0, faces));
    let started = Instant::now();
    let Initial {
        tri,
        pairing,
        flips,
    } = initial_pairing(tri, algorithm, options)?;
    if algorithm.is_perfect_directly() {
        // Perfect by Frink's construction: (c) = 0 and no completion, (d) = 0.
        let mut stats = initial_stats(&tri, &pairing, started.elapsed().as_secs_f64());
        stats.total_seconds = stats.initial_seconds;
        return Ok(Quadrangulation {
            algorithm,
            tri,
            pairing,
            stats,
        });
    }
    let mut stats = initial_stats(&tri, &pairing, started.elapsed().as_secs_f64());
    observer(Progress::new(INITIAL, 2 * pairing.len() as u64, faces));
    stats.flips = flips;
    let mut pairing = pairing;
    let completion_started = Instant::now();
    let work = augment::complete_observed(&tri, &mut pairing, observer)
        .map_err(|source| ConvertError::Completion { algorithm, source })?;
    stats.completion_seconds = completion_started.elapsed().as_secs_f64();
    stats.total_seconds = stats.initial_seconds + stats.completion_seconds;
    stats.augmenting_paths = work.augmenting_paths;
    stats.phases = work.phases;
    Ok(Quadrangulation {
        algorithm,
        tri,
        pairing,
        stats,
    })
}

/// The result of an algorithm's initial pairing step (before any completion).
#[derive(Clone, Debug)]
pub struct Initial {
    /// The paired triangulation (the input, or LRS's flipped `K`).
    pub tri: Triangulation,
    /// The pairing of `tri` (perfect for the Frink algorithms, partial for the others).
    pub pairing: Pairing,
    /// Edge flips (LRS only).
    pub flips: usize,
}

/// The initial pairing step of `algorithm` alone (what [`convert`] times as (a)), for
/// callers that time or complete it themselves (benchmarks, profiles). Errors as
/// [`convert`]'s.
pub fn initial_pairing(
    tri: Triangulation,
    algorithm: Algorithm,
    options: &Options,
) -> Result<Initial, ConvertError> {
    use frink::Strategy as _;
    let faces = tri.face_count();
    let frink_error = |source: frink::FrinkError, limit: usize| match source {
        frink::FrinkError::TooLarge(_) => ConvertError::TooLarge {
            algorithm,
            faces,
            limit,
        },
        source => ConvertError::Frink { algorithm, source },
    };
    let (tri, pairing, flips) = match algorithm {
        Algorithm::Lrs => {
            let e = lrs::initial_pairing(tri);
            (e.tri, e.pairing, e.flips)
        }
        Algorithm::PulliSegal => {
            let p = pulli_segal::initial_pairing(&tri, options);
            (tri, p, 0)
        }
        Algorithm::SimpleGreedy => {
            let p = greedy::initial_pairing(&tri, options);
            (tri, p, 0)
        }
        Algorithm::Matching => {
            let p = matching::initial_pairing(&tri);
            (tri, p, 0)
        }
        Algorithm::DsNaive => {
            let mut s = frink::Naive::new();
            let limit = s.max_nodes();
            let (p, _) =
                frink::perfect_matching_with(&tri, &mut s).map_err(|e| frink_error(e, limit))?;
            (tri, p, 0)
        }
        Algorithm::FrinkLct => {
            let mut s = frink::CoverTree::new();
            let limit = s.max_nodes();
            let (p, _) =
                frink::perfect_matching_with(&tri, &mut s).map_err(|e| frink_error(e, limit))?;
            (tri, p, 0)
        }
        Algorithm::DiksStanczyk => {
            let mut s = frink::DiksStanczyk::new();
            let limit = s.max_nodes();
            let (p, _) =
                frink::perfect_matching_with(&tri, &mut s).map_err(|e| frink_error(e, limit))?;
            (tri, p, 0)
        }
        Algorithm::BiedlBoseDemaineLubiw => {
            let mut s = frink::BiedlBoseDemaineLubiw::new();
            let limit = s.max_nodes();
            let (p, _) =
                frink::perfect_matching_with(&tri, &mut s).map_err(|e| frink_error(e, limit))?;
            (tri, p, 0)
        }
    };
    Ok(Initial {
        tri,
        pairing,
        flips,
    })
}

/// No mate.
const UNPAIRED: u32 = u32::MAX;

/// A set of disjoint pairs of edge-adjacent faces of one triangulation (a matching of its
/// dual graph), stored as one mate per face id. O(1) per query and change.
///
/// Guarantees: `mate(f) == Some(g)` iff `mate(g) == Some(f)`; a face is never its own
/// mate. Whether mates share an edge is the caller's invariant ([`Self::check`] verifies
/// it against a triangulation).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Pairing {
    mate: Vec<u32>,
    pairs: usize,
}

impl Pairing {
    /// The empty pairing for face ids `0..face_capacity`.
    pub fn new(face_capacity: usize) -> Self {
        Pairing {
            mate: vec![UNPAIRED; face_capacity],
            pairs: 0,
        }
    }

    /// The mate of `f`, if paired.
    #[inline]
    pub fn mate(&self, f: FaceId) -> Option<FaceId> {
        match self.mate.get(f.index()) {
            Some(&m) if m != UNPAIRED => Some(FaceId(m)),
            _ => None,
        }
    }

    /// Whether `f` is paired.
    #[inline]
    pub fn is_paired(&self, f: FaceId) -> bool {
        self.mate(f).is_some()
    }

    /// Pairs `f` and `g`, both unpaired and distinct (debug-asserted).
    #[inline]
    pub fn pair(&mut self, f: FaceId, g: FaceId) {
        debug_assert!(f != g && !self.is_paired(f) && !self.is_paired(g));
        self.mate[f.index()] = g.0;
        self.mate[g.index()] = f.0;
        self.pairs += 1;
    }

    /// Unpairs `f` and its mate; returns the mate.
    #[inline]
    pub fn unpair(&mut self, f: FaceId) -> Option<FaceId> {
        let g = self.mate(f)?;
        self.mate[f.index()] = UNPAIRED;
        self.mate[g.index()] = UNPAIRED;
        self.pairs -= 1;
        Some(g)
    }

    /// Number of pairs.
    #[inline]
    pub fn len(&self) -> usize {
        self.pairs
    }

    /// Whether there is no pair.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.pairs == 0
    }

    /// One more than the largest face id the pairing can hold.
    pub fn face_capacity(&self) -> usize {
        self.mate.len()
    }

    /// The pairs `(f, g)` with `f < g`, in increasing `f`.
    pub fn pairs(&self) -> impl Iterator<Item = (FaceId, FaceId)> + '_ {
        self.mate
            .iter()
            .enumerate()
            .filter(|&(f, &g)| g != UNPAIRED && (f as u32) < g)
            .map(|(f, &g)| (FaceId(f as u32), FaceId(g)))
    }

    /// The live faces of `tri` that are unpaired, in increasing id.
    pub fn unpaired<'a>(&'a self, tri: &'a Triangulation) -> impl Iterator<Item = FaceId> + 'a {
        tri.faces().filter(move |&f| !self.is_paired(f))
    }

    /// Whether every live face of `tri` is paired.
    pub fn is_perfect(&self, tri: &Triangulation) -> bool {
        2 * self.pairs == tri.face_count()
    }

    /// Checks the pairing against `tri` from scratch: mates are symmetric, live, distinct
    /// and share an edge of `tri`; the pair count is right. O(F).
    pub fn check(&self, tri: &Triangulation) -> Result<(), String> {
        if self.mate.len() < tri.face_capacity() {
            return Err(format!(
                "pairing holds {} faces, the triangulation {}",
                self.mate.len(),
                tri.face_capacity()
            ));
        }
        let mut paired = 0;
        for (f, &m) in self.mate.iter().enumerate() {
            if m == UNPAIRED {
                continue;
            }
            let (f, g) = (FaceId(f as u32), FaceId(m));
            if !tri.is_face(f) || !tri.is_face(g) {
                return Err(format!("pair ({f}, {g}) holds a removed face"));
            }
            if self.mate(g) != Some(f) {
                return Err(format!(
                    "{f} is paired with {g}, which is not paired with it"
                ));
            }
            if !tri.face_neighbours(f).contains(&g) {
                return Err(format!("{f} and {g} are paired but share no edge"));
            }
            paired += 1;
        }
        if paired != 2 * self.pairs {
            return Err(format!(
                "{} pairs recorded, {paired} faces paired",
                self.pairs
            ));
        }
        Ok(())
    }
}

/// The quad of the pair `(f, g)` (mates sharing an edge `[a, b]`, with third vertices `c`
/// in `f` and `d` in `g`): the cycle `[c, a, d, b]`, starting at `f`'s third vertex and
/// following `f`'s slot order, so a consistently oriented `f` gives a consistently
/// oriented quad. `None` if the two faces share no edge.
pub fn quad_of(tri: &Triangulation, f: FaceId, g: FaceId) -> Option<[u32; 4]> {
    let k = f
        .corners()
        .into_iter()
        .find(|&c| tri.opposite(c).face() == g)?;
    let d = tri.vertex(tri.opposite(k));
    // f = (c, a, b) in slot order from k: c at k, a at next, b at prev.
    let (c, a, b) = (tri.vertex(k), tri.vertex(k.next()), tri.vertex(k.prev()));
    Some([c.0, a.0, d.0, b.0])
}

/// The quad mesh of a perfect pairing of `tri`: one quad per pair ([`quad_of`]), in
/// increasing order of the pair's smaller face id; vertex ids are `tri`'s. `None` if the
/// pairing is not a perfect pairing of `tri`.
pub fn quad_faces(tri: &Triangulation, pairing: &Pairing) -> Option<Vec<[u32; 4]>> {
    if !pairing.is_perfect(tri) {
        return None;
    }
    pairing.pairs().map(|(f, g)| quad_of(tri, f, g)).collect()
}

/// A quad mesh over `tri`'s vertex ids (`vertex_count = tri.vertex_capacity()`, no
/// positions): see [`quad_faces`].
pub fn quad_mesh(tri: &Triangulation, pairing: &Pairing) -> Option<QuadMesh> {
    Some(QuadMesh::combinatorial(
        tri.vertex_capacity(),
        quad_faces(tri, pairing)?,
    ))
}

/// Test fixtures shared by the pairing modules' unit tests.
#[cfg(test)]
pub(crate) mod fixtures {
    use crate::core::{FaceId, Triangulation};

    /// A live face of `t` other than `f` that shares no edge with it (it may share a
    /// vertex): the partner of an invalid pair.
    pub(crate) fn face_not_adjacent_to(t: &Triangulation, f: FaceId) -> FaceId {
        t.faces()
            .find(|&g| g != f && !t.face_neighbours(f).contains(&g))
            .expect("a face sharing no edge with the given one")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::octahedron;

    /// Every perfect matching of the octahedron's dual (the cube graph), found by
    /// backtracking over the face list alone: faces are adjacent when they share two
    /// vertices.
    fn perfect_matchings(faces: &[[u32; 3]]) -> Vec<Vec<(usize, usize)>> {
        fn go(
            faces: &[[u32; 3]],
            used: &mut Vec<bool>,
            cur: &mut Vec<(usize, usize)>,
            out: &mut Vec<Vec<(usize, usize)>>,
        ) {
            let Some(f) = used.iter().position(|&u| !u) else {
                out.push(cur.clone());
                return;
            };
            used[f] = true;
            for g in f + 1..faces.len() {
                let shared = faces[f].iter().filter(|v| faces[g].contains(v)).count();
                if !used[g] && shared == 2 {
                    used[g] = true;
                    cur.push((f, g));
                    go(faces, used, cur, out);
                    cur.pop();
                    used[g] = false;
                }
            }
            used[f] = false;
        }
        let mut out = Vec::new();
        go(
            faces,
            &mut vec![false; faces.len()],
            &mut Vec::new(),
            &mut out,
        );
        out
    }

    /// The quads that pairs of triangles (given by their vertices) must give, each as
    /// its sorted 4 vertices, in sorted order: two triangles on an edge span the 4
    /// vertices of their union.
    fn pair_unions(pairs: impl IntoIterator<Item = ([u32; 3], [u32; 3])>) -> Vec<[u32; 4]> {
        sorted_quads(pairs.into_iter().map(|(a, b)| {
            let mut v: Vec<u32> = a.iter().chain(&b).copied().collect();
            v.sort_unstable();
            v.dedup();
            v.try_into()
                .expect("two triangles sharing an edge span 4 vertices")
        }))
    }

    /// `quads`, each with its vertices sorted, in sorted order.
    fn sorted_quads(quads: impl IntoIterator<Item = [u32; 4]>) -> Vec<[u32; 4]> {
        let mut out: Vec<[u32; 4]> = quads
            .into_iter()
            .map(|mut q| {
                q.sort_unstable();
                q
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// A pairing counts its pairs through pairing and unpairing, and lists each once.
    #[test]
    fn a_pairing_counts_and_lists_its_pairs() {
        let mut p = Pairing::new(6);
        assert!(p.is_empty());
        assert_eq!((p.len(), p.face_capacity()), (0, 6));
        p.pair(FaceId(4), FaceId(1));
        p.pair(FaceId(0), FaceId(5));
        assert!(!p.is_empty());
        assert_eq!(p.len(), 2);
        assert_eq!(
            p.pairs().collect::<Vec<_>>(),
            [(FaceId(0), FaceId(5)), (FaceId(1), FaceId(4))]
        );
        assert_eq!(p.mate(FaceId(1)), Some(FaceId(4)));
        assert!(p.is_paired(FaceId(4)) && !p.is_paired(FaceId(2)));
        assert_eq!(p.unpair(FaceId(5)), Some(FaceId(0)));
        assert_eq!(p.unpair(FaceId(5)), None);
        assert_eq!(p.len(), 1);
        assert_eq!(p.unpair(FaceId(4)), Some(FaceId(1)));
        assert!(p.is_empty());
    }

    /// Exactly Frink's reduction (its four strategies) pairs every face itself: for
    /// those no completion runs (no progress beyond the initial stage, no completion
    /// time); for the others it does. Either way the result's quad mesh has a quad per
    /// pair, on the union of the pair's vertices, and the initial step took time.
    #[test]
    fn only_frinks_reduction_skips_the_completion() {
        use crate::gen::random::{random, RandomParams, SurfaceKind};
        let direct = [
            Algorithm::DsNaive,
            Algorithm::FrinkLct,
            Algorithm::DiksStanczyk,
            Algorithm::BiedlBoseDemaineLubiw,
        ];
        let tri = random(&RandomParams {
            surface: SurfaceKind::NonOrientable(2),
            min_faces: 1500,
            flip_percent: 30,
            seed: 7,
        })
        .expect("a random surface");
        let faces = tri.face_list();
        for algorithm in Algorithm::ALL {
            assert_eq!(
                algorithm.is_perfect_directly(),
                direct.contains(&algorithm),
                "{algorithm}"
            );
            let mut seen = Vec::new();
            let q = convert_observed(tri.clone(), algorithm, &Options::default(), &mut |p| {
                seen.push((p.stage, p.done, p.total))
            })
            .expect("conversion");
            let completed = seen.iter().any(|&(s, _, _)| s != INITIAL);
            assert_eq!(completed, !direct.contains(&algorithm), "{algorithm}");
            // The initial stage starts at 0 and, when a completion follows, ends at the
            // faces the initial step paired.
            let n = faces.len() as u64;
            assert_eq!(seen[0], (INITIAL, 0, n), "{algorithm}");
            if completed {
                let paired = (q.stats.faces - q.stats.initial_unpaired) as u64;
                assert_eq!(seen[1], (INITIAL, paired, n), "{algorithm}");
            }
            assert!(q.stats.initial_seconds > 0.0, "{algorithm}");
            assert_eq!(
                q.stats.total_seconds,
                q.stats.initial_seconds + q.stats.completion_seconds,
                "{algorithm}"
            );
            if direct.contains(&algorithm) {
                assert_eq!(q.stats.completion_seconds, 0.0, "{algorithm}");
                assert_eq!(q.stats.total_seconds, q.stats.initial_seconds);
            }
            let mesh = q.quad_mesh().expect("a perfect pairing");
            assert_eq!(mesh.faces.len(), faces.len() / 2, "{algorithm}");
            let want = pair_unions(q.pairing.pairs().map(|(f, g)| {
                let ids = |f| q.tri.face_vertices(f).map(|v| v.0);
                (ids(f), ids(g))
            }));
            let got = sorted_quads(mesh.faces.iter().copied());
            assert_eq!(got, want, "{algorithm}");
        }
    }

    /// Every perfect pairing of the octahedron (9, the perfect matchings of the cube)
    /// passes the check and gives 4 quads, each the union of its two triangles' vertices.
    #[test]
    fn every_perfect_pairing_of_the_octahedron_gives_four_quads() {
        let m = octahedron();
        let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("octahedron");
        let all = perfect_matchings(&m.faces);
        assert_eq!(all.len(), 9, "the cube graph has 9 perfect matchings");
        for pairs in all {
            let mut p = Pairing::new(t.face_capacity());
            for &(f, g) in &pairs {
                assert!(!p.is_perfect(&t));
                p.pair(FaceId(f as u32), FaceId(g as u32));
            }
            assert_eq!(p.check(&t), Ok(()));
            assert!(p.is_perfect(&t));
            assert_eq!(initial_stats(&t, &p, 0.0).initial_unpaired, 0);
            let quads = quad_faces(&t, &p).expect("perfect");
            assert_eq!(quads.len(), 4);
            let expected = pair_unions(pairs.iter().map(|&(f, g)| (m.faces[f], m.faces[g])));
            let got = sorted_quads(quads);
            assert_eq!(got, expected);
        }
    }

    /// `Pairing::check` reports each way a pairing can be wrong.
    #[test]
    fn the_pairing_check_reports_every_kind_of_error() {
        let m = octahedron();
        let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("octahedron");
        let f = FaceId(0);
        let g = super::fixtures::face_not_adjacent_to(&t, f);
        // Two faces that share no edge.
        let mut p = Pairing::new(t.face_capacity());
        p.pair(f, g);
        assert!(p.check(&t).unwrap_err().contains("share no edge"));
        // Too short for the triangulation.
        let short = Pairing::new(t.face_capacity() - 1);
        assert!(short.check(&t).unwrap_err().contains("pairing holds"));
        // An adjacent pair, then one side pointed elsewhere: not symmetric.
        let h = t.face_neighbours(f)[0];
        let mut p = Pairing::new(t.face_capacity());
        p.pair(f, h);
        assert_eq!(p.check(&t), Ok(()));
        p.mate[h.index()] = g.0;
        assert!(p.check(&t).unwrap_err().contains("not paired with it"));
        // A pair count that disagrees with the mates.
        let mut p = Pairing::new(t.face_capacity());
        p.pair(f, h);
        p.pairs += 1;
        assert!(p.check(&t).unwrap_err().contains("pairs recorded"));
        // A pair holding a face the triangulation no longer has.
        let mut t2 = t.clone();
        let (a, b, _) = t2.edges().next().expect("an edge");
        t2.contract(a, b, &mut crate::History::new())
            .expect("the octahedron's edges are contractible");
        let dead = t.faces().find(|&x| !t2.is_face(x)).expect("a removed face");
        let live = t2.face_neighbours(t2.faces().next().expect("a face"))[0];
        let mut p = Pairing::new(t2.face_capacity());
        p.mate[dead.index()] = live.0;
        p.mate[live.index()] = dead.0;
        p.pairs = 1;
        assert!(p.check(&t2).unwrap_err().contains("removed face"));
    }
}
