//! The simplification conformance vectors `spec/vectors/simplify-*.jsonl` (format:
//! `spec/vectors/README.md`, section "Simplification vectors"):
//!
//! 1. **Exactly**: `simplify::simplify_with` on each stored input and options gives the
//!    stored output positions (bit for bit), faces, per-pass reports and statistics.
//!    Regenerate with `cargo run --release -p contractible-tools --bin
//!    make_simplify_vectors` only for an intended change.
//! 2. **Independently** of the simplifier, from the stored data alone: per component,
//!    the output has the input's Euler characteristic, orientability and boundary loops
//!    (the fuzz harness's face-list classifier); the statistics agree with the meshes and
//!    the pass reports; every output edge shorter than ε is counted in `remaining`, and
//!    the link condition of the surface with boundary, decided here from the face list,
//!    accounts for it (an edge that passes it can only be left by the guard); the nested
//!    mode contracts at least as many edges as the naive one; the exactness bound of the
//!    README holds, and the output coordinates are dyadic as it says, within the input's
//!    bounding box.

use std::collections::{BTreeMap, BTreeSet};

use contractible::simplify::{self, Options, PassReport};
use contractible::TriMesh;
use serde_json::Value;

use crate::common;
use crate::harness::{surface_topology, ComponentType};

const GROUPS: [(&str, usize); 2] = [("simplify-closed", 10), ("simplify-bounded", 7)];

/// The runs of every vector, in order: (mode, side, guard, index of ε among the three).
const RUNS: [(&str, &str, bool, usize); 10] = [
    ("naive", "count", true, 0),
    ("nested", "count", true, 0),
    ("naive", "count", false, 0),
    ("nested", "count", false, 0),
    ("naive", "count", false, 1),
    ("nested", "count", false, 1),
    ("naive", "count", false, 2),
    ("nested", "count", false, 2),
    ("nested", "path", false, 2),
    ("nested", "euclidean", false, 2),
];

fn all() -> Vec<Value> {
    common::read_vector_groups(&GROUPS)
}

fn num(v: &Value, key: &str) -> usize {
    v[key]
        .as_u64()
        .unwrap_or_else(|| panic!("missing number {key}")) as usize
}

fn positions(v: &Value) -> Vec<[f64; 3]> {
    v.as_array()
        .expect("positions")
        .iter()
        .map(|p| {
            let p = p.as_array().expect("triple");
            assert_eq!(p.len(), 3);
            [0, 1, 2].map(|k| p[k].as_f64().expect("coordinate"))
        })
        .collect()
}

fn reports(v: &Value) -> Vec<[usize; 4]> {
    v.as_array()
        .expect("pass_reports")
        .iter()
        .map(|r| {
            let r = r.as_array().expect("report");
            assert_eq!(r.len(), 4);
            [0, 1, 2, 3].map(|k| r[k].as_u64().expect("count") as usize)
        })
        .collect()
}

fn options(r: &Value) -> Options {
    let name = |k: &str| r[k].as_str().unwrap_or_else(|| panic!("missing {k}"));
    Options {
        eps: r["eps"].as_f64().expect("eps"),
        mode: name("mode").parse().expect("mode"),
        side: name("side").parse().expect("side"),
        position: name("position").parse().expect("position"),
        guard: r["guard"].as_bool().expect("guard"),
    }
}

fn input_mesh(v: &Value) -> TriMesh {
    let mesh = TriMesh::with_positions(positions(&v["positions"]), common::json_faces(&v["faces"]));
    assert_eq!(mesh.vertex_count, num(v, "vertex_count"), "{}", v["name"]);
    mesh
}

fn skips(v: &Value) -> [usize; 4] {
    [
        num(v, "link_condition"),
        num(v, "non_disc"),
        num(v, "foldover"),
        num(v, "frozen"),
    ]
}

