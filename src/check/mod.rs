//! Independent verdicts on outputs of **any** implementation: whether a file is a
//! correct answer to a task on an input, judged by the answer's properties, not by its
//! bytes (another implementation may break ties differently and still be right).
//!
//! **Guarantee.** A verdict lists every reason an output is wrong, each located (the
//! output's face index, edge, vertex, or the input's component), at most 20 of a kind
//! with the count of all; an output with no reason passes. The checks share no code with
//! the algorithms or the core's corner table: faces, edges, fans, components, χ,
//! orientability, boundary loops and the link condition are computed here from the face
//! lists alone (module `surface`).
//!
//! - [`reduce`]: the output is a closed 2-manifold on input vertices (matched by id when
//!   the output keeps the input's vertex list, else by exact position), with the input's
//!   positions, one component per input component of the same surface (χ and
//!   orientability), and **irreducible**: every edge fails the link condition (its ends
//!   have a common neighbour besides the two opposite vertices), the tetrahedron aside.
//!   [`reduce_history`] also replays a stated contraction history: each step valid in turn
//!   under the link condition, the replay ending at the output's faces.
//! - [`simplify()`]: the output is a surface (boundary allowed) with a finite position
//!   per used vertex, of the input's surface per component (χ, orientability, boundary
//!   loops; matched by id when the output keeps the input's vertex list, else as
//!   multisets of surface types), and no edge strictly shorter than ε passes the link
//!   condition of the surface with boundary (each loop coned to its own apex; an edge
//!   between two loops and a coned tetrahedron refused) unless the geometry guard of
//!   the run ([`SimplifyCheck`]) refuses it.
//! - [`quad()`]: every quad is two triangles of the paired triangulation (the input's
//!   faces, or a stated K of the input's surface on its vertices, [`QuadCheck`]) split
//!   along one of its diagonals, and every triangle is in exactly one quad: a perfect
//!   pairing of edge-adjacent triangles.
//!
//! **Complexity.** O(F log F) for the surfaces (and O(F) expected for the pairing),
//! plus Σ over output edges of the two ends' degrees for the link condition (for
//! `simplify`, over the short edges, plus their ends' faces for the guard).
//!
//! An input that is not a valid input of the task (for `reduce` and `quad`: not a
//! closed surface; for `simplify`: no surface, or no usable positions or ε) is an
//! error, not a failed verdict: the task must refuse it. (Only there does the checker call the core: its
//! build locates the input's defect as every task reports it. The `simplify` checker
//! takes the task's option types, `Eps` and `simplify::Position`, as plain values.)

mod decimate_check;
mod history;
mod quad_check;
mod simplify_check;
mod surface;

use std::collections::HashMap;

use crate::{Error, Mesh, QuadMesh, TriMesh};
pub use decimate_check::DecimateCheck;
pub use quad_check::QuadCheck;
pub use simplify_check::SimplifyCheck;
use surface::{analyse, push, Analysis, Part};

/// What is wrong with an output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum FailureKind {
    /// A face names a vertex the output does not have.
    VertexOutOfRange,
    /// A face repeats a vertex.
    DegenerateFace,
    /// Two faces have the same three vertices.
    RepeatedFace,
    /// An edge lies in more than two faces.
    NonManifoldEdge,
    /// A vertex's faces form more than one fan.
    NonManifoldVertex,
    /// An edge lies in one face only where the output must be closed.
    BoundaryEdge,
    /// An output vertex is no input vertex (by id, or by exact position).
    UnknownVertex,
    /// An output vertex kept the input's id but not its position.
    MovedVertex,
    /// An output component takes vertices of two input components.
    ComponentsMerged,
    /// An input component has no output component.
    ComponentLost,
    /// An input component has two or more output components.
    ComponentSplit,
    /// An output component is not the surface of its input component (χ,
    /// orientability, boundary loops).
    SurfaceChanged,
    /// An edge passes the link condition: the output is not irreducible.
    ContractibleEdge,
    /// An output vertex a face uses has no position or a non-finite one, where the task
    /// writes positions.
    InvalidPosition,
    /// An edge shorter than ε passes the link condition of the surface with boundary
    /// (and the geometry guard, when it was on): the simplification stopped early.
    ShortContractibleEdge,
    /// A quad is not two triangles of the paired triangulation split along one of its
    /// diagonals.
    QuadNotTwoTriangles,
    /// A triangle of the paired triangulation is in two or more quads.
    TriangleUsedTwice,
    /// A triangle of the paired triangulation is in no quad.
    TriangleUnused,
    /// A stated pair is not the two triangles of its quad (or the pairs and the quads
    /// differ in number).
    WrongPair,
    /// An input vertex is missing from a stated triangulation that must keep every one.
    MissingVertex,
    /// The output's face count is not one the run's target explains: below it by more
    /// than a collapse, or above it with an edge left that nothing refused.
    TargetMissed,
    /// A stated provenance map contradicts itself, the other map or the faces.
    InconsistentMap,
    /// A step of a stated contraction history is no contraction the link condition
    /// allows on the surface the steps before it left.
    InvalidHistory,
    /// Replaying a stated contraction history does not give the output's faces.
    HistoryMismatch,
}

