"""Shared fixtures: the repository's meshes, meshes generated at test time, the
command-line binary, the opt-in real-mesh corpus, and independent checks written from
the definitions (no code of the library is used to check its results).

The default run needs nothing beside the checkout: it reads `tests/data/meshes` (small
real meshes whose licences allow redistribution) and meshes the command line's
generators (`contractible gen ...`) or NumPy build at test time. The tests marked
`corpus` sweep the real-mesh corpus, which the repository does not carry; they are
deselected unless `--corpus` is given, and then read the corpus from
$CONTRACTIBLE_CORPUS, else from `shared` beside the checkout, failing (never skipping)
when it is not there."""

import csv
import gzip
import os
import subprocess
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "meshes"

# The sweeps read every closed mesh of at most this many faces.
SMALL_FACES = 12_000
# How many such meshes each source holds at least: a sweep over fewer has lost files.
DATA_SMALL_MIN = 9
CORPUS_SMALL_MIN = 58


# ------------------------------------------------------------- the opt-in corpus

def pytest_addoption(parser):
    parser.addoption(
        "--corpus", action="store_true", default=False,
        help="also run the tests marked `corpus`: sweeps over the real-mesh corpus read "
             "from $CONTRACTIBLE_CORPUS, else from `shared` beside the checkout (they "
             "fail, naming the folder, when it is missing)")


def pytest_configure(config):
    config.addinivalue_line(
        "markers",
        "corpus: sweeps over the real-mesh corpus the repository does not carry; "
        "deselected unless --corpus is given")


def pytest_collection_modifyitems(config, items):
    """Without --corpus the corpus tests are deselected, and pytest's summary counts
    them as such."""
    if config.getoption("--corpus"):
        return
    chosen = [item for item in items if item.get_closest_marker("corpus") is None]
    if len(chosen) < len(items):
        config.hook.pytest_deselected(
            items=[item for item in items if item.get_closest_marker("corpus") is not None])
        items[:] = chosen


def corpus_dir() -> Path:
    """The corpus folder (holding `meshes/manifest.csv`): $CONTRACTIBLE_CORPUS, else
    `shared` beside the checkout. Whether it is there is for the caller to check."""
    env = os.environ.get("CONTRACTIBLE_CORPUS")
    return Path(env) if env else ROOT.parent / "shared"


def corpus_meshes() -> Path:
    """The corpus meshes; fails the calling test, naming the folder expected, when the
    corpus is missing: a corpus run asked for never passes by skipping."""
    d = corpus_dir()
    manifest_path = d / "meshes" / "manifest.csv"
    if not manifest_path.is_file():
        pytest.fail(f"the real-mesh corpus (--corpus) is expected at {d} (no {manifest_path} "
                    "there): put the corpus folder `shared` beside the checkout or set "
                    "CONTRACTIBLE_CORPUS to its path", pytrace=False)
    return d / "meshes"


def pytest_generate_tests(metafunc):
    """A test taking `corpus_small` runs once per closed corpus mesh of at most
    SMALL_FACES faces (its manifest row). The list is read only when --corpus is given
    and the corpus is there; otherwise the test gets a single case, `corpus`, which is
    deselected without --corpus and fails naming the folder expected with it."""
    if "corpus_small" not in metafunc.fixturenames:
        return
    manifest_path = corpus_dir() / "meshes" / "manifest.csv"
    if metafunc.config.getoption("--corpus") and manifest_path.is_file():
        rows = small_closed(manifest(manifest_path.parent))
        metafunc.parametrize("corpus_small", rows, ids=[m["name"] for m in rows])
    else:
        metafunc.parametrize("corpus_small", [None], ids=["corpus"])


# ------------------------------------------------------------------------ meshes

def manifest(meshes):
    """The rows of `meshes/manifest.csv` (columns name, set, file, V, E, F, components,
    genus, euler, orientable, ...)."""
    with open(Path(meshes) / "manifest.csv", newline="") as f:
        return list(csv.DictReader(f))


def small_closed(rows):
    return [m for m in rows if m["set"] == "closed" and int(m["F"]) <= SMALL_FACES]


