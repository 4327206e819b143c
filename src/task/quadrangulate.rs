//! [`quadrangulate`]: a quad mesh on the same vertices, by a perfect pairing of the
//! triangles of every component.

use crate::core::{FaceId, Triangulation, VertexId};
use crate::mesh::{QuadMesh, TriMeshRef};
use crate::quad::{self, Algorithm, Quadrangulation, DS_NAIVE_MAX_FACES};
use crate::topology::SurfaceType;

use super::reduce::{closed_surfaces, position_count};
use super::{Error, Monitor, Step};

/// Options of [`quadrangulate`]. The default: LRS, seed 0, outputs verified.
#[derive(Clone, Debug)]
pub struct QuadOptions {
    /// The algorithm.
    pub algorithm: Algorithm,
    /// Seed of the documented random stream ([`crate::rng`]) for the randomised orders
    /// of SG and PS.
    pub seed: u64,
    /// Check every pairing independently (the checks of [`verify_quadrangulation`], with
    /// the input's faces read from the mesh) and fail with [`Error::Unverified`] if one
    /// is wrong.
    pub verify: bool,
    /// Run the components on rayon's current thread pool (the crate's `parallel`
    /// feature; ignored without it). The result is the sequential run's, errors
    /// included; only the order of the monitor's events differs.
    pub parallel: bool,
    /// Progress and cancellation.
    pub monitor: Monitor,
}

impl Default for QuadOptions {
    fn default() -> Self {
        QuadOptions {
            algorithm: Algorithm::default(),
            seed: 0,
            verify: true,
            parallel: false,
            monitor: Monitor::default(),
        }
    }
}

/// Counters of one conversion (one component, or the totals): the paper's Table 4.3
/// columns (a)–(e) plus the work of each step. The fields are the command line's
/// `quad --json` keys.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct QuadStats {
    /// The algorithm.
    #[cfg_attr(feature = "serde", serde(rename = "algo"))]
    pub algorithm: Algorithm,
    /// Triangles of the input.
    pub faces: usize,
    /// Quads of the output (half the triangles).
    pub quads: usize,
    /// χ of the input (summed in the totals).
    pub euler_characteristic: i64,
    /// Whether the input is orientable (every component, in the totals).
    pub orientable: bool,
    /// (a) Seconds of the initial pairing.
    pub initial_seconds: f64,
    /// (b) Percentage of the triangles paired by the initial step.
    pub initial_paired_percent: f64,
    /// (c) Triangles left unpaired by the initial step.
    pub initial_unpaired: usize,
    /// (d) Seconds of the completion.
    pub completion_seconds: f64,
    /// (e) Total seconds.
    pub total_seconds: f64,
    /// Edge flips (LRS only).
    pub flips: usize,
    /// Augmenting paths applied by the completion.
    pub augmenting_paths: usize,
    /// Searches of the completion (the maximum over components in the totals).
    pub phases: usize,
    /// Whether the independent check passed (`true` also when not checked: see
    /// [`QuadOptions::verify`]).
    pub verified: bool,
}

impl QuadStats {
    /// The counters of `q`, the conversion of a surface of type `input`.
    pub fn of(q: &Quadrangulation, input: SurfaceType, verified: bool) -> Self {
        let s = &q.stats;
        QuadStats {
            algorithm: q.algorithm,
            faces: s.faces,
            quads: q.pairing.len(),
            euler_characteristic: input.euler_characteristic(),
            orientable: input.is_orientable(),
            initial_seconds: s.initial_seconds,
            initial_paired_percent: s.initial_paired_percent,
            initial_unpaired: s.initial_unpaired,
            completion_seconds: s.completion_seconds,
            total_seconds: s.total_seconds,
            flips: s.flips,
            augmenting_paths: s.augmenting_paths,
            phases: s.phases,
            verified,
        }
    }