impl FailureKind {
    /// Every kind, in declaration order.
    pub const ALL: [FailureKind; 24] = [
        FailureKind::VertexOutOfRange,
        FailureKind::DegenerateFace,
        FailureKind::RepeatedFace,
        FailureKind::NonManifoldEdge,
        FailureKind::NonManifoldVertex,
        FailureKind::BoundaryEdge,
        FailureKind::UnknownVertex,
        FailureKind::MovedVertex,
        FailureKind::ComponentsMerged,
        FailureKind::ComponentLost,
        FailureKind::ComponentSplit,
        FailureKind::SurfaceChanged,
        FailureKind::ContractibleEdge,
        FailureKind::InvalidPosition,
        FailureKind::ShortContractibleEdge,
        FailureKind::QuadNotTwoTriangles,
        FailureKind::TriangleUsedTwice,
        FailureKind::TriangleUnused,
        FailureKind::WrongPair,
        FailureKind::MissingVertex,
        FailureKind::TargetMissed,
        FailureKind::InconsistentMap,
        FailureKind::InvalidHistory,
        FailureKind::HistoryMismatch,
    ];

    /// The kind's name in reports (snake case), stable across versions.
    ///
    /// ```
    /// use contractible::check::FailureKind;
    /// assert_eq!(FailureKind::ContractibleEdge.name(), "contractible_edge");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            FailureKind::VertexOutOfRange => "vertex_out_of_range",
            FailureKind::DegenerateFace => "degenerate_face",
            FailureKind::RepeatedFace => "repeated_face",
            FailureKind::NonManifoldEdge => "non_manifold_edge",
            FailureKind::NonManifoldVertex => "non_manifold_vertex",
            FailureKind::BoundaryEdge => "boundary_edge",
            FailureKind::UnknownVertex => "unknown_vertex",
            FailureKind::MovedVertex => "moved_vertex",
            FailureKind::ComponentsMerged => "components_merged",
            FailureKind::ComponentLost => "component_lost",
            FailureKind::ComponentSplit => "component_split",
            FailureKind::SurfaceChanged => "surface_changed",
            FailureKind::ContractibleEdge => "contractible_edge",
            FailureKind::InvalidPosition => "invalid_position",
            FailureKind::ShortContractibleEdge => "short_contractible_edge",
            FailureKind::QuadNotTwoTriangles => "quad_not_two_triangles",
            FailureKind::TriangleUsedTwice => "triangle_used_twice",
            FailureKind::TriangleUnused => "triangle_unused",
            FailureKind::WrongPair => "wrong_pair",
            FailureKind::MissingVertex => "missing_vertex",
            FailureKind::TargetMissed => "target_missed",
            FailureKind::InconsistentMap => "inconsistent_map",
            FailureKind::InvalidHistory => "invalid_history",
            FailureKind::HistoryMismatch => "history_mismatch",
        }
    }
}

/// One reason an output fails, with where (ids of the output file unless said).
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    /// What is wrong.
    pub kind: FailureKind,
    /// A sentence saying what and where.
    pub message: String,
    /// An output face involved.
    pub face: Option<usize>,
    /// An output edge (its ends, smaller first).
    pub edge: Option<[u32; 2]>,
    /// An output vertex.
    pub vertex: Option<u32>,
    /// An input component (numbered by their smallest face).
    pub component: Option<usize>,
}

impl Failure {
    fn new(kind: FailureKind, message: String) -> Self {
        Failure {
            kind,
            message,
            face: None,
            edge: None,
            vertex: None,
            component: None,
        }
    }
    fn face(mut self, f: usize) -> Self {
        self.face = Some(f);
        self
    }
    fn edge(mut self, e: [u32; 2]) -> Self {
        self.edge = Some(e);
        self
    }
    fn vertex(mut self, v: u32) -> Self {
        self.vertex = Some(v);
        self
    }
    fn component(mut self, c: usize) -> Self {
        self.component = Some(c);
        self
    }
}

