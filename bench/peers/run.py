#!/usr/bin/env python3
"""Side-by-side comparison of `contractible` with libigl and pymeshlab.

For every selected mesh of ../shared/meshes/closed/ the arrays are loaded once; then, per
task, every library runs on them in alternation (round r starts with library r mod k), and
the medians of the wall-clock times are reported. Every output is checked here, by code
written from the definitions and independent of the libraries:

- reduce: the output is a closed 2-manifold with the input's topology (Euler
  characteristic and orientability of every component) and no edge satisfies the link
  condition Lk(u) ∩ Lk(v) = Lk(uv) (the tetrahedron's boundary passes: every edge of K4
  fails the condition, it is irreducible);
- quad: the share of input triangles paired into quads (each quad verified to be the union
  of two output triangles sharing its diagonal) and the number of input triangles that are
  not in the output triangulation (changed by edge flips or remeshing);
- simplify (ε = 1 % of the bounding-box diagonal): faces out, whether the output is still
  a 2-manifold and whether the topology is unchanged.

Writes docs/peers.md, docs/peers/{reduce,quad,simplify}.png and docs/peers/results.json.

    python bench/peers/run.py            # the full comparison (≈ 10 min on an idle 2-core machine)
    python bench/peers/run.py --quick    # smoke test: 3 small meshes, one round, temp dir
"""

import argparse
import gc
import gzip
import json
import os
import platform
import shlex
import statistics
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from importlib import metadata
from pathlib import Path

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

import contractible
import igl
import pymeshlab

REPO = Path(__file__).resolve().parents[2]
DEFAULT_MESHES = REPO.parent / "shared" / "meshes" / "closed"

# Small and medium meshes spanning sizes, genus and components; every mesh of the directory
# with at least LARGE faces is added to them.
SMALL_MEDIUM = [
    "tiny_torus", "double_torus", "chair", "socket", "adis16480_stl", "stratocaster",
    "casting", "fertility_14k", "horse_20k", "input_wheel", "bunny_35k",
]
QUICK = ["tiny_torus", "socket", "casting"]
LARGE = 80_000

TASKS = {
    "reduce": ["contractible.reduce", "igl.decimate", "pymeshlab.quadric"],
    "quad": ["contractible.quad(lrs)", "contractible.quad(ps)", "pymeshlab.smart_pairing",
             "pymeshlab.quad_dominant"],
    "simplify": ["contractible.simplify", "pymeshlab.clustering", "pymeshlab.merge_close"],
}
OURS = {"reduce": "contractible.reduce", "quad": "contractible.quad(lrs)",
        "simplify": "contractible.simplify"}


# --------------------------------------------------------------------------------------
# Input


