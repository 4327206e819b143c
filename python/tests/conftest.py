"""Shared fixtures: the shared meshes, the command-line binary, and independent checks
written from the definitions (no code of the library is used to check its results)."""

import os
import subprocess
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
SHARED = Path(os.environ.get("CONTRACTIBLE_SHARED", ROOT.parent / "shared"))
MESHES = SHARED / "meshes"


def cli_binary() -> Path:
    """The release binary `cargo test --release --features invariants,cli` builds (CI
    builds it before running pytest); CONTRACTIBLE_BIN overrides."""
    env = os.environ.get("CONTRACTIBLE_BIN")
    if env:
        return Path(env)
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "contractible"


@pytest.fixture(scope="session")
def cli():
    exe = cli_binary()
    if not exe.exists():
        pytest.fail(f"{exe} not found: build it with `cargo build --release --features cli` "
                    "or set CONTRACTIBLE_BIN")

    def run(*args, check=True):
        r = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True)
        if check and r.returncode != 0:
            raise AssertionError(f"contractible {' '.join(map(str, args))}: {r.stderr}")
        return r

    return run


def manifest():
    import csv
    with open(MESHES / "manifest.csv", newline="") as f:
        return list(csv.DictReader(f))


def closed_meshes(max_faces):
    return [m for m in manifest() if m["set"] == "closed" and int(m["F"]) <= max_faces]


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