    /// The totals of `parts`.
    pub fn total(algorithm: Algorithm, parts: &[QuadStats]) -> Self {
        let sum = |f: fn(&QuadStats) -> usize| parts.iter().map(f).sum::<usize>();
        let sumf = |f: fn(&QuadStats) -> f64| parts.iter().map(f).sum::<f64>();
        let faces = sum(|p| p.faces);
        let unpaired = sum(|p| p.initial_unpaired);
        QuadStats {
            algorithm,
            faces,
            quads: sum(|p| p.quads),
            euler_characteristic: parts.iter().map(|p| p.euler_characteristic).sum(),
            orientable: parts.iter().all(|p| p.orientable),
            initial_seconds: sumf(|p| p.initial_seconds),
            initial_paired_percent: if faces == 0 {
                100.0
            } else {
                100.0 * (faces - unpaired) as f64 / faces as f64
            },
            initial_unpaired: unpaired,
            completion_seconds: sumf(|p| p.completion_seconds),
            total_seconds: sumf(|p| p.total_seconds),
            flips: sum(|p| p.flips),
            augmenting_paths: sum(|p| p.augmenting_paths),
            phases: parts.iter().map(|p| p.phases).max().unwrap_or(0),
            verified: parts.iter().all(|p| p.verified),
        }
    }
}

/// One component's conversion counters.
#[derive(Clone, Debug)]
pub struct QuadComponent {
    /// Counters and the verdict of the check.
    pub stats: QuadStats,
}

/// What [`quadrangulate`] returns.
#[derive(Clone, Debug)]
pub struct QuadResult {
    /// The quads over the input's vertices (the same `vertex_count`, the input's
    /// positions): per component, one quad per pair in increasing order of the pair's
    /// smaller face, each the cycle `[c, a, d, b]` around its two triangles
    /// ([`quad::quad_of`]), so consistently oriented triangles give consistently oriented
    /// quads.
    pub mesh: QuadMesh,
    /// The paired triangulation `K`, one row per input face: the input's faces, except
    /// that LRS's flips changed some (same vertices, same face count).
    pub triangles: Vec<[u32; 3]>,
    /// The pairs, as rows of `triangles` (input face indices), in the order of the quads.
    pub pairs: Vec<[u32; 2]>,
    /// Per component, in the order of their smallest input face.
    pub components: Vec<QuadComponent>,
    /// The totals.
    pub totals: QuadStats,
    /// Input vertices no face uses (kept in `mesh`, used by no quad).
    pub dropped_vertices: usize,
    /// Seconds validating the input and splitting it into components.
    pub seconds_build: f64,
    /// Seconds of the independent check (`None` when not checked).
    pub seconds_verify: Option<f64>,
}

/// The independent check of a conversion of `input`: `K` is `input` itself (the same
/// arrays: every algorithm but LRS leaves the triangulation as it was, and `input` was
/// validated when it was built), or `K` validates from scratch and has the input's
/// vertex set, counts and surface type; and the pairing is perfect with every pair
/// sharing an edge of `K` (checked on `K`'s face lists, not by the pairing's own
/// bookkeeping).
pub fn verify_quadrangulation(input: &Triangulation, q: &Quadrangulation) -> bool {
    let k = &q.tri;
    let same_surface = *k == *input
        || (k.vertex_count() == input.vertex_count()
            && same_surface_from_scratch(
                k,
                input.vertices(),
                input.face_count(),
                SurfaceType::of(input),
            ));
    same_surface && pairs_share_edges(q)
}

/// `k` validates from scratch and has the vertices `vertices`, `faces` faces and the
/// surface type `surface`.
fn same_surface_from_scratch(
    k: &Triangulation,
    vertices: impl Iterator<Item = VertexId>,
    faces: usize,
    surface: SurfaceType,
) -> bool {
    k.validate().is_ok()
        && k.face_count() == faces
        && k.vertices().eq(vertices)
        && SurfaceType::of(k) == surface
}