def read_off_gz(path):
    """(V float64 (n, 3), F int64 (m, 3)) of a gzip-compressed ASCII OFF of triangles."""
    with gzip.open(path, "rt") as f:
        words = " ".join(line.split("#", 1)[0] for line in f).split()
    if not words or words[0] != "OFF":
        raise ValueError(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    p = 4
    V = np.array(words[p:p + 3 * nv], dtype=np.float64).reshape(nv, 3)
    p += 3 * nv
    F = np.array(words[p:p + 4 * nf], dtype=np.int64).reshape(nf, 4)
    if not (F[:, 0] == 3).all():
        raise ValueError(f"{path}: not a triangle mesh")
    return V, np.ascontiguousarray(F[:, 1:])


def off_face_count(path):
    """The face count in the header of a gzip-compressed OFF (reads only the first lines)."""
    with gzip.open(path, "rt") as f:
        words = []
        for line in f:
            words += line.split("#", 1)[0].split()
            if len(words) >= 3:
                return int(words[2])
    raise ValueError(f"{path}: truncated OFF header")


# --------------------------------------------------------------------------------------
# Independent checks (from the definitions; none of the benchmarked libraries is used)


def surface_report(F):
    """Combinatorial facts about the faces F (unreferenced vertices are ignored).

    manifold: no degenerate or duplicate face, every edge in at most two faces, every
    vertex with a single fan of faces; closed: manifold and every edge in exactly two.
    components: sorted (χ, orientable) per connected component (orientable None when an
    edge has more than two faces).
    """
    F = np.asarray(F, dtype=np.int64).reshape(-1, 3)
    m = len(F)
    rep = {"faces": int(m), "vertices": 0, "edges": 0, "degenerate": 0, "duplicate": 0,
           "boundary_edges": 0, "nonmanifold_edges": 0, "nonmanifold_vertices": 0,
           "manifold": m > 0, "closed": False, "components": []}
    if m == 0:
        return rep
    degenerate = (F[:, 0] == F[:, 1]) | (F[:, 1] == F[:, 2]) | (F[:, 0] == F[:, 2])
    rep["degenerate"] = int(degenerate.sum())
    srt = np.sort(F, axis=1)
    rep["duplicate"] = int(m - len(np.unique(srt, axis=0)))
    used, inv = np.unique(F, return_inverse=True)
    Fr = inv.reshape(F.shape)
    n = len(used)
    rep["vertices"] = int(n)

    frm = Fr.ravel()
    to = Fr[:, [1, 2, 0]].ravel()
    lo, hi = np.minimum(frm, to), np.maximum(frm, to)
    key = lo * n + hi
    ukey, kinv, counts = np.unique(key, return_inverse=True, return_counts=True)
    rep["edges"] = int(len(ukey))
    rep["boundary_edges"] = int((counts == 1).sum())
    rep["nonmanifold_edges"] = int((counts > 2).sum())

    # Components (through edges), χ per component.
    ea, eb = ukey // n, ukey % n
    g = coo_matrix((np.ones(len(ukey)), (ea, eb)), shape=(n, n))
    ncomp, vlab = connected_components(g, directed=False)
    vc = np.bincount(vlab, minlength=ncomp)
    ec = np.bincount(vlab[ea], minlength=ncomp)
    fc = np.bincount(vlab[Fr[:, 0]], minlength=ncomp)
    chi = vc - ec + fc

    # Pairs of half-edges on the edges with exactly two faces.
    order = np.argsort(kinv, kind="stable")
    starts = np.concatenate(([0], np.cumsum(counts)[:-1]))
    two = counts == 2
    h1, h2 = order[starts[two]], order[starts[two] + 1]
    f1, f2 = h1 // 3, h2 // 3

    # Vertex fans: corners at the same vertex are linked across each two-face edge.
    # Corner 3f+i sits at Fr[f, i]; half-edge 3f+i runs from corner 3f+i to 3f+(i+1)%3.
    nxt = lambda h: (h // 3) * 3 + (h % 3 + 1) % 3  # noqa: E731
    same_dir = frm[h1] == frm[h2]
    a1, b1 = h1, nxt(h1)                       # corners of f1 at from(h1), to(h1)
    a2 = np.where(same_dir, h2, nxt(h2))       # corner of f2 at from(h1)
    b2 = np.where(same_dir, nxt(h2), h2)       # corner of f2 at to(h1)
    rows = np.concatenate((a1, b1))
    cols = np.concatenate((a2, b2))
    cg = coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(3 * m, 3 * m))
    _, clab = connected_components(cg, directed=False)
    fans = np.unique(np.stack((Fr.ravel(), clab)), axis=1)[0]
    rep["nonmanifold_vertices"] = int((np.bincount(fans, minlength=n) > 1).sum())

    rep["manifold"] = (rep["degenerate"] == 0 and rep["duplicate"] == 0
                       and rep["nonmanifold_edges"] == 0 and rep["nonmanifold_vertices"] == 0)
    rep["closed"] = rep["manifold"] and rep["boundary_edges"] == 0

    # Orientability: the orientation double cover of a component is connected iff the
    # component is non-orientable. Faces f1, f2 on an edge are coherent when they run
    # through it in opposite directions.
    orient = [None] * ncomp
    if rep["nonmanifold_edges"] == 0 and rep["degenerate"] == 0:
        coherent = ~same_dir
        r = np.concatenate((f1, f1 + m))
        c = np.concatenate((np.where(coherent, f2, f2 + m), np.where(coherent, f2 + m, f2)))
        dg = coo_matrix((np.ones(len(r)), (r, c)), shape=(2 * m, 2 * m))
        _, dlab = connected_components(dg, directed=False)
        fcomp = vlab[Fr[:, 0]]
        sheets = np.unique(np.stack((np.concatenate((fcomp, fcomp)), dlab)), axis=1)[0]
        per = np.bincount(sheets, minlength=ncomp)
        orient = [bool(x == 2) for x in per]
    rep["components"] = sorted((int(chi[i]), orient[i]) for i in range(ncomp))
    return rep


def topology_kept(before, after):
    """The output is a closed 2-manifold whose components have the input's (χ, orientable)."""
    return bool(after["closed"] and after["components"] == before["components"])


def contractible_edge_count(F):
    """Number of edges uv satisfying the link condition Lk(u) ∩ Lk(v) = Lk(uv), on a
    closed 2-manifold (naive: vertex neighbour sets and link-edge sets per vertex)."""
    nbr = defaultdict(set)
    link_edges = defaultdict(set)
    opposite = defaultdict(set)
    for a, b, c in np.asarray(F).tolist():
        for v, x, y in ((a, b, c), (b, c, a), (c, a, b)):
            nbr[v].update((x, y))
            link_edges[v].add((min(x, y), max(x, y)))
            opposite[(min(v, x), max(v, x))].add(y)
    count = 0
    for (u, v), lk_uv in opposite.items():
        if (nbr[u] & nbr[v]) == lk_uv and not (link_edges[u] & link_edges[v]):
            count += 1
    return count


def reduce_check(before, F_out):
    rep = surface_report(F_out)
    left = contractible_edge_count(F_out) if rep["closed"] else None
    return {"faces_out": rep["faces"], "vertices_out": rep["vertices"],
            "manifold": rep["manifold"], "closed": rep["closed"],
            "contractible_edges_left": left,
            "irreducible": bool(rep["closed"] and left == 0),
            "topology_kept": topology_kept(before, rep)}


def tri_keys(F, n):
    s = np.sort(np.asarray(F, dtype=np.int64), axis=1)
    return (s[:, 0] * n + s[:, 1]) * n + s[:, 2]


def triangles_changed(F_in, F_out, n):
    """Input triangles (as vertex sets) absent from the output triangulation."""
    return int((~np.isin(tri_keys(F_in, n), tri_keys(F_out, n))).sum())


def triangulation_facts(before, T):
    """Whether the triangulation under the quads is still a closed 2-manifold of the
    input's topology, and what breaks it when not."""
    rep = surface_report(T)
    bad = {k: rep[k] for k in ("degenerate", "duplicate", "nonmanifold_edges",
                               "nonmanifold_vertices", "boundary_edges") if rep[k]}
    return {"triangulation_topology_kept": topology_kept(before, rep),
            "triangulation_defects": bad}


def quad_check_contractible(before, F_in, q, n):
    """contractible.quad: every row of q.triangles in exactly one pair, the two triangles
    of a pair share an edge and span the quad's four vertices."""
    m = len(F_in)
    T, P, Q = np.asarray(q.triangles), np.asarray(q.pairs), np.asarray(q.quads)
    ok = len(T) == m and len(P) == len(Q) and np.array_equal(
        np.sort(P.ravel()), np.arange(len(P) * 2)) and 2 * len(P) <= m
    good = 0
    if ok:
        for (i, j), quad in zip(P.tolist(), Q.tolist()):
            a, b = set(T[i].tolist()), set(T[j].tolist())
            if len(a & b) == 2 and a | b == set(quad) and len(set(quad)) == 4:
                good += 1
    return {"paired_pct": 100.0 * 2 * good / m, "pairing_verified": bool(ok and good == len(P)),
            "triangles_changed": triangles_changed(F_in, T, n),
            **triangulation_facts(before, T)}


def quad_check_pymeshlab(before, V_in, F_in, V_out, tris, polys):
    """pymeshlab keeps the triangles (face_matrix) and marks each quad's diagonal as a
    'faux' edge; polygonal_face_list() returns the polygons those marks bound. A quad counts
    as paired when two output triangles share one of its diagonals and span it."""
    m, n = len(F_in), len(V_in)
    same_vertices = V_out.shape == V_in.shape and np.array_equal(V_out, V_in)
    tris = np.asarray(tris, dtype=np.int64)
    if not same_vertices:
        # map output vertices to input indices by exact position
        where = {tuple(p): i for i, p in enumerate(V_in.tolist())}
        remap = np.array([where.get(tuple(p), -1) for p in V_out.tolist()], dtype=np.int64)
        if (remap < 0).any():
            return {"paired_pct": None, "pairing_verified": False, "triangles_changed": None,
                    "note": "output vertices moved"}
        tris = remap[tris]
        polys = [remap[np.asarray(p, dtype=np.int64)] for p in polys]
    keys = set(tri_keys(tris, n).tolist())
    sizes = defaultdict(int)
    good = 0
    for p in polys:
        p = [int(x) for x in p]
        sizes[len(p)] += 1
        if len(p) != 4:
            continue
        a, b, c, d = p
        k = lambda x, y, z: int(tri_keys(np.array([[x, y, z]]), n)[0])  # noqa: E731
        if (k(a, b, c) in keys and k(a, c, d) in keys) or (k(a, b, d) in keys and k(b, c, d) in keys):
            good += 1
    return {"paired_pct": 100.0 * 2 * good / m,
            "pairing_verified": good == sizes.get(4, 0),
            "triangles_changed": triangles_changed(F_in, tris, n),
            "polygon_sizes": {str(k): v for k, v in sorted(sizes.items())},
            "output_triangles": int(len(tris)), "same_vertices": bool(same_vertices),
            **triangulation_facts(before, tris)}


def simplify_check(before, F_out):
    rep = surface_report(F_out)
    return {"faces_out": rep["faces"], "vertices_out": rep["vertices"],
            "manifold": rep["manifold"], "closed": rep["closed"],
            "degenerate": rep["degenerate"], "duplicate": rep["duplicate"],
            "nonmanifold_edges": rep["nonmanifold_edges"],
            "nonmanifold_vertices": rep["nonmanifold_vertices"],
            "boundary_edges": rep["boundary_edges"],
            "topology_kept": topology_kept(before, rep)}


def self_test():
    """The checks on known surfaces, so that a broken check cannot pass silently."""
    tetra = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
    octa = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    rp2 = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5], [0, 5, 1],
           [1, 2, 4], [2, 3, 5], [3, 4, 1], [4, 5, 2], [5, 1, 3]]
    pinched = tetra + [[t[0] + 3, t[1] + 3, t[2] + 3] for t in tetra]  # two spheres at vertex 3
    r = surface_report(tetra)
    assert r["closed"] and r["components"] == [(2, True)], r
    assert contractible_edge_count(tetra) == 0
    assert contractible_edge_count(octa) == 12
    r = surface_report(rp2)
    assert r["closed"] and r["components"] == [(1, False)], r
    assert contractible_edge_count(rp2) == 0  # the 6-vertex RP² is irreducible
    r = surface_report(pinched)
    assert not r["manifold"] and r["nonmanifold_vertices"] == 1, r
    r = surface_report(tetra[:3])
    assert r["manifold"] and not r["closed"] and r["boundary_edges"] == 3, r
    r = surface_report(tetra + [[0, 1, 2]])
    assert not r["manifold"] and r["duplicate"] == 1, r