#[test]
fn simplify_vector_files_hold_the_documented_runs() {
    let all = all();
    let names: BTreeSet<&str> = all
        .iter()
        .map(|v| v["name"].as_str().expect("name"))
        .collect();
    assert_eq!(names.len(), all.len(), "duplicate names");
    for v in &all {
        let runs = v["runs"].as_array().expect("runs");
        assert_eq!(runs.len(), RUNS.len(), "{}", v["name"]);
        let eps: Vec<f64> = (0..3)
            .map(|k| runs[2 + 2 * k]["eps"].as_f64().expect("eps"))
            .collect();
        assert!(eps[0] < eps[1] && eps[1] < eps[2], "{}: ε", v["name"]);
        for (r, &(mode, side, guard, e)) in runs.iter().zip(&RUNS) {
            assert_eq!(r["mode"], mode, "{}", v["name"]);
            assert_eq!(r["side"], side, "{}", v["name"]);
            assert_eq!(r["guard"], guard, "{}", v["name"]);
            assert_eq!(r["position"], "midpoint", "{}", v["name"]);
            assert_eq!(r["eps"].as_f64(), Some(eps[e]), "{}", v["name"]);
        }
    }
}

#[test]
fn library_reproduces_every_simplify_vector_exactly() {
    for v in all() {
        let name = v["name"].as_str().expect("name");
        let mesh = input_mesh(&v);
        for r in v["runs"].as_array().expect("runs") {
            let opts = options(r);
            let label = format!(
                "{name} {} {} guard {} ε {}",
                r["mode"], r["side"], opts.guard, opts.eps
            );
            let mut got_reports = Vec::new();
            let out = simplify::simplify_with(&mesh, &opts, &mut |p: &PassReport| {
                got_reports.push([p.component, p.pass, p.contracted, p.faces]);
            })
            .unwrap_or_else(|e| panic!("{label}: {e}"));
            let got: Vec<[u64; 3]> = out
                .mesh
                .positions
                .as_deref()
                .expect("positions")
                .iter()
                .map(|p| p.map(f64::to_bits))
                .collect();
            let want: Vec<[u64; 3]> = positions(&r["output_positions"])
                .iter()
                .map(|p| p.map(f64::to_bits))
                .collect();
            assert!(got == want, "{label}: output positions");
            assert_eq!(
                out.mesh.faces,
                common::json_faces(&r["output_faces"]),
                "{label}: faces"
            );
            assert_eq!(got_reports, reports(&r["pass_reports"]), "{label}: passes");
            let s = &out.stats;
            let w = &r["stats"];
            assert_eq!(
                [
                    s.vertices_in,
                    s.faces_in,
                    s.vertices_out,
                    s.faces_out,
                    s.components,
                    s.boundary_loops,
                    s.edges_contracted,
                    s.discs_removed,
                    s.vertices_removed_inside,
                    s.short_edges_remaining,
                    s.passes,
                ],
                [
                    "vertices_in",
                    "faces_in",
                    "vertices_out",
                    "faces_out",
                    "components",
                    "boundary_loops",
                    "edges_contracted",
                    "discs_removed",
                    "vertices_removed_inside",
                    "short_edges_remaining",
                    "passes",
                ]
                .map(|k| num(w, k)),
                "{label}: counts"
            );
            let counts =
                |c: &simplify::SkipCounts| [c.link_condition, c.non_disc, c.foldover, c.frozen];
            assert_eq!(counts(&s.skipped), skips(&w["skipped"]), "{label}: skipped");
            assert_eq!(
                counts(&s.remaining),
                skips(&w["remaining"]),
                "{label}: remaining"
            );
            assert_eq!(
                s.shortest_remaining_edge.map(f64::to_bits),
                w["shortest_remaining_edge"].as_f64().map(f64::to_bits),
                "{label}: shortest edge"
            );
        }
    }
}

/// The distinct edges of `faces` as (low, high) vertex pairs.
fn edges(faces: &[[u32; 3]]) -> BTreeSet<(u32, u32)> {
    faces
        .iter()
        .flat_map(|f| (0..3).map(move |k| (f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3]))))
        .collect()
}