/// `q`'s pairing is perfect on its triangulation `K` and the two faces of every pair
/// share two vertices in `K`'s face lists (so, in a valid triangulation, an edge).
fn pairs_share_edges(q: &Quadrangulation) -> bool {
    let k = &q.tri;
    if 2 * q.pairing.len() != k.face_count() {
        return false;
    }
    let mut seen = vec![false; k.face_capacity()];
    for (f, g) in q.pairing.pairs() {
        if !k.is_face(f) || !k.is_face(g) || seen[f.index()] || seen[g.index()] {
            return false;
        }
        seen[f.index()] = true;
        seen[g.index()] = true;
        let (a, b) = (k.face_vertices(f), k.face_vertices(g));
        if a.iter().filter(|v| b.contains(v)).count() != 2 {
            return false;
        }
    }
    true
}

/// What the task keeps of a component while its triangulation is converted (the
/// triangulation itself is handed to the algorithm, not copied): where its vertices and
/// faces come from in the mesh, and its surface type.
struct Origin {
    vertex_origin: Vec<u32>,
    face_origin: Vec<u32>,
    surface: SurfaceType,
}

/// [`verify_quadrangulation`] for a component of `mesh` converted without a copy of its
/// triangulation: `K`'s faces are the mesh's faces of the component (through the
/// origins; the mesh was validated when the component was built from it), or `K`
/// validates from scratch and has the component's vertices, face count and surface type;
/// and the pairing is perfect with every pair sharing an edge of `K`. The task's output
/// (quads, triangles, pairs) is read from `K`'s face lists and the pairing alone, which
/// is what this checks.
fn verify_component(mesh: TriMeshRef<'_>, origin: &Origin, q: &Quadrangulation) -> bool {
    let k = &q.tri;
    let (n, m) = (origin.vertex_origin.len(), origin.face_origin.len());
    let faces_unchanged = k.face_capacity() == m
        && k.face_count() == m
        && origin.face_origin.iter().enumerate().all(|(f, &g)| {
            let got = k
                .face_vertices(FaceId(f as u32))
                .map(|v| origin.vertex_origin.get(v.index()).copied());
            mesh.faces.get(g as usize).map(|w| w.map(Some)) == Some(got)
        });
    let same_surface = faces_unchanged
        || same_surface_from_scratch(k, (0..n as u32).map(VertexId), m, origin.surface);
    same_surface && pairs_share_edges(q)
}

/// The quad of two triangles `f` and `g` sharing an edge, from their vertex lists:
/// `[c, a, d, b]` where `f = (c, a, b)` in slot order from `c`, its vertex not in `g`,
/// and `d` is `g`'s vertex not in `f` ([`quad::quad_of`]'s quad, without the
/// triangulation's adjacency). `None` if they share no two vertices.
fn quad_of_faces(f: [u32; 3], g: [u32; 3]) -> Option<[u32; 4]> {
    let k = (0..3).find(|&i| !g.contains(&f[i]))?;
    let d = *g.iter().find(|v| !f.contains(v))?;
    (f.iter().filter(|v| g.contains(v)).count() == 2).then_some([
        f[k],
        f[(k + 1) % 3],
        d,
        f[(k + 2) % 3],
    ])
}