# --------------------------------------------------------------------------------------
# The runs. Each returns the output arrays a user would take away (NumPy out).


def pml_run(V, F, filt, **kw):
    """NumPy in, filter, NumPy out; building the pymeshlab Mesh is part of the time, as
    copying the arrays in is part of contractible's."""
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(V, F))
    getattr(ms, filt)(**kw)
    mm = ms.current_mesh()
    if not mm.is_compact():  # deleted elements stay in place until compacted
        mm.compact()
    return ms, mm  # the MeshSet owns the mesh: keep it alive while the arrays are read


def make_runs(task, V, F, eps):
    Vf, Ff = np.asfortranarray(V), np.asfortranarray(F.astype(np.int32))  # igl's layout
    if task == "reduce":
        def ours():
            r = contractible.reduce(V, F)
            return r.vertices, r.faces, r.stats, r.vertex_map

        def igl_dec():
            U, G, _, I = igl.decimate(Vf, Ff, 0)
            return U, G, I  # I: the input vertex each output vertex was born from

        def pml_q():
            ms, mm = pml_run(V, F, "meshing_decimation_quadric_edge_collapse",
                         targetfacenum=1, preservetopology=True)
            return mm.vertex_matrix(), mm.face_matrix()

        return {"contractible.reduce": ours, "igl.decimate": igl_dec, "pymeshlab.quadric": pml_q}
    if task == "quad":
        def pml_quad(filt):
            def run():
                ms, mm = pml_run(V, F, filt)
                return mm.vertex_matrix(), mm.face_matrix(), mm.polygonal_face_list()
            return run

        return {"contractible.quad(lrs)": lambda: contractible.quad(V, F, algo="lrs"),
                "contractible.quad(ps)": lambda: contractible.quad(V, F, algo="ps"),
                "pymeshlab.smart_pairing": pml_quad("meshing_tri_to_quad_by_smart_triangle_pairing"),
                "pymeshlab.quad_dominant": pml_quad("meshing_tri_to_quad_dominant")}
    if task == "simplify":
        def ours():
            s = contractible.simplify(V, F, eps_rel=0.01)
            return s.vertices, s.faces, s.stats

        def pml_s(filt):
            def run():
                ms, mm = pml_run(V, F, filt, threshold=pymeshlab.PureValue(eps))
                return mm.vertex_matrix(), mm.face_matrix()
            return run

        return {"contractible.simplify": ours,
                "pymeshlab.clustering": pml_s("meshing_decimation_clustering"),
                "pymeshlab.merge_close": pml_s("meshing_merge_close_vertices")}
    raise ValueError(task)