/// The verdict on one output.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// The task judged.
    pub task: &'static str,
    /// The reasons it fails, at most 20 of a kind, in the order found.
    pub failures: Vec<Failure>,
    /// Per kind found: how many there were (listed or not), in the order first found.
    pub counts: Vec<(FailureKind, usize)>,
}

impl Verdict {
    /// Whether the output is a correct answer.
    pub fn passed(&self) -> bool {
        self.failures.is_empty()
    }

    fn new(task: &'static str) -> Self {
        Verdict {
            task,
            failures: Vec::new(),
            counts: Vec::new(),
        }
    }

    fn fail(&mut self, f: Failure) {
        push(&mut self.failures, &mut self.counts, f);
    }

    /// Adds the reasons `failures` counted in `counts` (as [`surface::analyse`] lists
    /// them: at most `LISTED` of a kind, every one counted).
    fn absorb(&mut self, failures: Vec<Failure>, counts: Vec<(FailureKind, usize)>) {
        for (kind, n) in counts {
            match self.counts.iter_mut().find(|(k, _)| *k == kind) {
                Some((_, m)) => *m += n,
                None => self.counts.push((kind, n)),
            }
        }
        self.failures.extend(failures);
    }
}

/// The reason when no output vertex can be matched to the input's.
fn no_matching(input: &TriMesh, output_vertices: usize) -> Failure {
    Failure::new(
        FailureKind::UnknownVertex,
        format!(
            "the output has {output_vertices} vertices, the input {}, and no positions to match \
             them by",
            input.vertex_count
        ),
    )
}

/// How the output's vertices are the input's.
enum Matching {
    /// The output keeps the input's vertex list: ids are the input's.
    ById,
    /// Per output vertex, the input vertex at its exact position (`u32::MAX`: none).
    ByPosition(Vec<u32>),
}

/// Matches the output's vertices to the input's: by id when the output has as many
/// vertices and the same positions (or neither has positions), else by exact position.
/// Referenced output vertices that match nothing are failures; `None` when no matching
/// is possible at all (counts differ and a side has no positions).
///
/// Several input vertices may share a position (two touching objects, a seam): each
/// output component is then given the input component holding candidates of most of its
/// vertices (one no earlier output component took, on a tie; components with a
/// one-candidate vertex first), and each of its vertices the first candidate in that
/// component no other output vertex took.
fn match_vertices<const N: usize>(
    input: &TriMesh,
    output: &Mesh<N>,
    inp: &Analysis,
    out_parts: &[&[u32]],
    verdict: &mut Verdict,
) -> Option<Matching> {
    let same_list = output.vertex_count == input.vertex_count
        && match (&input.positions, &output.positions) {
            (Some(a), Some(b)) => a.len() == b.len(),
            (None, None) => true,
            _ => false,
        };
    if same_list {
        if let (Some(a), Some(b)) = (&input.positions, &output.positions) {
            for &v in &referenced(output) {
                let (p, q) = (a[v as usize], b[v as usize]);
                // Bit for bit, but −0 and +0 are one position.
                if p.map(|x| (x + 0.0).to_bits()) != q.map(|x| (x + 0.0).to_bits()) {
                    verdict.fail(
                        Failure::new(
                            FailureKind::MovedVertex,
                            format!("output vertex {v} is at {q:?}, input vertex {v} at {p:?}"),
                        )
                        .vertex(v),
                    );
                }
            }
        }
        return Some(Matching::ById);
    }
    let (Some(a), Some(b)) = (&input.positions, &output.positions) else {
        if output.vertex_count <= input.vertex_count {
            // No positions to match: ids are taken as the input's.
            return Some(Matching::ById);
        }
        return None;
    };
    // Input vertices no face uses are candidates only where no used one is.
    let part_of = part_of_vertex(inp, input.vertex_count);
    let bits = |p: [f64; 3]| p.map(|x| (x + 0.0).to_bits());
    let mut at: HashMap<[u64; 3], Vec<u32>> = HashMap::with_capacity(a.len());
    for (i, &p) in a.iter().enumerate() {
        at.entry(bits(p)).or_default().push(i as u32);
    }
    for c in at.values_mut() {
        if c.iter().any(|&i| part_of[i as usize] != usize::MAX) {
            c.retain(|&i| part_of[i as usize] != usize::MAX);
        }
    }
    let candidates = |v: u32| -> &[u32] {
        b.get(v as usize)
            .and_then(|&q| at.get(&bits(q)))
            .map_or(&[], Vec::as_slice)
    };
    let mut order: Vec<usize> = (0..out_parts.len()).collect();
    order.sort_by_key(|&j| !out_parts[j].iter().any(|&v| candidates(v).len() == 1));
    let mut claimed = vec![false; inp.parts.len()];
    let mut taken = vec![false; input.vertex_count];
    let mut map = vec![u32::MAX; output.vertex_count];
    for j in order {
        let mut tally: Vec<(usize, usize)> = Vec::new();
        for &v in out_parts[j] {
            let mut ks: Vec<usize> = candidates(v)
                .iter()
                .map(|&i| part_of[i as usize])
                .filter(|&k| k != usize::MAX)
                .collect();
            ks.sort_unstable();
            ks.dedup();
            for k in ks {
                match tally.iter_mut().find(|(x, _)| *x == k) {
                    Some((_, n)) => *n += 1,
                    None => tally.push((k, 1)),
                }
            }
        }
        let home = tally
            .iter()
            .max_by_key(|&&(k, n)| (n, !claimed[k], std::cmp::Reverse(k)))
            .map(|&(k, _)| k);
        if let Some(k) = home {
            claimed[k] = true;
        }
        for &v in out_parts[j] {
            let c = candidates(v);
            let pick = c
                .iter()
                .copied()
                .find(|&i| Some(part_of[i as usize]) == home && !taken[i as usize])
                .or_else(|| c.iter().copied().find(|&i| !taken[i as usize]))
                .or_else(|| c.first().copied());
            match pick {
                Some(i) => {
                    taken[i as usize] = true;
                    map[v as usize] = i;
                }
                None => verdict.fail(
                    Failure::new(
                        FailureKind::UnknownVertex,
                        format!(
                            "output vertex {v} at {:?} is at no input vertex's position",
                            b.get(v as usize).copied().unwrap_or_default()
                        ),
                    )
                    .vertex(v),
                ),
            }
        }
    }
    Some(Matching::ByPosition(map))
}