fn dist2(p: [f64; 3], q: [f64; 3]) -> f64 {
    let d = [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
}

/// The link condition of a surface with boundary, decided from its face list alone:
/// every boundary loop is coned to a new vertex of its own; the edge `[u, v]` passes iff
/// its endpoints' common neighbours in the coned surface are exactly the third vertices
/// of its two coned faces, `u` and `v` are not on two different loops, and they are not
/// both of degree 3 (the edge of a tetrahedron).
struct LinkTest {
    neighbours: BTreeMap<u32, BTreeSet<u64>>,
    opposite: BTreeMap<(u32, u32), BTreeSet<u64>>,
    loop_of: BTreeMap<u32, u64>,
}

impl LinkTest {
    fn new(faces: &[[u32; 3]]) -> Self {
        let mut count: BTreeMap<(u32, u32), usize> = BTreeMap::new();
        let mut opposite: BTreeMap<(u32, u32), BTreeSet<u64>> = BTreeMap::new();
        let mut neighbours: BTreeMap<u32, BTreeSet<u64>> = BTreeMap::new();
        for f in faces {
            for k in 0..3 {
                let (a, b, c) = (f[k], f[(k + 1) % 3], f[(k + 2) % 3]);
                let e = (a.min(b), a.max(b));
                *count.entry(e).or_default() += 1;
                opposite.entry(e).or_default().insert(u64::from(c));
                neighbours.entry(a).or_default().insert(u64::from(b));
                neighbours.entry(b).or_default().insert(u64::from(a));
            }
        }
        // Boundary loops by union–find over the boundary edges; the cone apex of a loop
        // gets an id above every vertex.
        let boundary: Vec<(u32, u32)> = count
            .iter()
            .filter(|&(_, &c)| c == 1)
            .map(|(&e, _)| e)
            .collect();
        let mut parent: BTreeMap<u32, u32> = BTreeMap::new();
        fn find(parent: &mut BTreeMap<u32, u32>, x: u32) -> u32 {
            let p = *parent.entry(x).or_insert(x);
            if p == x {
                return x;
            }
            let r = find(parent, p);
            parent.insert(x, r);
            r
        }
        for &(a, b) in &boundary {
            let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
            if ra != rb {
                parent.insert(ra, rb);
            }
        }
        let apex = |root: u32| (1u64 << 32) + u64::from(root);
        let mut loop_of = BTreeMap::new();
        let vertices: Vec<u32> = parent.keys().copied().collect();
        for v in vertices {
            let w = apex(find(&mut parent, v));
            loop_of.insert(v, w);
            neighbours.entry(v).or_default().insert(w);
        }
        for &(a, b) in &boundary {
            opposite.entry((a, b)).or_default().insert(loop_of[&a]);
        }
        LinkTest {
            neighbours,
            opposite,
            loop_of,
        }
    }

    fn passes(&self, u: u32, v: u32) -> bool {
        let (nu, nv) = (&self.neighbours[&u], &self.neighbours[&v]);
        let common: BTreeSet<u64> = nu.intersection(nv).copied().collect();
        let two_loops = matches!(
            (self.loop_of.get(&u), self.loop_of.get(&v)),
            (Some(a), Some(b)) if a != b
        );
        common == self.opposite[&(u.min(v), u.max(v))]
            && !two_loops
            && !(nu.len() == 3 && nv.len() == 3)
    }
}

/// Contracting passes per component, at most (the `depth` of the README's bound).
fn depth(reports: &[[usize; 4]]) -> usize {
    let mut per: BTreeMap<usize, usize> = BTreeMap::new();
    for r in reports {
        *per.entry(r[0]).or_default() += usize::from(r[2] > 0);
    }
    per.values().copied().max().unwrap_or(0)
}

#[test]
fn stored_simplify_outputs_are_valid_independently() {
    let mut link_checked = 0;
    for v in all() {
        let name = v["name"].as_str().expect("name");
        let in_pos = positions(&v["positions"]);
        let in_faces = common::json_faces(&v["faces"]);
        let before = surface_topology(&in_faces).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(
            before.vertices,
            in_pos.len(),
            "{name}: an unused input vertex"
        );
        let mut stated: Vec<ComponentType> = v["components"]
            .as_array()
            .expect("components")
            .iter()
            .map(|c| ComponentType {
                euler: c["euler_characteristic"].as_i64().expect("χ"),
                orientable: c["orientable"].as_bool().expect("orientable"),
                boundary_loops: num(c, "boundary_loops"),
            })
            .collect();
        stated.sort_unstable();
        assert_eq!(before.components, stated, "{name}: stated components");
        // The coordinates' bits, as stated.
        let fraction = num(&v["coordinate_bits"], "fraction") as i32;
        let magnitude = num(&v["coordinate_bits"], "magnitude") as i32;
        let dyadic = |x: f64, bits: i32| {
            let y = x * 2f64.powi(bits);
            y == y.trunc()
        };
        assert!(
            in_pos
                .iter()
                .flatten()
                .all(|&x| dyadic(x, fraction) && x.abs() < 2f64.powi(magnitude)),
            "{name}: coordinate bits"
        );
        let lo: [f64; 3] = [0, 1, 2].map(|k| in_pos.iter().map(|p| p[k]).fold(f64::MAX, f64::min));
        let hi: [f64; 3] = [0, 1, 2].map(|k| in_pos.iter().map(|p| p[k]).fold(f64::MIN, f64::max));
        let mut contracted: BTreeMap<(u64, bool, String), usize> = BTreeMap::new();
        for r in v["runs"].as_array().expect("runs") {
            let opts = options(r);
            let label = format!(
                "{name} {} {} guard {} ε {}",
                r["mode"], r["side"], opts.guard, opts.eps
            );
            let s = &r["stats"];
            let pos = positions(&r["output_positions"]);
            let out = common::json_faces(&r["output_faces"]);
            let after = surface_topology(&out).unwrap_or_else(|e| panic!("{label}: {e}"));
            assert_eq!(after.components, before.components, "{label}: topology");
            assert_eq!(
                after.vertices,
                pos.len(),
                "{label}: an unused output vertex"
            );
            assert!(
                out.iter().flatten().all(|&x| (x as usize) < pos.len()),
                "{label}: vertex out of range"
            );
            // The exactness bound and what it implies for the output coordinates.
            let reps = reports(&r["pass_reports"]);
            let d = depth(&reps) as i32;
            let b = magnitude + fraction + d + 1;
            if opts.guard {
                assert!(4 * (b + 1) + 4 <= 53, "{label}: the guard's bound fails");
            } else {
                assert!(2 * b + 2 <= 53, "{label}: the length bound fails");
            }
            for p in &pos {
                for k in 0..3 {
                    assert!(
                        dyadic(p[k], fraction + d) && lo[k] <= p[k] && p[k] <= hi[k],
                        "{label}: coordinate {} not as the bound says",
                        p[k]
                    );
                }
            }
            // Statistics against the meshes.
            let (vin, fin) = (num(s, "vertices_in"), num(s, "faces_in"));
            let (vout, fout) = (num(s, "vertices_out"), num(s, "faces_out"));
            assert_eq!((vin, fin), (in_pos.len(), in_faces.len()), "{label}: in");
            assert_eq!((vout, fout), (pos.len(), out.len()), "{label}: out");
            assert_eq!(num(s, "components"), before.components.len(), "{label}");
            assert_eq!(num(s, "boundary_loops"), before.loops(), "{label}");
            let (edges_contracted, discs, inside) = (
                num(s, "edges_contracted"),
                num(s, "discs_removed"),
                num(s, "vertices_removed_inside"),
            );
            assert_eq!(vin - vout, edges_contracted + inside, "{label}: vertices");
            let lost_boundary = before.boundary_edges - after.boundary_edges;
            assert_eq!(
                fin - fout,
                2 * edges_contracted - lost_boundary + 2 * inside,
                "{label}: faces"
            );
            assert!(inside >= discs, "{label}: a disc without an inside vertex");
            // The pass reports.
            let total: usize = reps.iter().map(|r| r[2]).sum();
            assert_eq!(total, edges_contracted, "{label}: contractions per pass");
            let mut last: BTreeMap<usize, [usize; 4]> = BTreeMap::new();
            for rep in &reps {
                let prev = last.get(&rep[0]).map_or(0, |p| p[1]);
                assert_eq!(rep[1], prev + 1, "{label}: pass numbers");
                last.insert(rep[0], *rep);
            }
            assert_eq!(
                last.keys().copied().collect::<Vec<_>>(),
                (0..before.components.len()).collect::<Vec<_>>(),
                "{label}: components reported"
            );
            assert!(
                last.values().all(|p| p[2] == 0),
                "{label}: last pass not idle"
            );
            assert_eq!(
                last.values().map(|p| p[1]).max(),
                Some(num(s, "passes")),
                "{label}: passes"
            );
            assert_eq!(
                last.values().map(|p| p[3]).sum::<usize>(),
                fout,
                "{label}: faces after the last passes"
            );
            // Short edges: recounted, and accounted for by the link condition.
            let eps2 = opts.eps * opts.eps;
            let es = edges(&out);
            let shortest = es
                .iter()
                .map(|&(a, b)| dist2(pos[a as usize], pos[b as usize]))
                .fold(f64::INFINITY, f64::min);
            assert_eq!(
                s["shortest_remaining_edge"].as_f64().map(f64::to_bits),
                shortest.is_finite().then(|| shortest.sqrt().to_bits()),
                "{label}: shortest edge"
            );
            let short: Vec<(u32, u32)> = es
                .iter()
                .copied()
                .filter(|&(a, b)| dist2(pos[a as usize], pos[b as usize]) < eps2)
                .collect();
            let [link, non_disc, foldover, frozen] = skips(&s["remaining"]);
            assert_eq!(num(s, "short_edges_remaining"), short.len(), "{label}");
            assert_eq!(link + non_disc + foldover, short.len(), "{label}: reasons");
            assert_eq!(frozen, 0, "{label}: a short edge left frozen");
            let test = LinkTest::new(&out);
            let passing = short.iter().filter(|&&(a, b)| test.passes(a, b)).count();
            link_checked += short.len();
            if r["mode"] == "naive" {
                assert_eq!(
                    (link, passing),
                    (short.len() - foldover, foldover),
                    "{label}: naive leaves only link-condition failures and guard refusals"
                );
                assert_eq!(
                    discs + inside + non_disc,
                    0,
                    "{label}: naive removed a disc"
                );
                assert_eq!(skips(&s["skipped"])[1], 0, "{label}: naive non_disc");
            } else {
                assert!(
                    passing <= foldover,
                    "{label}: a short edge passing the link condition left"
                );
            }
            if !opts.guard {
                assert_eq!(
                    foldover + skips(&s["skipped"])[2],
                    0,
                    "{label}: fold-over without the guard"
                );
            }
            if r["side"] == "count" {
                let mode = r["mode"].as_str().expect("mode").to_string();
                contracted.insert((opts.eps.to_bits(), opts.guard, mode), edges_contracted);
            }
        }
        for ((eps, guard, mode), &n) in &contracted {
            if mode == "nested" {
                let naive = contracted[&(*eps, *guard, "naive".to_string())];
                assert!(n >= naive, "{name}: nested {n} < naive {naive}");
            }
        }
    }
    assert!(link_checked > 100, "{link_checked} short edges checked");
}

/// The independent link test refuses what it must: a tetrahedron's edge, an edge with a
/// third common neighbour, a chord of a boundary loop and an edge joining two loops;
/// it accepts an ordinary interior edge and a boundary edge.
#[test]
fn the_independent_link_test_tells_the_cases_apart() {
    let tetra = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
    let t = LinkTest::new(&tetra);
    assert!(!t.passes(0, 1));
    // The octahedron: every edge passes.
    let octa = contractible::gen::octahedron();
    let t = LinkTest::new(&octa.faces);
    assert!(edges(&octa.faces).iter().all(|&(a, b)| t.passes(a, b)));
    // The octahedron with a face subdivided: [0, 2] of the face [0, 2, 4] now has the
    // common neighbour 6 besides 4 and 5.
    let mut sub: Vec<[u32; 3]> = octa
        .faces
        .iter()
        .copied()
        .filter(|f| *f != [0, 2, 4])
        .collect();
    sub.extend([[0, 2, 6], [2, 4, 6], [4, 0, 6]]);
    let t = LinkTest::new(&sub);
    assert!(!t.passes(0, 2) && t.passes(0, 6));
    // A 3 × 1 strip of squares (a disc): vertices 0..4 bottom, 4..8 top. The chord
    // [1, 5]... is a rung, a boundary-to-boundary interior edge of one loop.
    let strip = [
        [0, 1, 5],
        [0, 5, 4],
        [1, 2, 6],
        [1, 6, 5],
        [2, 3, 7],
        [2, 7, 6],
    ];
    let t = LinkTest::new(&strip);
    assert!(!t.passes(1, 5), "a chord of the loop");
    assert!(t.passes(1, 2), "a boundary edge");
    // An annulus: two loops; a rung joins them.
    let n = 6u32;
    let ring: Vec<[u32; 3]> = (0..n)
        .flat_map(|i| {
            let j = (i + 1) % n;
            [[i, j, n + j], [i, n + j, n + i]]
        })
        .collect();
    let t = LinkTest::new(&ring);
    assert!(!t.passes(0, n), "an edge joining two loops");
    assert!(t.passes(0, 1), "an edge along one loop");
}