/// A quad mesh on the vertices of `mesh`, a union of closed surfaces (orientable or
/// not): a perfect pairing of edge-adjacent triangles of every component by
/// `options.algorithm` (one always exists: Petersen), each pair a quad. Only LRS changes
/// the triangulation, by flips ([`QuadResult::triangles`]). Every pairing is checked
/// independently unless `options.verify` is off.
///
/// Deterministic for a given mesh and options (timings aside).
///
/// # Errors
/// [`Error::PositionCount`] if `mesh` has positions but not one per vertex (checked
/// first); [`Error::Mesh`] or [`Error::NotClosed`] if `mesh` is not a union of closed
/// surfaces;
/// [`Error::TooLarge`] for `ds-naive` on a component above [`DS_NAIVE_MAX_FACES`]
/// faces, and for `ds` and `bbdl` above their structures' limits; [`Error::Cancelled`];
/// [`Error::Unverified`] if a pairing fails its check (a defect of the library).
///
/// # Example
/// ```
/// let octahedron = contractible::gen::octahedron();
/// let q = contractible::quadrangulate(&octahedron, &Default::default())?;
/// assert_eq!(q.mesh.faces.len(), 4);
/// # Ok::<(), contractible::Error>(())
/// ```
pub fn quadrangulate<'a>(
    mesh: impl Into<TriMeshRef<'a>>,
    options: &QuadOptions,
) -> Result<QuadResult, Error> {
    let mesh: TriMeshRef<'a> = mesh.into();
    let monitor = &options.monitor;
    let algorithm = options.algorithm;
    position_count(mesh)?;
    let started = std::time::Instant::now();
    let surfaces = closed_surfaces(mesh, "quad", monitor)?;
    let seconds_build = started.elapsed().as_secs_f64();
    let n = surfaces.components.len();
    if algorithm == Algorithm::DsNaive {
        // O(F²): about F²/4 node visits, minutes beyond this size.
        if let Some((component, c)) = surfaces
            .components
            .iter()
            .enumerate()
            .find(|(_, c)| c.tri.face_count() > DS_NAIVE_MAX_FACES)
        {
            return Err(Error::TooLarge {
                algorithm,
                component,
                faces: c.tri.face_count(),
                limit: DS_NAIVE_MAX_FACES,
            });
        }
    }
    let qopts = quad::Options { seed: options.seed };
    let items = surfaces
        .components
        .into_iter()
        .map(|c| (c.tri.face_count(), c))
        .collect();
    // Each component's triangulation is moved into its algorithm: the check reads the
    // input's faces from the mesh instead of from a copy (28 bytes a triangle).
    let done = monitor.each_component(Step::Run, options.parallel, items, |i, c, observer| {
        let origin = Origin {
            surface: SurfaceType::of(&c.tri),
            vertex_origin: c.vertex_origin,
            face_origin: c.face_origin,
        };
        match quad::convert_observed(c.tri, algorithm, &qopts, observer) {
            Ok(q) => Ok((origin, q)),
            Err(quad::ConvertError::TooLarge { faces, limit, .. }) => Err(Error::TooLarge {
                algorithm,
                component: i,
                faces,
                limit,
            }),
            Err(source) => Err(Error::Convert {
                component: i,
                source,
            }),
        }
    })?;
    let mut verdicts = vec![true; n];
    let mut seconds_verify = None;
    if options.verify {
        let started = std::time::Instant::now();
        let items = done
            .iter()
            .map(|(origin, q)| (q.tri.face_count(), (origin, q)))
            .collect();
        verdicts = monitor.each_component(
            Step::Verify,
            options.parallel,
            items,
            |_, (origin, q), _| Ok(verify_component(mesh, origin, q)),
        )?;
        seconds_verify = Some(started.elapsed().as_secs_f64());
        let bad: Vec<usize> = (0..n).filter(|&i| !verdicts[i]).collect();
        if !bad.is_empty() {
            return Err(Error::Unverified {
                task: "quad",
                components: bad,
                detail: "not a perfect pairing of adjacent faces of a valid triangulation \
                         with the input's vertices and topology"
                    .into(),
            });
        }
    }
    let mut quads: Vec<[u32; 4]> = Vec::with_capacity(mesh.faces.len() / 2);
    let mut pairs: Vec<[u32; 2]> = Vec::with_capacity(mesh.faces.len() / 2);
    let mut triangles = mesh.faces.to_vec();
    let mut components = Vec::with_capacity(n);
    for ((origin, q), ok) in done.iter().zip(verdicts) {
        // The rows of `K` first, in mesh ids; each quad is then read from its pair's rows.
        for f in q.tri.faces() {
            triangles[origin.face_origin[f.index()] as usize] = q
                .tri
                .face_vertices(f)
                .map(|v| origin.vertex_origin[v.index()]);
        }
        for (f, g) in q.pairing.pairs() {
            let pair = [origin.face_origin[f.index()], origin.face_origin[g.index()]];
            let Some(quad) =
                quad_of_faces(triangles[pair[0] as usize], triangles[pair[1] as usize])
            else {
                return Err(Error::Unverified {
                    task: "quad",
                    components: vec![components.len()],
                    detail: format!("pair {f}, {g} shares no edge"),
                });
            };
            quads.push(quad);
            pairs.push(pair);
        }
        components.push(QuadComponent {
            stats: QuadStats::of(q, origin.surface, ok),
        });
    }
    let stats: Vec<QuadStats> = components.iter().map(|c| c.stats.clone()).collect();
    Ok(QuadResult {
        mesh: QuadMesh {
            vertex_count: mesh.vertex_count,
            positions: mesh.positions.map(<[_]>::to_vec),
            faces: quads,
        },
        triangles,
        pairs,
        totals: QuadStats::total(algorithm, &stats),
        components,
        dropped_vertices: surfaces.dropped_vertices.len(),
        seconds_build,
        seconds_verify,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen;
    use crate::TriMesh;

    /// Every algorithm on two components with positions: the quads carry the input's
    /// positions, cover each input triangle exactly once (by the pairs), and each quad is
    /// the union of its pair's triangles, checked from the face lists alone.
    #[test]
    fn every_algorithm_gives_quads_with_positions_on_every_component() {
        let mut faces = gen::icosahedron().faces;
        faces.extend(gen::torus7().faces.iter().map(|f| f.map(|v| v + 12)));
        let positions: Vec<[f64; 3]> = (0..19).map(|i| [i as f64, 0.5 * i as f64, 1.0]).collect();
        let mesh = TriMesh::with_positions(positions.clone(), faces);
        for algorithm in Algorithm::ALL {
            let q = quadrangulate(
                &mesh,
                &QuadOptions {
                    algorithm,
                    seed: 3,
                    ..QuadOptions::default()
                },
            )
            .expect("closed surfaces");
            assert_eq!(q.mesh.positions.as_deref(), Some(&positions[..]));
            assert_eq!(q.mesh.faces.len(), mesh.faces.len() / 2, "{algorithm}");
            assert_eq!(q.components.len(), 2);
            let mut covered = vec![0; mesh.faces.len()];
            for (quad, [f, g]) in q.mesh.faces.iter().zip(&q.pairs) {
                covered[*f as usize] += 1;
                covered[*g as usize] += 1;
                let mut a: Vec<u32> = q.triangles[*f as usize]
                    .iter()
                    .chain(&q.triangles[*g as usize])
                    .copied()
                    .collect();
                a.sort_unstable();
                a.dedup();
                let mut b = quad.to_vec();
                b.sort_unstable();
                assert_eq!(a, b, "{algorithm}");
            }
            assert!(covered.iter().all(|&c| c == 1), "{algorithm}");
        }
    }

    /// A torus and a Klein bottle with the same numbers of vertices and faces.
    fn torus_and_klein() -> (Triangulation, Triangulation) {
        use crate::gen::random::{random, RandomParams, SurfaceKind};
        let surface = |surface| {
            random(&RandomParams {
                surface,
                min_faces: 200,
                flip_percent: 50,
                seed: 5,
            })
            .expect("a random surface")
        };
        let pair = (
            surface(SurfaceKind::Orientable(1)),
            surface(SurfaceKind::NonOrientable(2)),
        );
        assert_eq!(
            (pair.0.vertex_count(), pair.0.face_count()),
            (pair.1.vertex_count(), pair.1.face_count())
        );
        pair
    }

    /// Two wrong pairings made from `q`'s, each with what is wrong: a pair missing, and
    /// two faces sharing no edge paired (their mates paired with each other).
    fn wrong_pairings(q: &Quadrangulation) -> [(Quadrangulation, &'static str); 2] {
        let f = q.tri.faces().next().expect("a face");
        let mut short = q.clone();
        short.pairing.unpair(f);
        let mut far = q.clone();
        let g = crate::quad::fixtures::face_not_adjacent_to(&q.tri, f);
        let (f2, g2) = (
            far.pairing.unpair(f).expect("paired"),
            far.pairing.unpair(g).expect("paired"),
        );
        far.pairing.pair(f, g);
        far.pairing.pair(f2, g2);
        [(short, "a pair missing"), (far, "faces sharing no edge")]
    }

    /// The independent check accepts every algorithm's conversion, by its from-scratch
    /// path too (LRS flips edges, so its triangulation is not the input's), and refuses
    /// a conversion of another surface with the same counts, a corrupted triangulation,
    /// and pairings that are not perfect or pair faces sharing no edge.
    #[test]
    fn the_quad_check_accepts_conversions_and_refuses_wrong_ones() {
        use crate::quad::{convert, Options};
        let (torus, klein) = torus_and_klein();
        let opts = Options { seed: 1 };
        for algorithm in Algorithm::ALL {
            let q = convert(torus.clone(), algorithm, &opts).expect("converted");
            assert!(verify_quadrangulation(&torus, &q), "{algorithm}");
        }
        let lrs = convert(torus.clone(), Algorithm::Lrs, &opts).expect("converted");
        assert!(lrs.tri != torus, "LRS flipped no edge on this input");

        let other = convert(klein, Algorithm::PulliSegal, &opts).expect("converted");
        assert!(!verify_quadrangulation(&torus, &other), "another surface");

        let mut broken = lrs.clone();
        broken.tri.degree[0] += 1;
        assert!(
            !verify_quadrangulation(&torus, &broken),
            "a broken triangulation"
        );

        for q in [
            &lrs,
            &convert(torus.clone(), Algorithm::PulliSegal, &opts).expect(""),
        ] {
            for (wrong, what) in wrong_pairings(q) {
                assert!(!verify_quadrangulation(&torus, &wrong), "{what}");
            }
        }
    }

    /// The task's own check, which keeps no copy of the input triangulation, accepts
    /// every algorithm's conversion of a mesh component (LRS's by the from-scratch path)
    /// and refuses a conversion of another surface with the same counts, a triangulation
    /// whose faces were corrupted, and pairings that are not perfect or pair faces
    /// sharing no edge. A corrupted adjacency array under unchanged faces is accepted:
    /// the output is read from the face lists and the pairing alone.
    #[test]
    fn the_component_check_accepts_conversions_and_refuses_wrong_ones() {
        use crate::quad::{convert, Options};
        let (torus, klein) = torus_and_klein();
        // The torus as the second component of a mesh, so that the origins are not
        // the identity.
        let mut faces = gen::octahedron().faces;
        faces.extend(torus.to_mesh().faces.iter().map(|f| f.map(|v| v + 6)));
        let mesh = TriMesh::combinatorial(6 + torus.vertex_count(), faces);
        let c = crate::core::Surfaces::from_mesh(&mesh)
            .expect("closed surfaces")
            .components
            .remove(1);
        let origin = Origin {
            surface: SurfaceType::of(&c.tri),
            vertex_origin: c.vertex_origin,
            face_origin: c.face_origin,
        };
        assert_eq!(origin.face_origin[0], 8);
        let opts = Options { seed: 1 };
        for algorithm in Algorithm::ALL {
            let q = convert(c.tri.clone(), algorithm, &opts).expect("converted");
            assert!(verify_component((&mesh).into(), &origin, &q), "{algorithm}");
        }
        let lrs = convert(c.tri.clone(), Algorithm::Lrs, &opts).expect("converted");
        assert!(lrs.tri != c.tri, "LRS flipped no edge on this input");
        let ps = convert(c.tri.clone(), Algorithm::PulliSegal, &opts).expect("converted");

        let other = convert(klein, Algorithm::PulliSegal, &opts).expect("converted");
        assert!(
            !verify_component((&mesh).into(), &origin, &other),
            "another surface"
        );

        let mut broken = ps.clone();
        broken.tri.corner_vertex[0] = broken.tri.corner_vertex[1];
        assert!(
            !verify_component((&mesh).into(), &origin, &broken),
            "a corrupted face"
        );
        let mut adjacency = ps.clone();
        adjacency.tri.degree[0] += 1;
        assert!(verify_component((&mesh).into(), &origin, &adjacency));

        for q in [&lrs, &ps] {
            for (wrong, what) in wrong_pairings(q) {
                assert!(!verify_component((&mesh).into(), &origin, &wrong), "{what}");
            }
        }
    }

    /// A pairing whose pair count is right but that names a face twice (in two pairs of
    /// adjacent faces), or a face the triangulation does not have, is refused (not
    /// indexed out of range). Release builds only: `Pairing::pair` debug-asserts that its
    /// faces are unpaired and distinct.
    #[cfg(not(debug_assertions))]
    #[test]
    fn pairings_naming_a_face_twice_or_a_missing_face_are_refused() {
        let torus = gen::torus7();
        let tri = Triangulation::from_faces(torus.vertex_count, &torus.faces).expect("a torus");
        let q = quad::convert(
            tri.clone(),
            Algorithm::PulliSegal,
            &quad::Options { seed: 1 },
        )
        .expect("converted");
        assert!(verify_quadrangulation(&tri, &q));
        // A pair (a, b) and a neighbour c < b of b other than a: c's pair is replaced by
        // (c, b), so that `pairs` lists b twice, each time beside a face sharing an edge.
        let (a, b, c) = q
            .pairing
            .pairs()
            .find_map(|(a, b)| {
                let c = tri
                    .face_neighbours(b)
                    .into_iter()
                    .find(|&c| c != a && c < b)?;
                Some((a, b, c))
            })
            .expect("a pair with such a neighbour");
        let mut twice = q.clone();
        twice.pairing.unpair(c);
        twice.pairing.pair(c, b);
        assert_eq!(twice.pairing.len(), q.pairing.len());
        let listed = twice
            .pairing
            .pairs()
            .filter(|&(f, g)| g == b && (f == a || f == c));
        assert_eq!(listed.count(), 2);
        assert!(!verify_quadrangulation(&tri, &twice), "a face paired twice");
        // One face of a pair beyond the triangulation's faces.
        let mut missing = q.clone();
        missing.pairing = quad::Pairing::new(tri.face_capacity() + 1);
        for (f, g) in q.pairing.pairs().filter(|&(f, _)| f != a) {
            missing.pairing.pair(f, g);
        }
        missing.pairing.pair(a, FaceId(tri.face_capacity() as u32));
        assert_eq!(missing.pairing.len(), q.pairing.len());
        assert!(
            !verify_quadrangulation(&tri, &missing),
            "a face it does not have"
        );
    }

    /// The quad read from two face lists is `quad::quad_of`'s, read from the
    /// triangulation's adjacency, on every pair of every algorithm's conversion (LRS's
    /// flipped faces included); faces sharing fewer than two vertices have none.
    #[test]
    fn quads_from_face_lists_are_the_adjacency_quads() {
        let torus = gen::torus7();
        let tri = Triangulation::from_faces(torus.vertex_count, &torus.faces).expect("a torus");
        let opts = quad::Options { seed: 2 };
        for algorithm in Algorithm::ALL {
            let q = quad::convert(tri.clone(), algorithm, &opts).expect("converted");
            let faces = |f: FaceId| q.tri.face_vertices(f).map(|v| v.0);
            for (f, g) in q.pairing.pairs() {
                assert_eq!(
                    quad_of_faces(faces(f), faces(g)),
                    quad::quad_of(&q.tri, f, g),
                    "{algorithm}"
                );
            }
        }
        assert_eq!(quad_of_faces([0, 1, 2], [2, 3, 4]), None);
        assert_eq!(quad_of_faces([0, 1, 2], [3, 4, 5]), None);
        assert_eq!(quad_of_faces([0, 1, 2], [2, 1, 3]), Some([0, 1, 3, 2]));
    }

    /// A component above ds-naive's limit is refused, located, before any work.
    #[test]
    fn ds_naive_refuses_large_components() {
        let big = gen::subdivide(&gen::octahedron(), 7).expect("a valid mesh within the limits");
        assert!(big.faces.len() > DS_NAIVE_MAX_FACES);
        let e = quadrangulate(
            &big,
            &QuadOptions {
                algorithm: Algorithm::DsNaive,
                ..QuadOptions::default()
            },
        )
        .unwrap_err();
        assert!(matches!(e, Error::TooLarge { component: 0, .. }), "{e}");
        assert!(e.to_string().contains("use ds or frink-lct"), "{e}");
    }
}