/// Per input vertex, its component (`usize::MAX`: no face uses it).
fn part_of_vertex(inp: &Analysis, vertex_count: usize) -> Vec<usize> {
    let mut part_of = vec![usize::MAX; vertex_count];
    for (k, p) in inp.parts.iter().enumerate() {
        for &v in &p.vertices {
            part_of[v as usize] = k;
        }
    }
    part_of
}

/// The output vertices its faces use, increasing.
fn referenced<const N: usize>(mesh: &Mesh<N>) -> Vec<u32> {
    let mut used = vec![false; mesh.vertex_count];
    for f in &mesh.faces {
        for &v in f {
            if let Some(u) = used.get_mut(v as usize) {
                *u = true;
            }
        }
    }
    (0..mesh.vertex_count as u32)
        .filter(|&v| used[v as usize])
        .collect()
}

/// The input analysed as a task input: a surface, possibly with boundary (the core's
/// build locates a defect as every task reports it).
fn surface_input(input: &TriMesh, task: &'static str) -> Result<Analysis, Error> {
    analyse(input.vertex_count, &input.faces, "input").map_err(|(failures, _)| {
        // The reader's build locates the defect as every task reports it.
        match crate::ConedSurfaces::from_mesh(input) {
            Err(e) => Error::Mesh(e),
            Ok(_) => Error::BadOption {
                option: "input",
                value: failures
                    .first()
                    .map_or_else(String::new, |f| f.message.clone()),
                expected: format!("a surface ({task} input)"),
            },
        }
    })
}

/// The input analysed as a task input: a closed surface for `reduce`.
fn closed_input(input: &TriMesh, task: &'static str) -> Result<Analysis, Error> {
    let a = surface_input(input, task)?;
    if let Some(&((x, y), _, f)) = a.edges.iter().find(|(_, o, _)| o[1] == u32::MAX) {
        return Err(Error::NotClosed {
            task,
            a: x,
            b: y,
            face: f as usize,
            boundary_loops: Some(a.parts.iter().map(|p| p.boundary_loops).sum()),
        });
    }
    Ok(a)
}

/// The face-list analysis of `output`; `None`, with the reasons in `verdict`, when its
/// faces are no surface (the later checks would only restate them).
fn output_surface(output: &TriMesh, verdict: &mut Verdict) -> Option<Analysis> {
    match analyse(output.vertex_count, &output.faces, "output") {
        Ok(a) => Some(a),
        Err((failures, counts)) => {
            verdict.failures = failures;
            verdict.counts = counts;
            None
        }
    }
}

