//! Code common to the integration tests: the repository's own test data
//! (`tests/data/`), the opt-in real-mesh corpus, list parsing and independent checkers.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use contractible::irreducible::{Algorithm, Options, Reduction};
use contractible::Triangulation;

/// The repository's root: the directory of the package whose test target includes this
/// file, or its parent for the command line's package (cli/), whose tests read the same
/// data, documents and examples.
pub fn repo_root() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    if env!("CARGO_PKG_NAME") == "contractible-cli" {
        dir.parent()
            .expect("cli/ is inside the repository")
            .to_path_buf()
    } else {
        dir.to_path_buf()
    }
}

/// The repository's own test data, `tests/data/` (see its README for what each file tests
/// and where it comes from).
pub fn data_dir() -> PathBuf {
    repo_root().join("tests/data")
}

/// The small real meshes the repository carries, `tests/data/meshes/` (with their
/// `manifest.csv`, the corpus manifest's columns).
pub fn data_meshes() -> PathBuf {
    data_dir().join("meshes")
}

/// The opt-in real-mesh corpus (ignored unless asked for: `-- --ignored ::corpus::`): the folder given by the environment
/// variable `CONTRACTIBLE_CORPUS`, or else `../shared` beside the checkout; it holds
/// `meshes/manifest.csv`, `meshes/closed/` and `meshes/invalid/`.
///
/// Panics, naming the folder it looked for, when the corpus is not there: a corpus run
/// asked for never passes by skipping.
pub fn corpus_dir() -> PathBuf {
    let dir = match std::env::var_os("CONTRACTIBLE_CORPUS") {
        Some(d) => PathBuf::from(d),
        None => repo_root().join("../shared"),
    };
    let manifest = dir.join("meshes/manifest.csv");
    assert!(
        manifest.is_file(),
        "the real-mesh corpus is expected at {} (no {} there): put the \
         corpus folder `shared` beside the checkout or set CONTRACTIBLE_CORPUS to its path",
        dir.display(),
        manifest.display()
    );
    dir
}

/// The corpus meshes, `corpus_dir()/meshes`.
pub fn corpus_meshes() -> PathBuf {
    corpus_dir().join("meshes")
}

pub use contractible::io::list::NamedSurface;

/// Every surface of the published list `tests/data/irreducible/FILE`, read by the
/// library's list reader.
pub fn read_surface_list(file: &str) -> Vec<NamedSurface> {
    let path = data_dir().join("irreducible").join(file);
    contractible::io::list::read_surface_list(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// One row of a mesh manifest (`tests/data/meshes/manifest.csv` or the corpus's; the
/// columns the tests use).
#[derive(Debug, Clone)]
pub struct ManifestRow {
    pub name: String,
    pub set: String,
    pub file: String,
    pub v: usize,
    pub e: usize,
    pub f: usize,
    pub components: usize,
    /// Per-component genus expanded to a sorted list; `None` entries for `N2`-style codes.
    pub genus: Vec<String>,
    pub euler: i64,
    pub orientable: bool,
}

/// Splits one CSV line honouring double quotes.
fn csv_fields(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    for ch in line.chars() {
        match ch {
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(std::mem::take(&mut cur)),
            _ => cur.push(ch),
        }
    }
    out.push(cur);
    out
}

/// Expands the manifest's genus column (`0`, `0,0`, `0 x26`, `0 x1; 1 x4`) to one entry
/// per component, sorted.
pub fn expand_genus(s: &str, components: usize) -> Vec<String> {
    let mut out = Vec::new();
    if s.contains('x') {
        for part in s.split(';') {
            let part = part.trim();
            let (g, n) = part.split_once(" x").expect("G xN");
            for _ in 0..n.trim().parse::<usize>().expect("count") {
                out.push(g.trim().to_string());
            }
        }
    } else {
        out = s.split(',').map(|g| g.trim().to_string()).collect();
    }
    if out.len() == 1 && components > 1 {
        out = vec![out[0].clone(); components];
    }
    out.sort();
    out
}

/// The rows of the repository's own mesh manifest, `tests/data/meshes/manifest.csv`.
pub fn data_manifest() -> Vec<ManifestRow> {
    manifest_in(&data_meshes())
}

/// The rows of the corpus manifest (panics, naming the place, when the corpus is absent).
pub fn corpus_manifest() -> Vec<ManifestRow> {
    manifest_in(&corpus_meshes())
}

/// The rows of `dir/manifest.csv`; each row's `file` is relative to `dir`.
pub fn manifest_in(dir: &std::path::Path) -> Vec<ManifestRow> {
    let path = dir.join("manifest.csv");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header = csv_fields(lines.next().expect("header"));
    let col = |n: &str| {
        header
            .iter()
            .position(|h| h == n)
            .unwrap_or_else(|| panic!("column {n}"))
    };
    let (c_name, c_set, c_file, c_v, c_e, c_f) = (
        col("name"),
        col("set"),
        col("file"),
        col("V"),
        col("E"),
        col("F"),
    );
    let (c_comp, c_genus, c_euler, c_or) = (
        col("components"),
        col("genus"),
        col("euler"),
        col("orientable"),
    );
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let r = csv_fields(l);
            let components: usize = r[c_comp].parse().expect("components");
            ManifestRow {
                name: r[c_name].clone(),
                set: r[c_set].clone(),
                file: r[c_file].clone(),
                v: r[c_v].parse().expect("V"),
                e: r[c_e].parse().expect("E"),
                f: r[c_f].parse().expect("F"),
                components,
                genus: expand_genus(&r[c_genus], components),
                euler: r[c_euler].parse().expect("euler"),
                orientable: r[c_or] == "True",
            }
        })
        .collect()
}