def conformance_verdict(lib, V, F, out):
    """The library's own conformance checker (`contractible.check("reduce", ...)`) on an
    output, beside the script's checks: in the input's vertex ids where the library says
    which input vertex each output vertex is (contractible: `vertex_map`; igl.decimate:
    its birth-vertex map I, the positions having moved to edge midpoints), else as a
    combinatorial answer in its own ids (pymeshlab moves vertices and gives no map)."""
    n = len(V)
    if lib.startswith("contractible"):
        ids = np.asarray(out[3])
    elif lib == "igl.decimate":
        ids = np.asarray(out[2]).reshape(-1)
    else:
        ids = None
    G = np.asarray(out[1], dtype=np.int64).reshape(-1, 3)
    if ids is not None:
        v = contractible.check("reduce", None, F, None, ids[G], vertex_count=n,
                               out_vertex_count=n)
    else:
        v = contractible.check("reduce", None, F, None, G, vertex_count=n,
                               out_vertex_count=len(out[0]))
    return {"check_passed": bool(v["passed"]), "check_counts": v["counts"]}


def check(task, lib, V, F, before, out):
    n = len(V)
    if task == "reduce":
        rep = reduce_check(before, out[1])
        rep.update(conformance_verdict(lib, V, F, out))
        return rep
    if task == "quad":
        if lib.startswith("contractible"):
            return quad_check_contractible(before, F, out, n)
        return quad_check_pymeshlab(before, V, F, out[0], out[1], out[2])
    return simplify_check(before, out[1])


def bench_task(task, V, F, eps, before, args, skipped, spent, log):
    """Alternating rounds; a library stops repeating on this mesh once its time here
    exceeds --case-budget (it keeps the rounds done); a peer whose runs in this task have
    taken more than --peer-budget seconds in all is skipped on the remaining (larger)
    meshes."""
    runs = make_runs(task, V, F, eps)
    libs = list(runs)
    times = {lib: [] for lib in libs}
    alg = {lib: [] for lib in libs}  # contractible's own clock: the algorithm alone
    outputs = {}
    active = [lib for lib in libs if lib not in skipped[task]]
    for lib in libs:
        if lib in skipped[task]:
            log(f"    {lib}: not run ({skipped[task][lib]})")
    rounds = max(args.reps, args.peer_reps)
    for r in range(rounds):
        k = len(active)
        if k == 0:
            break
        for lib in active[r % k:] + active[:r % k]:
            want = args.reps if lib.startswith("contractible") else args.peer_reps
            if len(times[lib]) >= want or sum(times[lib]) > args.case_budget:
                continue
            gc.collect()
            t0 = time.perf_counter()
            out = runs[lib]()
            times[lib].append(time.perf_counter() - t0)
            if lib.startswith("contractible"):
                st = out.stats if hasattr(out, "stats") else out[2]
                alg[lib].append(st["seconds"] if "seconds" in st else st["total_seconds"])
            if lib not in outputs:
                outputs[lib] = out
    results = {}
    for lib in libs:
        if not times[lib]:
            results[lib] = {"skipped": skipped[task].get(lib, "not run")}
            continue
        res = {"median_s": statistics.median(times[lib]), "runs": len(times[lib]),
               "times_s": times[lib]}
        if alg[lib]:
            res["algorithm_median_s"] = statistics.median(alg[lib])
        res.update(check(task, lib, V, F, before, outputs[lib]))
        spent[task][lib] += sum(times[lib])
        if spent[task][lib] > args.peer_budget and not lib.startswith("contractible"):
            skipped[task][lib] = (f"its {task} runs took {spent[task][lib]:.0f} s "
                                  f"up to {len(F)} triangles, over --peer-budget "
                                  f"{args.peer_budget:g} s")
        results[lib] = res
        log(f"    {lib}: {fmt_ms(res['median_s'])} ms (n={res['runs']}) "
            + ", ".join(f"{k}={v}" for k, v in res.items()
                        if k not in ("median_s", "runs", "times_s", "algorithm_median_s")))
    return results


# --------------------------------------------------------------------------------------
# Report


DEFECT = {"degenerate": "degenerate face", "duplicate": "duplicate face",
          "nonmanifold_edges": "non-manifold edge", "nonmanifold_vertices": "non-manifold vertex",
          "boundary_edges": "boundary edge"}


def plural(k, noun):
    if k == 1:
        return f"1 {noun}"
    return f"{k} " + (noun[:-2] + "ices" if noun.endswith("vertex") else noun + "s")