/// Judges `output` as an irreducible triangulation of `input` (the task `reduce`): see
/// the [module](self) for what is checked.
///
/// # Errors
/// [`Error::NotClosed`] or [`Error::Mesh`] (locating the first defect) when `input` is
/// not a closed surface, which `reduce` must refuse.
///
/// # Example
/// ```
/// use contractible::{check, gen, reduce};
/// let sphere = gen::icosahedron();
/// let ours = reduce(&sphere, &Default::default())?;
/// assert!(check::reduce(&sphere, &ours.mesh)?.passed());
/// // The input itself is not irreducible: its edges pass the link condition.
/// let verdict = check::reduce(&sphere, &sphere)?;
/// assert!(!verdict.passed());
/// assert_eq!(verdict.failures[0].kind, check::FailureKind::ContractibleEdge);
/// # Ok::<(), contractible::Error>(())
/// ```
pub fn reduce(input: &TriMesh, output: &TriMesh) -> Result<Verdict, Error> {
    Ok(reduce_verdict(input, output)?.0)
}

/// Judges `output` as an irreducible triangulation of `input` reached by the stated
/// contractions: everything [`reduce`] checks, and each step `[u, v]` of `history`
/// (contract `v` into `u`, input vertex ids, oldest first) is valid in turn and the replay
/// gives the output. A step is valid when `u` and `v` are distinct vertices of the surface
/// the earlier steps left, `uv` is one of its edges and passes the link condition (read
/// off the faces: the ends' only common neighbours are the two opposite vertices, and the
/// surface there is no tetrahedron); the first invalid step is reported
/// ([`FailureKind::InvalidHistory`]) and ends the replay. After a whole replay, each face
/// of the replayed surface or of the output (in input ids) that is not in the other is a
/// [`FailureKind::HistoryMismatch`]. The contractions of [`crate::reduce`]'s result are
/// [`crate::ReduceResult::contractions`].
///
/// **Complexity.** [`reduce`]'s, plus O(F log F) and, per step, the faces at its two
/// ends.
///
/// # Errors
/// As [`reduce`]'s.
///
/// # Example
/// ```
/// use contractible::{check, gen, reduce};
/// let sphere = gen::icosahedron();
/// let ours = reduce(&sphere, &Default::default())?;
/// let history = ours.contractions();
/// assert_eq!(history.len(), 8); // 12 vertices down to the tetrahedron's 4
/// assert!(check::reduce_history(&sphere, &ours.mesh, &history)?.passed());
/// // Stopping one step short leaves a face the output does not have.
/// let verdict = check::reduce_history(&sphere, &ours.mesh, &history[..7])?;
/// assert_eq!(verdict.failures[0].kind, check::FailureKind::HistoryMismatch);
/// # Ok::<(), contractible::Error>(())
/// ```
pub fn reduce_history(
    input: &TriMesh,
    output: &TriMesh,
    history: &[[u32; 2]],
) -> Result<Verdict, Error> {
    let (mut verdict, faces) = reduce_verdict(input, output)?;
    let Some(end) = history::replay(input.vertex_count, &input.faces, history, &mut verdict) else {
        return Ok(verdict);
    };
    // An output on the survivors renumbered in increasing input order (as `reduce`
    // writes it) is read so, positions agreeing: by position alone, input vertices that
    // share one (a mesh without geometry) could not be told apart.
    let same_positions = |v: usize, i: u32| match (&output.positions, &input.positions) {
        (Some(p), Some(q)) => {
            let bits = |x: Option<&[f64; 3]>| x.map(|x| x.map(|c| (c + 0.0).to_bits()));
            bits(p.get(v)).is_some() && bits(p.get(v)) == bits(q.get(i as usize))
        }
        (None, None) => true,
        _ => false,
    };
    let by_survivors = output.vertex_count == end.survivors.len()
        && output.vertex_count != input.vertex_count
        && (end.survivors.iter().enumerate()).all(|(v, &i)| same_positions(v, i));
    let faces = if by_survivors {
        (output.faces.iter())
            .map(|f| f.map(|v| end.survivors.get(v as usize).copied()))
            .map(|[a, b, c]| Some([a?, b?, c?]))
            .collect()
    } else {
        faces
    };
    if let Some(faces) = faces {
        history::compare(&end.faces, &faces, history.len(), &mut verdict);
    }
    Ok(verdict)
}