/// Whether the two face lists describe isomorphic triangulations: a bijection of their
/// vertices mapping the face set of `a` exactly onto the face set of `b` (faces compared
/// as unordered triples, so mirror images count as isomorphic). Vertex ids may be sparse.
///
/// Backtracking over vertex bijections: vertices of `a` are assigned in BFS order, each
/// to an unused vertex of `b` of the same degree that is adjacent in `b` to the images
/// of exactly the already-assigned `a`-neighbours. For the small triangulations of the
/// tests (≤ ~20 vertices) this is instantaneous.
pub fn is_isomorphic(a: &[[u32; 3]], b: &[[u32; 3]]) -> bool {
    use std::collections::{BTreeMap, BTreeSet};

    /// Dense relabelling, adjacency matrix, and the face set as sorted triples.
    struct G {
        n: usize,
        adj: Vec<Vec<bool>>,
        nbrs: Vec<Vec<usize>>,
        faces: BTreeSet<[usize; 3]>,
    }
    fn build(f: &[[u32; 3]]) -> Option<G> {
        let mut id: BTreeMap<u32, usize> = BTreeMap::new();
        for t in f {
            for &v in t {
                let k = id.len();
                id.entry(v).or_insert(k);
            }
        }
        let n = id.len();
        let mut adj = vec![vec![false; n]; n];
        let mut faces = BTreeSet::new();
        for t in f {
            let mut d = t.map(|v| id[&v]);
            for i in 0..3 {
                let (p, q) = (d[i], d[(i + 1) % 3]);
                adj[p][q] = true;
                adj[q][p] = true;
            }
            d.sort();
            if !faces.insert(d) {
                return None; // a repeated face: not a simplicial surface
            }
        }
        let nbrs = (0..n)
            .map(|v| (0..n).filter(|&w| adj[v][w]).collect())
            .collect();
        Some(G {
            n,
            adj,
            nbrs,
            faces,
        })
    }
    let (Some(ga), Some(gb)) = (build(a), build(b)) else {
        return false;
    };
    if ga.n != gb.n || ga.faces.len() != gb.faces.len() {
        return false;
    }
    let mut da: Vec<usize> = ga.nbrs.iter().map(Vec::len).collect();
    let mut db: Vec<usize> = gb.nbrs.iter().map(Vec::len).collect();
    da.sort();
    db.sort();
    if da != db {
        return false;
    }
    // BFS order over a's vertices (every component).
    let mut order = Vec::with_capacity(ga.n);
    let mut seen = vec![false; ga.n];
    for s in 0..ga.n {
        if seen[s] {
            continue;
        }
        seen[s] = true;
        let mut k = order.len();
        order.push(s);
        while k < order.len() {
            let v = order[k];
            k += 1;
            for &w in &ga.nbrs[v] {
                if !seen[w] {
                    seen[w] = true;
                    order.push(w);
                }
            }
        }
    }
    fn go(
        k: usize,
        order: &[usize],
        ga: &G,
        gb: &G,
        map: &mut Vec<usize>,
        used: &mut Vec<bool>,
    ) -> bool {
        if k == order.len() {
            return ga.faces.iter().all(|f| {
                let mut g = f.map(|v| map[v]);
                g.sort();
                gb.faces.contains(&g)
            });
        }
        let v = order[k];
        for c in 0..gb.n {
            if used[c] || gb.nbrs[c].len() != ga.nbrs[v].len() {
                continue;
            }
            let consistent = order[..k]
                .iter()
                .all(|&p| ga.adj[v][p] == gb.adj[c][map[p]]);
            if !consistent {
                continue;
            }
            map[v] = c;
            used[c] = true;
            if go(k + 1, order, ga, gb, map, used) {
                return true;
            }
            used[c] = false;
        }
        map[v] = usize::MAX;
        false
    }
    let mut map = vec![usize::MAX; ga.n];
    let mut used = vec![false; gb.n];
    go(0, &order, &ga, &gb, &mut map, &mut used)
}