def fmt_ms(s):
    ms = 1000 * s
    return f"{ms:.3g}" if ms < 100 else f"{ms:.0f}"


def yn(x):
    return "–" if x is None else ("yes" if x else "**no**")


def machine():
    cpu = "unknown"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        nproc = subprocess.run(["nproc"], capture_output=True, text=True).stdout.strip()
    except OSError:
        nproc = str(os.cpu_count())
    mem = ""
    try:
        for line in open("/proc/meminfo"):
            if line.startswith("MemTotal"):
                mem = f"{int(line.split()[1]) / 2**20:.1f} GiB"
    except OSError:
        pass
    return {"cpu": cpu, "nproc": nproc, "memory": mem, "os": platform.platform(),
            "python": platform.python_version()}


def versions():
    v = {}
    for pkg in ("contractible", "libigl", "pymeshlab", "numpy", "scipy", "matplotlib"):
        try:
            v[pkg] = metadata.version(pkg)
        except metadata.PackageNotFoundError:
            v[pkg] = "?"
    try:
        v["contractible commit"] = subprocess.run(
            ["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"],
            capture_output=True, text=True).stdout.strip() or "?"
    except OSError:
        v["contractible commit"] = "?"
    return v


def plot(task, data, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.8))
    markers = "osD^v<>"
    for i, lib in enumerate(TASKS[task]):
        pts = sorted((d["triangles"], d["tasks"][task][lib]["median_s"]) for d in data
                     if task in d["tasks"] and "median_s" in d["tasks"][task].get(lib, {}))
        if pts:
            x, y = zip(*pts)
            ax.plot(x, y, marker=markers[i % len(markers)], label=lib, linewidth=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("input triangles")
    ax.set_ylabel("median wall time [s]")
    ax.set_title({"reduce": "irreducible triangulation", "quad": "tri → quad conversion",
                  "simplify": "short-edge simplification, ε = 1 % of the diagonal"}[task])
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def cell(res, ours):
    """'median ms (ratio×)' with ratio = this library's median / contractible's."""
    if "median_s" not in res:
        return "not run"
    s = fmt_ms(res["median_s"])
    if "algorithm_median_s" in res:
        s += f" (alg. {fmt_ms(res['algorithm_median_s'])})"
    if ours is not None and res is not ours and "median_s" in ours:
        s += f" ({res['median_s'] / ours['median_s']:.1f}×)"
    if res["runs"] < 5:
        s += f" n={res['runs']}"
    return s


def write_report(meta, data, out_md):
    L = []
    w = L.append
    w("# contractible beside libigl and pymeshlab")
    w("")
    w("Generated by `bench/peers/run.py`; do not edit by hand. Command:")
    w("")
    w(f"    {meta['command']}")
    w("")
    w(f"Run on {meta['date']}, {meta['elapsed_s'] / 60:.1f} min in all. "
      f"Machine: {meta['machine']['cpu']}, `nproc` = {meta['machine']['nproc']}, "
      f"{meta['machine']['memory']}, {meta['machine']['os']}, Python {meta['machine']['python']}. "
      f"1-min load average sampled at every mesh: {min(meta['load']):.1f} to "
      f"{max(meta['load']):.1f} (on {meta['machine']['nproc']} cores: a load well above "
      f"{meta['machine']['nproc']} means other processes competed for them).")
    if meta.get("note"):
        w("")
        w(f"**Note:** {meta['note']}")
    w("")
    w("Versions: " + ", ".join(f"{k} {v}" for k, v in meta["versions"].items()) + ".")
    w("")
    w("## How it is measured")
    w("")
    w(f"- Each mesh is read once (gzip OFF, by the script). Per task the libraries run in "
      f"alternation in one process (round r starts with library r mod k), medians of "
      f"{meta['args']['reps']} run(s) for contractible and up to {meta['args']['peer_reps']} "
      f"for the peers (`n=` marks fewer: a library stops repeating on a mesh once its time "
      f"there exceeds {meta['args']['case_budget']:g} s; a peer is skipped on the remaining, "
      f"larger meshes of a task once its runs in that task took "
      f"{meta['args']['peer_budget']:g} s in all: \"not run\").")
    w("- Wall time of NumPy in → NumPy out: `contractible.*(V, F)` (float64/int64 arrays, "
      "copied by the package); `igl.decimate(V, F, 0)` with V, F already in its "
      "Fortran-ordered float64/int32 layout; pymeshlab: `MeshSet()`, `add_mesh(Mesh(V, F))`, "
      "the filter, `compact()` when it left deleted elements, then `vertex_matrix()`, `face_matrix()` (and `polygonal_face_list()` for "
      "quads).")
    w("- Ratios in parentheses: the library's median / contractible's median of the whole "
      "call (above 1: contractible is faster). Quad ratios are against "
      "`contractible.quad(lrs)`. \"alg.\" is the median of contractible's own clock for the "
      "algorithm alone (`stats['seconds']`, quad `stats['total_seconds']`): the rest of the "
      "call is copying and checking the arrays, building the surface and making the outputs.")
    w("- Every output is checked by code in the script, independent of the three "
      "libraries: closed 2-manifold (no degenerate or duplicate face, every edge in exactly "
      "two faces, one fan per vertex), χ and orientability per component (orientation "
      "double cover) compared with the input's, and for reduce the naive link test: no edge "
      "uv with Lk(u) ∩ Lk(v) = Lk(uv) (the tetrahedron passes: it is irreducible).")
    w("")

    present = {t for d in data for t in d["tasks"]}
    if "reduce" in present:
        reduce_section(data, w)
    if "quad" in present:
        quad_section(data, w)
    if "simplify" in present:
        simplify_section(data, w)
    w("Raw times and checks: [`peers/results.json`](peers/results.json).")
    w("")
    # The decimation section is written by bench/peers/decimate.py: keep it.
    old = out_md.read_text() if out_md.exists() else ""
    begin, end = "<!-- decimation: begin", "<!-- decimation: end -->"
    if begin in old and end in old:
        w(old[old.index(begin):old.index(end) + len(end)])
        w("")
    out_md.write_text("\n".join(L))


def reduce_section(data, w):
    big = [d for d in data if d["triangles"] >= LARGE and "reduce" in d["tasks"]]
    w("## Irreducible triangulation")
    w("")
    w("`contractible.reduce(V, F)` (RS) vs `igl.decimate(V, F, 0)` (shortest-edge collapse "
      "until no collapse is allowed) vs pymeshlab "
      "`meshing_decimation_quadric_edge_collapse(targetfacenum=1, preservetopology=True)`.")
    w("")
    if big:
        rat = [(d["name"], d["tasks"]["reduce"]["igl.decimate"]["median_s"]
                / d["tasks"]["reduce"]["contractible.reduce"]["median_s"]) for d in big
               if "median_s" in d["tasks"]["reduce"].get("igl.decimate", {})]
        missing = [d["name"] for d in big if "median_s" not in d["tasks"]["reduce"].get(
            "igl.decimate", {}) or "median_s" not in d["tasks"]["reduce"][OURS["reduce"]]]
        if missing:
            w(f"**Target not checked on {', '.join(missing)}** (a library was not run).")
            w("")
        if rat:
            worst = min(rat, key=lambda x: x[1])
            verdict = "met" if worst[1] >= 50 and not missing else "NOT met"
            w(f"**Target: contractible.reduce ≥ 50× faster than igl.decimate(V, F, 0) on every "
              f"shared mesh of ≥ {LARGE // 1000}k triangles: {verdict}.** The smallest ratio "
              f"over the {len(rat)} meshes is {worst[1]:.0f}× ({worst[0]}); all: "
              + ", ".join(f"{n} {r:.0f}×" for n, r in rat) + ".")
            alg = [(d["name"], d["tasks"]["reduce"]["igl.decimate"]["median_s"]
                    / d["tasks"]["reduce"][OURS["reduce"]]["algorithm_median_s"]) for d in big
                   if "median_s" in d["tasks"]["reduce"].get("igl.decimate", {})
                   and "algorithm_median_s" in d["tasks"]["reduce"][OURS["reduce"]]]
            if alg:
                w("")
                w("Against contractible's algorithm alone (RS, `stats['seconds']`, without "
                  "copying, validating and building the surface): "
                  + ", ".join(f"{n} {r:.0f}×" for n, r in alg) + ".")
            w("")
    libs = TASKS["reduce"]
    w("| mesh | triangles | χ (components) | " + " | ".join(f"{l} ms" for l in libs) + " |")
    w("|---|---:|---|" + "---:|" * len(libs))
    for d in data:
        t = d["tasks"].get("reduce")
        if not t:
            continue
        ours = t[OURS["reduce"]]
        w(f"| {d['name']} | {d['triangles']} | {d['chi']} | "
          + " | ".join(cell(t[l], ours) for l in libs) + " |")
    w("")
    skipped_lines(data, "reduce", w)
    w("Outputs (faces out; irreducible by the naive link test / topology unchanged / the "
      "verdict of `contractible check reduce`, the conformance checker):")
    w("")
    w("| mesh | " + " | ".join(libs) + " |")
    w("|---|" + "---|" * len(libs))
    for d in data:
        t = d["tasks"].get("reduce")
        if not t:
            continue
        cells = []
        for l in libs:
            r = t[l]
            if "faces_out" not in r:
                cells.append("not run")
                continue
            s = f"{r['faces_out']}; {yn(r['irreducible'])} / {yn(r['topology_kept'])}"
            if "check_passed" in r:
                s += f" / {yn(r['check_passed'])}"
            if r["contractible_edges_left"]:
                s += f" ({plural(r['contractible_edges_left'], 'contractible edge')} left)"
            if not r["closed"]:
                s += " (not a closed manifold)"
            cells.append(s)
        w(f"| {d['name']} | " + " | ".join(cells) + " |")
    w("")
    w(summary_line(data, "reduce", "irreducible", "irreducible output"))
    w(summary_line(data, "reduce", "topology_kept", "topology unchanged"))
    w(summary_line(data, "reduce", "check_passed", "passed by `contractible check reduce`"))
    agree = [d["name"] + " " + l for d in data for l, r in d["tasks"].get("reduce", {}).items()
             if "check_passed" in r and r["check_passed"] != (r["irreducible"] and r["topology_kept"])]
    w("- the checker's verdict equals (irreducible and topology unchanged) on every output"
      if not agree else f"- the checker disagrees with the script's checks on: {', '.join(agree)}")
    w("")
    w("![reduce](peers/reduce.png)")
    w("")


def quad_section(data, w):
    libs = TASKS["quad"]
    flags = [d["tasks"]["quad"][l]["same_vertices"] for d in data if "quad" in d["tasks"]
             for l in libs if "same_vertices" in d["tasks"]["quad"][l]]
    same, total = sum(flags), len(flags)
    w("## Tri → quad conversion")
    w("")
    w("`contractible.quad(V, F, algo=\"lrs\" | \"ps\")` (perfect pairings; LRS flips edges, "
      "PS does not) vs pymeshlab `meshing_tri_to_quad_by_smart_triangle_pairing()` and "
      "`meshing_tri_to_quad_dominant()` (default `level`, \"Fewest triangles\").")
    w("")
    w("How pymeshlab's quads are read: its filters keep a triangle mesh (`face_matrix()`) "
      "and mark the diagonal of each quad as a *faux* edge; "
      "`Mesh.polygonal_face_list()` returns the polygons bounded by the non-faux edges (a "
      "list of index arrays: length 4 for a quad, 3 for an unpaired triangle). A quad counts "
      "as paired when two triangles of `face_matrix()` share one of its diagonals and span "
      "its four vertices (output vertices are matched to the input's by position; here they "
      f"came out identical to the input's, in order, on {same}/{total} outputs). "
      "\"Paired\" = 2 × verified quads / input triangles; \"changed\" = input triangles (as "
      "vertex sets) absent from the output triangulation (`face_matrix()`; for contractible "
      "the paired triangulation `triangles`).")
    w("")
    w("| mesh | triangles | " + " | ".join(f"{l} ms" for l in libs) + " |")
    w("|---|---:|" + "---:|" * len(libs))
    for d in data:
        t = d["tasks"].get("quad")
        if not t:
            continue
        ours = t[OURS["quad"]]
        w(f"| {d['name']} | {d['triangles']} | " + " | ".join(cell(t[l], ours) for l in libs) + " |")
    w("")
    skipped_lines(data, "quad", w)
    w("Paired % / input triangles changed (the output triangulation is also checked: a "
      "closed 2-manifold with the input's χ and orientability per component, flagged when not):")
    w("")
    w("| mesh | " + " | ".join(libs) + " |")
    w("|---|" + "---|" * len(libs))
    for d in data:
        t = d["tasks"].get("quad")
        if not t:
            continue
        cells = []
        for l in libs:
            r = t[l]
            if r.get("paired_pct") is None:
                cells.append(r.get("note", "not run"))
                continue
            p = r["paired_pct"]
            s = ("100 %" if p == 100.0 else f"{min(p, 99.99):.2f} %") + f" / {r['triangles_changed']}"
            if not r["pairing_verified"]:
                s += " (pairing check failed)"
            if not r["triangulation_topology_kept"]:
                s += " (**output triangulation broken**: " + (", ".join(
                    plural(v, DEFECT[k]) for k, v in r["triangulation_defects"].items())
                    or "topology changed") + ")"
            cells.append(s)
        w(f"| {d['name']} | " + " | ".join(cells) + " |")
    w("")
    parts = []
    for lib in libs:
        vals = [d["tasks"]["quad"][lib]["paired_pct"] for d in data if "quad" in d["tasks"]
                and d["tasks"]["quad"][lib].get("paired_pct") is not None]
        if vals:
            parts.append(f"{lib} {sum(v == 100.0 for v in vals)}/{len(vals)}")
    w("- every triangle paired: " + ", ".join(parts) + ".")
    w(summary_line(data, "quad", "triangulation_topology_kept",
                   "output triangulation a closed 2-manifold of the input's topology"))
    w("")
    w("![quad](peers/quad.png)")
    w("")


def simplify_section(data, w):
    libs = TASKS["simplify"]
    w("## Short-edge simplification, ε = 1 % of the bounding-box diagonal")
    w("")
    w("`contractible.simplify(V, F, eps_rel=0.01)` (nested mode, midpoints) vs pymeshlab "
      "`meshing_decimation_clustering(threshold=PureValue(ε))` (vertex clustering, cell "
      "size ε) and `meshing_merge_close_vertices(threshold=PureValue(ε))`, with "
      "ε = 0.01 × ‖max − min‖ of the vertices (the same absolute value for all three; "
      "contractible's `stats['eps']` is compared with it).")
    w("")
    w("| mesh | triangles | " + " | ".join(f"{l} ms" for l in libs) + " |")
    w("|---|---:|" + "---:|" * len(libs))
    for d in data:
        t = d["tasks"].get("simplify")
        if not t:
            continue
        ours = t[OURS["simplify"]]
        w(f"| {d['name']} | {d['triangles']} | " + " | ".join(cell(t[l], ours) for l in libs) + " |")
    w("")
    skipped_lines(data, "simplify", w)
    w("Faces out; manifold / topology unchanged:")
    w("")
    w("| mesh | " + " | ".join(libs) + " |")
    w("|---|" + "---|" * len(libs))
    for d in data:
        t = d["tasks"].get("simplify")
        if not t:
            continue
        cells = []
        for l in libs:
            r = t[l]
            if "faces_out" not in r:
                cells.append("not run")
                continue
            s = f"{r['faces_out']}; {yn(r['manifold'])} / {yn(r['topology_kept'])}"
            bad = [plural(r[k], DEFECT[k]) for k in DEFECT if r.get(k)]
            if bad:
                s += " (" + ", ".join(bad) + ")"
            cells.append(s)
        w(f"| {d['name']} | " + " | ".join(cells) + " |")
    w("")
    eq = [d for d in data if d.get("contractible_eps") is not None]
    agree = [d for d in eq if np.isclose(d["contractible_eps"], d["eps"], rtol=1e-9, atol=0)]
    w(f"- contractible's `stats['eps']` equals the script's ε (relative 1e-9) on "
      f"{len(agree)}/{len(eq)} meshes" + ("" if len(agree) == len(eq) else ": **differs** on "
      + ", ".join(d["name"] for d in eq if d not in agree)) + ".")
    w(summary_line(data, "simplify", "manifold", "manifold output"))
    w(summary_line(data, "simplify", "topology_kept", "topology unchanged"))
    w("")
    w("![simplify](peers/simplify.png)")
    w("")


def skipped_lines(data, task, w):
    """One line per peer that was not run on some meshes, with the reason."""
    first = {}
    for d in data:
        for lib, r in d["tasks"].get(task, {}).items():
            if "skipped" in r and lib not in first:
                first[lib] = (d["name"], r["skipped"])
    for lib, (name, why) in first.items():
        w(f"- {lib} not run from {name} on ({why}).")
    if first:
        w("")


def summary_line(data, task, key, what):
    parts = []
    for lib in TASKS[task]:
        vals = [d["tasks"][task][lib].get(key) for d in data if task in d["tasks"]
                and key in d["tasks"][task].get(lib, {})]
        if vals:
            parts.append(f"{lib} {sum(bool(v) for v in vals)}/{len(vals)}")
    return f"- {what}: " + ", ".join(parts) + "."


# --------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--meshes-dir", type=Path, default=DEFAULT_MESHES)
    ap.add_argument("--meshes", help="comma-separated names (default: a selection plus every "
                    f"mesh of >= {LARGE} triangles)")
    ap.add_argument("--tasks", default="reduce,quad,simplify")
    ap.add_argument("--reps", type=int, default=None,
                    help="runs of contractible (median; default 5, 1 with --quick)")
    ap.add_argument("--peer-reps", type=int, default=None,
                    help="runs of libigl / pymeshlab (default: --reps)")
    ap.add_argument("--case-budget", type=float, default=20.0,
                    help="stop repeating a library on a mesh once its runs there took this "
                    "many seconds (default 20)")
    ap.add_argument("--peer-budget", type=float, default=150.0,
                    help="skip a peer on the remaining (larger) meshes of a task once its "
                    "runs in that task took this many seconds in all (default 150)")
    ap.add_argument("--quick", action="store_true",
                    help="smoke test: 3 small meshes, 1 run each, output to a temp dir")
    ap.add_argument("--out", type=Path, help="markdown report (default docs/peers.md; "
                    "with --quick a temporary directory)")
    ap.add_argument("--note", default=None, help="a sentence added to the report")
    args = ap.parse_args()
    if args.reps is None:
        args.reps = 1 if args.quick else 5
    if args.quick:
        if args.meshes is None:
            args.meshes = ",".join(QUICK)
    if args.peer_reps is None:
        args.peer_reps = args.reps
    if args.out is None:
        args.out = (Path(tempfile.mkdtemp(prefix="peers-quick-")) / "peers.md" if args.quick
                    else REPO / "docs" / "peers.md")
    plot_dir = args.out.parent / "peers"
    plot_dir.mkdir(parents=True, exist_ok=True)
    tasks = [t for t in args.tasks.split(",") if t]
    for t in tasks:
        if t not in TASKS:
            ap.error(f"unknown task {t!r}")

    if args.meshes:
        names = args.meshes.split(",")
    else:
        names = list(SMALL_MEDIUM)
        for p in sorted(args.meshes_dir.glob("*.off.gz")):
            name = p.name[:-len(".off.gz")]
            if name not in names and off_face_count(p) >= LARGE:
                names.append(name)
    paths = [args.meshes_dir / f"{n}.off.gz" for n in names]
    for p in paths:
        if not p.exists():
            ap.error(f"no mesh {p}")
    paths.sort(key=off_face_count)  # ascending, so --peer-budget prunes only the larger meshes

    self_test()
    log = lambda s: print(s, flush=True)  # noqa: E731
    t_start = time.perf_counter()
    loads = []  # 1-min load average at the start of every mesh, and at the end
    skipped = {t: {} for t in TASKS}
    spent = {t: defaultdict(float) for t in TASKS}
    data = []
    for p in paths:
        name = p.name[:-len(".off.gz")]
        loads.append(os.getloadavg()[0])
        V, F = read_off_gz(p)
        before = surface_report(F)
        if not before["closed"]:
            raise SystemExit(f"{name}: input is not a closed 2-manifold")
        chis = defaultdict(int)
        for c, _ in before["components"]:
            chis[c] += 1
        chi = ", ".join(f"{c}" + (f" ×{k}" if k > 1 else "") for c, k in sorted(chis.items()))
        eps = 0.01 * float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))
        log(f"{name}: {len(F)} triangles, χ {chi}")
        d = {"name": name, "triangles": int(len(F)), "vertices": int(len(V)), "chi": chi,
             "eps": eps, "tasks": {}}
        for task in tasks:
            log(f"  {task}")
            d["tasks"][task] = bench_task(task, V, F, eps, before, args, skipped, spent, log)
        if "simplify" in tasks:
            s = contractible.simplify(V, F, eps_rel=0.01).stats
            d["contractible_eps"] = s.get("eps")
            if s.get("eps") is not None and not np.isclose(s["eps"], eps, rtol=1e-9):
                log(f"  WARNING: contractible's eps {s['eps']} != script's {eps}")
        data.append(d)
    elapsed = time.perf_counter() - t_start
    loads.append(os.getloadavg()[0])

    cmd = shlex.join(["python", "bench/peers/run.py"] + sys.argv[1:])
    meta = {"command": cmd, "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
            "elapsed_s": elapsed, "machine": machine(), "versions": versions(),
            "load": loads, "note": args.note,
            "args": {k: (str(v) if isinstance(v, Path) else v) for k, v in vars(args).items()}}
    for task in tasks:
        plot(task, data, plot_dir / f"{task}.png")
    (plot_dir / "results.json").write_text(json.dumps({"meta": meta, "meshes": data}, indent=1))
    write_report(meta, data, args.out)
    log(f"wrote {args.out} and {plot_dir}/ in {elapsed / 60:.1f} min")


if __name__ == "__main__":
    main()