/// Faces in input vertex ids.
type InputFaces = Vec<[u32; 3]>;

/// [`reduce`]'s verdict, and the output's faces in input ids when every vertex they use
/// is matched to an input vertex.
fn reduce_verdict(
    input: &TriMesh,
    output: &TriMesh,
) -> Result<(Verdict, Option<InputFaces>), Error> {
    let inp = closed_input(input, "reduce")?;
    let mut verdict = Verdict::new("reduce");
    let Some(out) = output_surface(output, &mut verdict) else {
        return Ok((verdict, None));
    };
    for &((a, b), _, f) in out.edges.iter().filter(|(_, o, _)| o[1] == u32::MAX) {
        verdict.fail(
            Failure::new(
                FailureKind::BoundaryEdge,
                format!("output edge [{a}, {b}] is in one face only (face {f})"),
            )
            .face(f as usize)
            .edge([a, b]),
        );
    }
    if !verdict.passed() {
        // Not closed: the surface checks below would only restate it.
        return Ok((verdict, None));
    }
    let out_parts: Vec<&[u32]> = out.parts.iter().map(|p| p.vertices.as_slice()).collect();
    let Some(matching) = match_vertices(input, output, &inp, &out_parts, &mut verdict) else {
        verdict.fail(no_matching(input, output.vertex_count));
        return Ok((verdict, None));
    };
    let to_input = |v: u32| -> Option<u32> {
        match &matching {
            Matching::ById => (v < input.vertex_count as u32).then_some(v),
            Matching::ByPosition(m) => m.get(v as usize).copied().filter(|&i| i != u32::MAX),
        }
    };
    let by_id = matches!(matching, Matching::ById);
    same_components(input, &inp, &out, &to_input, by_id, false, &mut verdict);
    contractible_edges(&out, &mut verdict);
    let faces: Option<InputFaces> = (output.faces.iter())
        .map(|f| {
            let [a, b, c] = f.map(&to_input);
            Some([a?, b?, c?])
        })
        .collect();
    Ok((verdict, faces))
}

/// Compares the components of `out` with those of `inp` through `to_input` (an output
/// vertex's input vertex): each output component within one input component
/// (`components_merged`), one per input component (`component_lost`, `component_split`),
/// of its surface (`surface_changed`: χ and orientability, and the boundary loops when
/// `loops`). `by_id`: an output vertex with no input vertex is beyond the input's list
/// (by position, the matching has already reported it).
fn same_components(
    input: &TriMesh,
    inp: &Analysis,
    out: &Analysis,
    to_input: &dyn Fn(u32) -> Option<u32>,
    by_id: bool,
    loops: bool,
    verdict: &mut Verdict,
) {
    let part_of_vertex = part_of_vertex(inp, input.vertex_count);
    // Each output component lies in one input component of the same surface.
    let mut outputs_of: Vec<Vec<usize>> = vec![Vec::new(); inp.parts.len()];
    for (j, q) in out.parts.iter().enumerate() {
        let mut parts: Vec<usize> = Vec::new();
        for &v in &q.vertices {
            match to_input(v).map(|i| part_of_vertex[i as usize]) {
                Some(k) if k != usize::MAX => parts.push(k),
                Some(_) => {
                    verdict.fail(
                        Failure::new(
                            FailureKind::UnknownVertex,
                            format!("output vertex {v} is an input vertex no input face uses"),
                        )
                        .vertex(v),
                    );
                }
                None => {
                    if by_id {
                        verdict.fail(
                            Failure::new(
                                FailureKind::UnknownVertex,
                                format!("output vertex {v} is beyond the input's vertices"),
                            )
                            .vertex(v),
                        );
                    }
                }
            }
        }
        parts.sort_unstable();
        parts.dedup();
        if parts.len() > 1 {
            verdict.fail(
                Failure::new(
                    FailureKind::ComponentsMerged,
                    format!(
                        "the output component of face {} joins input components {parts:?}",
                        q.first_face
                    ),
                )
                .face(q.first_face)
                .component(parts[0]),
            );
        } else if let Some(&k) = parts.first() {
            // Unknown vertices aside, the component is this input component's.
            outputs_of[k].push(j);
        }
    }
    for (k, p) in inp.parts.iter().enumerate() {
        match outputs_of[k].as_slice() {
            [] => verdict.fail(
                Failure::new(
                    FailureKind::ComponentLost,
                    format!(
                        "input component {k} (of face {}) has no output component",
                        p.first_face
                    ),
                )
                .component(k),
            ),
            [j] => {
                let q = &out.parts[*j];
                if surface_of(q, loops) != surface_of(p, loops) {
                    verdict.fail(
                        Failure::new(
                            FailureKind::SurfaceChanged,
                            format!(
                                "input component {k}: {}, its output (of face {}): {}",
                                surface_name(p, loops),
                                q.first_face,
                                surface_name(q, loops)
                            ),
                        )
                        .face(q.first_face)
                        .component(k),
                    );
                }
            }
            many => verdict.fail(
                Failure::new(
                    FailureKind::ComponentSplit,
                    format!(
                        "input component {k} has {} output components (of faces {:?})",
                        many.len(),
                        many.iter()
                            .map(|&j| out.parts[j].first_face)
                            .collect::<Vec<_>>()
                    ),
                )
                .component(k),
            ),
        }
    }
}