// ---- Irreducible-triangulation algorithms: which to run, and the independent checks.

pub const ALL: [Algorithm; 3] = [Algorithm::Rs, Algorithm::Schipper, Algorithm::Brute];

/// The algorithms under test (see the module documentation).
pub fn algorithms() -> Vec<Algorithm> {
    match std::env::var("CONTRACTIBLE_TEST_ALGORITHMS") {
        Ok(list) if !list.trim().is_empty() => {
            let chosen: Vec<Algorithm> = list
                .split(',')
                .map(|name| {
                    let name = name.trim();
                    *ALL.iter()
                        .find(|a| a.name() == name)
                        .unwrap_or_else(|| panic!("unknown algorithm {name:?}"))
                })
                .collect();
            chosen
        }
        _ => ALL.to_vec(),
    }
}

pub fn options(seed: u64) -> Options {
    Options {
        seed,
        count_retests: true,
        keep_history: true,
    }
}

/// Checks `r`, the reduction of `input` by `alg`, independently of the algorithm.
pub fn check(input: &Triangulation, r: &Reduction, alg: Algorithm, label: &str) {
    let out = &r.tri;
    let label = format!("{} {label}", alg.name());
    assert_eq!(r.algorithm, alg, "{label}");
    out.validate()
        .unwrap_or_else(|e| panic!("{label}: invalid output: {e}"));
    assert_eq!(
        out.euler_characteristic(),
        input.euler_characteristic(),
        "{label}: χ changed"
    );
    assert_eq!(
        out.is_orientable(),
        input.is_orientable(),
        "{label}: orientability changed"
    );
    for (a, b, _) in out.edges() {
        assert!(
            !out.link_condition_naive(a, b),
            "{label}: output edge {a}-{b} is contractible"
        );
    }
    let h = out.euler_genus();
    if h == 0 {
        assert!(
            out.vertex_count() == 4 && out.face_count() == 4,
            "{label}: a sphere must reduce to the tetrahedron, got {} vertices",
            out.vertex_count()
        );
    } else {
        assert!(
            out.vertex_count() as i64 <= 13 * h - 4,
            "{label}: {} vertices exceed Joret–Wood 13h − 4 = {}",
            out.vertex_count(),
            13 * h - 4
        );
    }
    // Output vertex ids are input ids.
    assert!(out.vertices().all(|v| input.is_vertex(v)), "{label}");
    assert!(r.expand() == *input, "{label}: expand() is not the input");

    let s = &r.stats;
    let c = s.contractions as usize;
    assert_eq!(s.vertices_in, input.vertex_count(), "{label}");
    assert_eq!(s.edges_in, input.edge_count(), "{label}");
    assert_eq!(s.faces_in, input.face_count(), "{label}");
    assert_eq!(s.vertices_out, out.vertex_count(), "{label}");
    assert_eq!(s.faces_out, out.face_count(), "{label}");
    assert_eq!(c, r.history.len(), "{label}");
    assert_eq!(c, s.vertices_in - s.vertices_out, "{label}");
    assert_eq!(s.faces_out, s.faces_in - 2 * c, "{label}");
    assert!(s.edges_tested_more_than_once <= s.link_tests, "{label}");
    let e_out = out.edge_count() as u64;
    match alg {
        Algorithm::Rs => {
            assert!(
                s.link_tests <= s.edges_in as u64,
                "{label}: ℓ = {} > edges_in = {}",
                s.link_tests,
                s.edges_in
            );
            assert_eq!(s.edges_tested_more_than_once, 0, "{label}: ε");
        }
        Algorithm::Schipper => {
            // Each contraction follows a passing test; every output vertex was found
            // trapped by testing all its edges, so every output edge was tested from
            // both endpoints.
            assert!(
                s.link_tests >= s.contractions + 2 * e_out,
                "{label}: ℓ = {} too small",
                s.link_tests
            );
            assert!(
                s.edges_tested_more_than_once >= e_out,
                "{label}: ε too small"
            );
        }
        Algorithm::Brute => {
            if c == 0 {
                assert_eq!(s.link_tests, e_out, "{label}: one pass, every edge once");
                assert_eq!(s.edges_tested_more_than_once, 0, "{label}");
            } else {
                // The last two passes both tested every surviving edge.
                assert!(
                    s.link_tests >= s.contractions + 2 * e_out,
                    "{label}: ℓ = {} too small",
                    s.link_tests
                );
                assert!(
                    s.edges_tested_more_than_once >= e_out,
                    "{label}: ε too small"
                );
            }
        }
    }
}