def data_mesh(name, kind="closed"):
    """A mesh of the repository's `tests/data/meshes`."""
    return DATA / kind / f"{name}.off.gz"


def cli_binary() -> Path:
    """The release binary `contractible` that `cargo build --release -p contractible-cli`
    (or the README's test command) builds in the workspace's target folder (CI builds it
    before running pytest); CONTRACTIBLE_BIN overrides."""
    env = os.environ.get("CONTRACTIBLE_BIN")
    if env:
        return Path(env)
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "contractible"


@pytest.fixture(scope="session")
def cli():
    exe = cli_binary()
    if not exe.exists():
        pytest.fail(f"{exe} not found: build it with `cargo build --release -p contractible-cli` "
                    "or set CONTRACTIBLE_BIN")

    def run(*args, check=True):
        r = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True)
        if check and r.returncode != 0:
            raise AssertionError(f"contractible {' '.join(map(str, args))}: {r.stderr}")
        return r

    return run


# Meshes made at test time, by name: the arguments of `contractible gen`, or a NumPy
# construction (see `many_components_mesh`).
GENERATED = {
    "tetrahedron": ["tetrahedron"],
    "octahedron": ["octahedron"],
    "torus7": ["torus7"],
    "klein": ["klein"],
    # A genus-2 marching-tetrahedra surface with positions (2,160 faces).
    "genus2_iso": ["isosurface", "--surface", "genus:2", "--resolution", 16],
    # A random orientable genus-2 surface (positions all at the origin).
    "random_g2": ["random", "--genus", 2, "--faces", 1500, "--seed", 7],
    # The two-sheeted hyperboloid cut by its box: two discs, open.
    "hyperboloid": ["isosurface", "--surface", "hyperboloid", "--resolution", 12],
    # NumPy constructions.
    "many_components": None,
    "bunny_open": None,
}


def bunny_open_mesh():
    """The bunny of tests/data/meshes without its first face: a real mesh with one
    boundary loop (of 3 edges)."""
    V, F = read_off(data_mesh("bunny_npm"))
    return V, F[1:]


def many_components_mesh(cli, d):
    """120 disjoint closed components (tetrahedra, octahedra, icosahedra, 7-vertex tori,
    6-vertex projective planes), each moved to its own place: a mesh with many
    components, one of them non-orientable every fifth."""
    parts = []
    for kind in ["tetrahedron", "octahedron", "icosahedron", "torus7", "rp2"]:
        p = d / f"part_{kind}.off"
        cli("gen", kind, "-o", p, "--quiet")
        parts.append(read_off(p))
    Vs, Fs, n = [], [], 0
    for i in range(120):
        V, F = parts[i % len(parts)]
        Vs.append(V + np.array([4.0 * i, 0.0, 0.0]))
        Fs.append(F + n)
        n += len(V)
    return np.vstack(Vs), np.vstack(Fs)


def read_off(path):
    """An ASCII OFF file of triangles, optionally gzipped, read without the library."""
    path = Path(path)
    raw = path.read_bytes()
    if path.suffix == ".gz":
        raw = gzip.decompress(raw)
    words = raw.decode().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    V = np.array(words[at:at + 3 * nv], dtype=np.float64).reshape(nv, 3)
    at += 3 * nv
    F = np.array(words[at:at + 4 * nf], dtype=np.int64).reshape(nf, 4)
    assert np.all(F[:, 0] == 3)
    return V, F[:, 1:]


def write_off(path, V, F):
    """An ASCII OFF file, written without the library."""
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        for x, y, z in np.asarray(V).tolist():
            f.write(f"{x!r} {y!r} {z!r}\n")
        for a, b, c in np.asarray(F).tolist():
            f.write(f"3 {a} {b} {c}\n")