/// A component's surface: χ, orientability and, when `loops`, boundary loops.
fn surface_of(p: &Part, loops: bool) -> (i64, bool, usize) {
    (
        p.euler(),
        p.orientable,
        if loops { p.boundary_loops } else { 0 },
    )
}

/// "χ 2 orientable" (", 1 boundary loop(s)" added when `loops`).
fn surface_name(p: &Part, loops: bool) -> String {
    let mut s = format!("χ {} {}", p.euler(), orientable_name(p.orientable));
    if loops {
        let b = p.boundary_loops;
        s.push_str(&format!(
            ", {b} boundary loop{}",
            if b == 1 { "" } else { "s" }
        ));
    }
    s
}

/// Judges `output` as a simplification of `input` (the task `simplify`) by a run with
/// the ε and options of `options`: see the [module](self) for what is checked. Flags
/// only what no correct run could have produced: topology changed, or a short edge left
/// that the run had to contract.
///
/// # Errors
/// As `simplify` refuses its input: [`Error::BadOption`] for an ε that is not a finite
/// number > 0 (or a relative one that gives none), [`Error::MissingPositions`],
/// [`Error::PositionCount`], [`Error::NonFiniteCoordinate`], [`Error::NoCoordinates`],
/// and [`Error::Mesh`] (locating the first defect) for faces that are no surface.
///
/// # Example
/// ```
/// use contractible::{check, gen, simplify, SimplifyOptions};
/// let sphere = gen::isosurface(&gen::IsoParams::new(
///     gen::Implicit::Sphere { radius: 1.0 },
///     gen::Tessellation::SixTetrahedra,
///     12,
/// ))?;
/// let ours = simplify(&sphere, &SimplifyOptions::relative(0.1))?;
/// let options = check::SimplifyCheck::relative(0.1);
/// assert!(check::simplify(&sphere, &ours.mesh, &options)?.passed());
/// // The input itself has short edges it could still contract.
/// let verdict = check::simplify(&sphere, &sphere, &options)?;
/// assert!(!verdict.passed());
/// assert_eq!(verdict.failures[0].kind, check::FailureKind::ShortContractibleEdge);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn simplify(
    input: &TriMesh,
    output: &TriMesh,
    options: &SimplifyCheck,
) -> Result<Verdict, Error> {
    simplify_check::check(input, output, options)
}

/// Judges `output` as a tri-quad conversion of `input` (the task `quad`) with what the
/// answer states besides its quads (`stated`: the paired triangulation K, when edges
/// were flipped, and the pairs): every quad is two triangles of K split along one of
/// its diagonals (the pair stated for it, when pairs are given), every triangle of K in
/// exactly one quad, and K (when stated) a closed surface on the input's vertices with
/// the input's surface per component (χ, orientability). Output vertices are matched to
/// the input's as for [`reduce`]. The quad mesh is then a closed polygon surface of the
/// input's χ per component (see `spec/conformance.md`).
///
/// # Errors
/// [`Error::NotClosed`] or [`Error::Mesh`] (locating the first defect) when `input` is
/// not a closed surface, which the conversion must refuse.
///
/// # Example
/// ```
/// use contractible::{check, gen, quadrangulate, QuadOptions};
/// let sphere = gen::icosahedron();
/// let ours = quadrangulate(&sphere, &QuadOptions::default())?;
/// let stated = check::QuadCheck {
///     triangles: Some(&ours.triangles),
///     pairs: Some(&ours.pairs),
/// };
/// assert!(check::quad(&sphere, &ours.mesh, &stated)?.passed());
/// // A quad given twice pairs its triangles twice and leaves two others unpaired.
/// let mut wrong = ours.mesh.clone();
/// wrong.faces[1] = wrong.faces[0];
/// let k_only = check::QuadCheck { triangles: Some(&ours.triangles), pairs: None };
/// let verdict = check::quad(&sphere, &wrong, &k_only)?;
/// assert!(!verdict.passed());
/// assert_eq!(verdict.failures[0].kind, check::FailureKind::TriangleUsedTwice);
/// # Ok::<(), contractible::Error>(())
/// ```
pub fn quad(input: &TriMesh, output: &QuadMesh, stated: &QuadCheck<'_>) -> Result<Verdict, Error> {
    quad_check::check(input, output, stated)
}