// ---- Dual graph (petgraph), the reference for tri-quad matchings.

/// The dual graph of `t` as a petgraph: one node per live face (weight: its id), one
/// edge per edge of `t` joining the two faces that share it. On a closed surface it is
/// cubic and bridgeless (every edge lies on the cycle of faces around either endpoint),
/// so by Petersen's theorem it has a perfect matching. Node `k` is the `k`-th live
/// face in id order.
pub fn dual_graph(t: &Triangulation) -> petgraph::graph::UnGraph<contractible::FaceId, ()> {
    let mut g = petgraph::graph::UnGraph::with_capacity(t.face_count(), t.edge_count());
    let mut node = vec![petgraph::graph::NodeIndex::end(); t.face_capacity()];
    for f in t.faces() {
        node[f.index()] = g.add_node(f);
    }
    for (_, _, c) in t.edges() {
        let o = t.opposite(c);
        g.add_edge(node[c.face().index()], node[o.face().index()], ());
    }
    g
}

/// The conformance vectors of `spec/vectors/<group>.jsonl`, one JSON value per line.
/// (Only the test targets that depend on `serde_json` call it.)
pub fn read_vectors(group: &str) -> Vec<serde_json::Value> {
    let path = repo_root()
        .join("spec/vectors")
        .join(format!("{group}.jsonl"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{group}: {e}")))
        .collect()
}

/// A JSON array of vertex-id triples (a vector's `faces`, `output_faces`, `k_faces`...).
pub fn json_faces(v: &serde_json::Value) -> Vec<[u32; 3]> {
    v.as_array()
        .expect("face array")
        .iter()
        .map(|f| {
            let f = f.as_array().expect("triple");
            assert_eq!(f.len(), 3);
            [0, 1, 2].map(|k| f[k].as_u64().expect("vertex id") as u32)
        })
        .collect()
}

/// Every vector of `groups`, each group checked to hold its expected count.
pub fn read_vector_groups(groups: &[(&str, usize)]) -> Vec<serde_json::Value> {
    groups
        .iter()
        .flat_map(|(g, n)| {
            let v = read_vectors(g);
            assert_eq!(v.len(), *n, "{g}: number of vectors");
            v
        })
        .collect()
}

/// The published small surfaces of `tests/data/irreducible/` (every surface with up to 8
/// vertices, the torus and projective-plane lists), built, with their names.
pub fn small_published_surfaces() -> Vec<(String, Triangulation)> {
    let mut out = Vec::new();
    for file in [
        "surfaces-upto-8-vertices.txt",
        "torus.txt",
        "projective-plane.txt",
    ] {
        for s in read_surface_list(file) {
            let t = Triangulation::from_faces(s.vertex_count, &s.faces)
                .unwrap_or_else(|e| panic!("{}: {e}", s.name));
            out.push((s.name, t));
        }
    }
    out
}

/// Union–find: the root of `x`'s set (with path halving), for the independent topology
/// checkers of the tests.
pub fn find(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// Union–find: joins the sets of `a` and `b`; the smaller root index stays the root.
pub fn union(parent: &mut [usize], a: usize, b: usize) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    parent[ra.max(rb)] = ra.min(rb);
}