@pytest.fixture(scope="session")
def mesh_file(cli, tmp_path_factory):
    """The file of a mesh by name: a mesh of `tests/data/meshes/closed`, or one of
    GENERATED, made on first use."""
    d = tmp_path_factory.mktemp("generated")
    made = {}

    def path(name):
        if name not in GENERATED:
            p = data_mesh(name)
            assert p.is_file(), p
            return p
        if name not in made:
            p = d / f"{name}.off"
            if name == "many_components":
                write_off(p, *many_components_mesh(cli, d))
            elif name == "bunny_open":
                write_off(p, *bunny_open_mesh())
            else:
                cli("gen", *GENERATED[name], "-o", p, "--quiet")
            made[name] = p
        return made[name]

    return path


# ---------------------------------------------------------------- independent checks

def edges_of(F):
    """Undirected edges -> list of faces containing them."""
    faces_of = defaultdict(list)
    for i, (a, b, c) in enumerate(np.asarray(F).tolist()):
        for u, v in ((a, b), (b, c), (c, a)):
            faces_of[(min(u, v), max(u, v))].append(i)
    return faces_of


def components(F):
    """Face components (lists of face indices), by shared vertices (union-find)."""
    F = np.asarray(F)
    parent = {}

    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b, c in F.tolist():
        ra, rb, rc = find(a), find(b), find(c)
        parent[rb] = ra
        parent[find(rc)] = ra
    groups = defaultdict(list)
    for i, (a, _, _) in enumerate(F.tolist()):
        groups[find(a)].append(i)
    return list(groups.values())


def orientable(F):
    """Whether the faces can be oriented coherently (BFS over shared edges, flipping a
    face when its shared edge runs the same way as its neighbour's)."""
    F = np.asarray(F).tolist()
    faces_of = defaultdict(list)
    for i, (a, b, c) in enumerate(F):
        for u, v in ((a, b), (b, c), (c, a)):
            faces_of[frozenset((u, v))].append(i)
    sign = [0] * len(F)

    def directed(i, s):
        a, b, c = F[i]
        es = [(a, b), (b, c), (c, a)]
        return es if s > 0 else [(v, u) for u, v in es]

    for start in range(len(F)):
        if sign[start]:
            continue
        sign[start] = 1
        stack = [start]
        while stack:
            i = stack.pop()
            for u, v in directed(i, sign[i]):
                for j in faces_of[frozenset((u, v))]:
                    if j == i:
                        continue
                    # j must run the edge the other way: v -> u.
                    want = 1 if (v, u) in directed(j, 1) else -1
                    if sign[j] == 0:
                        sign[j] = want
                        stack.append(j)
                    elif sign[j] != want:
                        return False
    return True


def surface_signature(F):
    """Sorted (chi, orientable, boundary loops) per component, from the face list."""
    out = []
    F = np.asarray(F)
    for comp in components(F):
        f = F[comp]
        e = edges_of(f)
        v = len(np.unique(f))
        boundary = [k for k, fs in e.items() if len(fs) == 1]
        # Boundary loops: components of the boundary edges' graph.
        adj = defaultdict(list)
        for a, b in boundary:
            adj[a].append(b)
            adj[b].append(a)
        seen, loops = set(), 0
        for s in adj:
            if s in seen:
                continue
            loops += 1
            stack = [s]
            seen.add(s)
            while stack:
                x = stack.pop()
                for y in adj[x]:
                    if y not in seen:
                        seen.add(y)
                        stack.append(y)
        out.append((v - len(e) + len(f), orientable(f), loops))
    return sorted(out)


def is_closed_manifold_faces(F):
    return all(len(fs) == 2 for fs in edges_of(F).values())


def contractible_edges(F):
    """Edges satisfying the link condition, by the definition: on a closed surface an
    edge uv is contractible iff u and v have exactly two common neighbours (the
    vertices opposite uv) and its component is not the tetrahedron boundary."""
    F = np.asarray(F)
    nbrs = defaultdict(set)
    for a, b, c in F.tolist():
        nbrs[a] |= {b, c}
        nbrs[b] |= {a, c}
        nbrs[c] |= {a, b}
    bad = []
    for comp in components(F):
        f = F[comp]
        if len(np.unique(f)) == 4:
            continue  # the tetrahedron boundary: irreducible
        for (u, v) in edges_of(f):
            if len(nbrs[u] & nbrs[v]) == 2:
                bad.append((u, v))
    return bad