/// Judges `output` as a decimation of `input` (the task `decimate`) by a run with the
/// target and options of `options`, and its provenance maps where stated: a surface
/// (boundary allowed) with a finite position per used vertex, of the input's surface per
/// component (χ, orientability, boundary loops; by the stated `vertex_map`, or by id
/// when the output keeps the input's vertex list, else as multisets of surface types);
/// the maps consistent with each other and with the faces (every output vertex's input
/// vertices joined by input edges, every output face its origin renamed, every other
/// input face degenerate); locked vertices where they were; under
/// [`Placement::Endpoint`](crate::decimate::Placement) every position an input
/// position; and a face count the target explains: at least the target less one
/// collapse's faces, and above the target only when, for a run without guard or cap,
/// no unlocked edge passes the link condition of the surface with boundary.
///
/// # Errors
/// As `decimate` refuses its input: [`Error::MissingPositions`],
/// [`Error::PositionCount`], [`Error::NonFiniteCoordinate`], [`Error::NoCoordinates`],
/// [`Error::Mesh`] for faces that are no surface, and [`Error::BadOption`] for a `keep`
/// outside [0, 1] or a locked vertex that is no input vertex.
///
/// # Example
/// ```
/// use contractible::{check, decimate, gen, DecimateOptions};
/// let sphere = gen::subdivide(&gen::icosahedron(), 2)?;
/// let ours = decimate(&sphere, &DecimateOptions::keep(0.25))?;
/// let options = check::DecimateCheck {
///     keep: Some(0.25),
///     vertex_map: Some(&ours.vertex_map),
///     collapse_map: Some(&ours.collapse_map),
///     face_origin: Some(&ours.face_origin),
///     ..Default::default()
/// };
/// assert!(check::decimate(&sphere, &ours.mesh, &options)?.passed());
/// // The input is no answer: it has four times the faces asked for... and is
/// // judged so once the run's guard is known to be off.
/// let unguarded = check::DecimateCheck { keep: Some(0.25), allow_foldover: true, ..Default::default() };
/// let verdict = check::decimate(&sphere, &sphere, &unguarded)?;
/// assert_eq!(verdict.failures[0].kind, check::FailureKind::TargetMissed);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn decimate(
    input: &TriMesh,
    output: &TriMesh,
    options: &DecimateCheck<'_>,
) -> Result<Verdict, Error> {
    decimate_check::check(input, output, options)
}

fn orientable_name(o: bool) -> &'static str {
    if o {
        "orientable"
    } else {
        "non-orientable"
    }
}

/// Every closed edge whose ends have no common neighbour besides its two opposite
/// vertices passes the link condition (on a closed surface the two are the same), unless
/// its component is the tetrahedron, where contracting any edge leaves two faces on three
/// vertices.
fn contractible_edges(out: &Analysis, verdict: &mut Verdict) {
    for &((a, b), opposite, f) in &out.edges {
        if opposite[1] == u32::MAX {
            continue;
        }
        let part = &out.parts[out.part_of_face[f as usize]];
        if part.vertices.len() == 4 && part.faces == 4 {
            continue;
        }
        if out.other_common_neighbour(a, b, opposite).is_none() {
            verdict.fail(
                Failure::new(
                    FailureKind::ContractibleEdge,
                    format!(
                        "output edge [{a}, {b}] passes the link condition (common neighbours \
                         only {} and {}): the output is not irreducible",
                        opposite[0], opposite[1]
                    ),
                )
                .face(f as usize)
                .edge([a, b]),
            );
        }
    }
}

#[cfg(test)]
mod decimate_tests;
#[cfg(test)]
mod history_tests;
#[cfg(test)]
mod quad_tests;
#[cfg(test)]
mod simplify_tests;
#[cfg(test)]
mod tests;
