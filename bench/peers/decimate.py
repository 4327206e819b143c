#!/usr/bin/env python3
"""Decimation to a face budget: `contractible.decimate` beside the decimators people use.

For every mesh and every target (10 % and 1 % of the input faces, rounded up), each
decimator runs in its own worker process (one process per decimator, fed the meshes one
after the other; a crash or a time-out costs that decimator that case only) three times;
the median wall time of the whole call, NumPy in → NumPy out, is reported, with
faces/s = input faces / that median. The output of the first run is then judged here, by
code written from the definitions and used for every library:

- topology kept: a closed 2-manifold (no degenerate or duplicate face, every edge in
  exactly two faces, the faces around every vertex a single cycle) whose components have
  the input's Euler characteristic and orientability (`surface_report` of run.py: the
  component count is the length of that list);
- faces reached: output faces / target;
- two-sided Hausdorff distance relative to the input's bounding-box diagonal, by one
  sampler: N points uniformly by area on each surface (fixed seed) plus its vertices, and
  for each point the exact distance to the other surface's triangles (point–triangle
  distance, candidates from a k-d tree of triangle pieces with a proven lower bound for
  the ones not examined). Sampling can only miss the maximum, never overstate it.

The decimators (all from PyPI, bench/peers/requirements-decimate.txt):

    contractible           contractible.decimate(V, F, faces=t)       (defaults: optimal placement, guard)
    contractible.passes    contractible.decimate(V, F, faces=t, schedule="passes")   (the fast option)
    fast_simplification    fast_simplification.simplify(V, F, target_count=t)   (trimesh.simplify_quadric_decimation)
    pyfqmr                 Simplify().setMesh(V, F); simplify_mesh(target_count=t)
    open3d                 TriangleMesh.simplify_quadric_decimation(t)
    pyvista.decimate       PolyData.decimate(1 - t/F)                  (vtkQuadricDecimation)
    pyvista.decimate_pro   PolyData.decimate_pro(1 - t/F, preserve_topology=True)
    pymeshlab.quadric      meshing_decimation_quadric_edge_collapse(targetfacenum=t)
    pymeshlab.quadric_pt   the same with preservetopology=True
    igl.decimate           igl.decimate(V, F, t)                       (shortest edge, midpoint)
    igl.qslim              igl.qslim(V, F, t)
    meshoptimizer          meshoptimizer.simplify(..., target_index_count=3t, target_error=1)

    python bench/peers/decimate.py                  # the repository's meshes (tests/data/meshes/closed)
    python bench/peers/decimate.py --corpus         # and the shared corpus ($CONTRACTIBLE_CORPUS or ../shared/meshes)
    python bench/peers/decimate.py --quick          # smoke test: 2 small meshes, 1 run, temp dir
    python bench/peers/decimate.py --picture        # docs/images/decimate.png from the last raw results

Writes docs/raw/decimate_peers_<date>.{json,csv} and the section between the decimation
markers of docs/peers.md (--no-doc: print it only).
"""

import argparse
import csv
import json
import os
import select
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from importlib import metadata
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
REPO_MESHES = REPO / "tests" / "data" / "meshes" / "closed"
RAW = REPO / "docs" / "raw"
DOC = REPO / "docs" / "peers.md"
BEGIN = "<!-- decimation: begin (written by bench/peers/decimate.py) -->"
END = "<!-- decimation: end -->"

TARGETS = (0.10, 0.01)
OURS = "contractible"
# Every configuration of this library in the comparison (none is anyone's "best peer").
OURS_ALL = ("contractible", "contractible.passes")
DECIMATORS = ["contractible", "contractible.passes", "fast_simplification", "pyfqmr", "open3d", "pyvista.decimate",
              "pyvista.decimate_pro", "pymeshlab.quadric", "pymeshlab.quadric_pt",
              "igl.decimate", "igl.qslim", "meshoptimizer"]
PACKAGES = {"contractible": "contractible", "contractible.passes": "contractible", "fast_simplification": "fast_simplification",
            "pyfqmr": "pyfqmr", "open3d": "open3d", "pyvista.decimate": "pyvista",
            "pyvista.decimate_pro": "pyvista", "pymeshlab.quadric": "pymeshlab",
            "pymeshlab.quadric_pt": "pymeshlab", "igl.decimate": "libigl",
            "igl.qslim": "libigl", "meshoptimizer": "meshoptimizer"}
QUICK = ["bunny_npm", "high_genus_3"]
SEED = 20261206
# Face counts within this fraction of contractible's output count are "the same face count".
SAME_FACES = 0.05


# --------------------------------------------------------------------------------------
# The decimators (run in the worker processes). Each takes float64 (n, 3) and int64 (m, 3)
# C arrays and the target face count, and returns (vertices, faces) as NumPy arrays: the
# conversions a user needs on either side are part of the timed call.


def make_decimator(name):
    if name in OURS_ALL:
        import contractible
        schedule = "passes" if name == "contractible.passes" else "exact"

        def run(V, F, t):
            d = contractible.decimate(V, F, faces=t, schedule=schedule)
            return d.vertices, d.faces, d.stats
        return run
    if name == "fast_simplification":
        import fast_simplification

        def run(V, F, t):
            return fast_simplification.simplify(V, F, target_count=t)
        return run
    if name == "pyfqmr":
        import pyfqmr

        def run(V, F, t):
            s = pyfqmr.Simplify()
            s.setMesh(V, F)
            s.simplify_mesh(target_count=t, verbose=False)
            U, G, _ = s.getMesh()
            return U, G
        return run
    if name == "open3d":
        import open3d as o3d

        def run(V, F, t):
            m = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V),
                                          o3d.utility.Vector3iVector(F.astype(np.int32)))
            r = m.simplify_quadric_decimation(target_number_of_triangles=t)
            return np.asarray(r.vertices), np.asarray(r.triangles)
        return run
    if name.startswith("pyvista."):
        import pyvista as pv

        def run(V, F, t):
            p = pv.PolyData.from_regular_faces(V, F)
            red = 1.0 - t / len(F)
            r = (p.decimate(red) if name == "pyvista.decimate"
                 else p.decimate_pro(red, preserve_topology=True))
            return np.asarray(r.points, dtype=np.float64), r.regular_faces
        return run
    if name.startswith("pymeshlab."):
        import pymeshlab

        def run(V, F, t):
            ms = pymeshlab.MeshSet()
            ms.add_mesh(pymeshlab.Mesh(V, F))
            ms.meshing_decimation_quadric_edge_collapse(
                targetfacenum=t, preservetopology=(name == "pymeshlab.quadric_pt"))
            mm = ms.current_mesh()
            if not mm.is_compact():
                mm.compact()
            return mm.vertex_matrix(), mm.face_matrix()
        return run
    if name.startswith("igl."):
        import igl
        fn = igl.decimate if name == "igl.decimate" else igl.qslim

        def run(V, F, t):
            U, G, _, _ = fn(np.asfortranarray(V), np.asfortranarray(F.astype(np.int32)), t)
            return U, G
        return run
    if name == "meshoptimizer":
        import meshoptimizer

        def run(V, F, t):
            idx = np.ascontiguousarray(F.astype(np.uint32).ravel())
            pos = np.ascontiguousarray(V.astype(np.float32))
            dst = np.zeros_like(idx)
            k = meshoptimizer.simplify(dst, idx, pos, target_index_count=3 * t,
                                       target_error=1.0)
            G = dst[:k].reshape(-1, 3).astype(np.int64)
            return V, G  # the kept vertices stay at their input positions
        return run
    raise ValueError(name)


def worker(name, cases_path, out_dir):
    """Runs one decimator on the cases of cases_path (from --start on), prints one JSON
    line per case when it is done; outputs of the first run go to out_dir."""
    # A decimator that loops allocating (igl.decimate and igl.qslim do on some inputs)
    # fails on this limit instead of taking the machine's memory.
    gib = float(os.environ.get("DECIMATE_MEMORY_GIB", "0"))
    if gib > 0:
        import resource
        lim = int(gib * 2**30)
        resource.setrlimit(resource.RLIMIT_AS, (lim, lim))
    # Results go to the original stdout; whatever the libraries print goes to stderr.
    res = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)
    cases = json.loads(Path(cases_path).read_text())
    start = int(os.environ.get("DECIMATE_START", "0"))
    reps, budget = int(os.environ["DECIMATE_REPS"]), float(os.environ["DECIMATE_BUDGET"])
    t0 = time.perf_counter()
    run = make_decimator(name)
    import_s = time.perf_counter() - t0
    meshes = {}
    for i, c in enumerate(cases[start:], start):
        if c["mesh_file"] not in meshes:
            meshes.clear()
            z = np.load(c["mesh_file"])
            meshes[c["mesh_file"]] = (np.ascontiguousarray(z["V"]), np.ascontiguousarray(z["F"]))
        V, F = meshes[c["mesh_file"]]
        times, stats, first = [], None, None
        for r in range(reps):
            t1 = time.perf_counter()
            out = run(V, F, c["target"])
            times.append(time.perf_counter() - t1)
            if first is None:
                first = out
            del out
            if sum(times) > budget:
                break
        U, G = np.asarray(first[0], dtype=np.float64), np.asarray(first[1], dtype=np.int64)
        if len(first) > 2:
            stats = first[2]
        path = Path(out_dir) / f"{name}-{i}.npz"
        np.savez(path, U=U, G=G)
        print(json.dumps({"case": i, "times_s": times, "out": str(path), "stats": stats,
                          "import_s": import_s, "load": os.getloadavg()[0]}), file=res, flush=True)


# --------------------------------------------------------------------------------------
# The measurement (main process)


def run_decimator(name, cases, tmp, reps, budget, timeout, memory, log):
    """{case index: result} for one decimator, restarting its worker after a crash or a
    time-out."""
    results = {}
    cases_path = tmp / "cases.json"
    start = 0
    while start < len(cases):
        env = dict(os.environ, DECIMATE_START=str(start), DECIMATE_REPS=str(reps),
                   DECIMATE_BUDGET=str(budget), DECIMATE_MEMORY_GIB=str(memory))
        errf = open(tmp / f"{name}.stderr", "w+")
        p = subprocess.Popen([sys.executable, str(tmp / "decimate_worker.py"), "--worker", name,
                              str(cases_path), str(tmp)], stdout=subprocess.PIPE,
                             stderr=errf, text=True, env=env)
        buf = ""
        deadline = time.monotonic() + timeout + 60  # the first case pays the imports
        failed = None
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                p.kill()
                failed = f"timed out (over {timeout:g} s)"
                break
            ready, _, _ = select.select([p.stdout], [], [], min(left, 1.0))
            if not ready:
                if p.poll() is not None:
                    rest = p.stdout.read()
                    buf += rest or ""
                    if not rest:
                        break
                continue
            line = p.stdout.readline()
            if not line:
                p.wait()
                break
            r = json.loads(line)
            results[r["case"]] = r
            c = cases[r["case"]]
            log(f"  {name:22s} {c['mesh']:16s} {c['target_pct']:>4} %: "
                f"{statistics.median(r['times_s']) * 1e3:9.2f} ms (n={len(r['times_s'])})")
            start = r["case"] + 1
            deadline = time.monotonic() + timeout
        p.wait()
        errf.seek(0)
        err = errf.read()
        errf.close()
        if start >= len(cases):
            break
        if failed is None:
            failed = f"crashed (exit code {p.returncode})"
            tail = [l for l in err.strip().splitlines() if l.strip()][-1:]
            if tail:
                failed += f": {tail[0][:200]}"
        c = cases[start]
        log(f"  {name:22s} {c['mesh']:16s} {c['target_pct']:>4} %: {failed}")
        results[start] = {"case": start, "failed": failed}
        start += 1
    return results


# --------------------------------------------------------------------------------------
# Distances: exact point-triangle distance, one sampler for every library


def point_triangle_distance(P, A, B, C):
    """Distance from each point P[i] to the triangle (A[i], B[i], C[i]), all (n, 3).

    The nearest point of a triangle is either inside it, where it is the orthogonal
    projection of P onto the plane, or on one of its three sides: the distance is the
    smallest of the distance to the plane (when the projection falls inside) and the
    three point-segment distances. Degenerate triangles have only their sides.
    """
    def seg(P, X, Y):
        d = Y - X
        dd = np.einsum("ij,ij->i", d, d)
        t = np.einsum("ij,ij->i", P - X, d) / np.where(dd > 0, dd, 1.0)
        t = np.clip(np.where(dd > 0, t, 0.0), 0.0, 1.0)
        q = X + t[:, None] * d
        return np.sqrt(np.einsum("ij,ij->i", P - q, P - q))

    best = np.minimum(np.minimum(seg(P, A, B), seg(P, B, C)), seg(P, C, A))
    n = np.cross(B - A, C - A)
    nn = np.einsum("ij,ij->i", n, n)
    ok = nn > 0
    h = np.einsum("ij,ij->i", P - A, n) / np.where(ok, nn, 1.0)
    Q = P - h[:, None] * n  # projection onto the plane
    inside = ok.copy()
    for X, Y in ((A, B), (B, C), (C, A)):
        inside &= np.einsum("ij,ij->i", np.cross(Y - X, Q - X), n) >= 0
    plane = np.abs(h) * np.sqrt(nn)
    return np.where(inside, np.minimum(plane, best), best)


class Surface:
    """The triangles of a mesh (referenced faces only), with a k-d tree over the centres
    of triangle pieces (each triangle bisected at its longest side until every piece fits
    in a ball of radius r around its centre), for exact nearest-distance queries."""

    def __init__(self, V, F):
        V = np.asarray(V, dtype=np.float64)
        F = np.asarray(F, dtype=np.int64).reshape(-1, 3)
        self.T = V[F]  # (m, 3, 3)
        self.vertices = V[np.unique(F)]
        T = self.T
        cen = T.mean(axis=1)
        rad = np.linalg.norm(T - cen[:, None, :], axis=2).max(axis=1)
        self.r = max(2.0 * float(np.median(rad)), 1e-12 * float(np.ptp(V, axis=0).max() or 1))
        pieces = []
        while len(T):
            cen = T.mean(axis=1)
            rad = np.linalg.norm(T - cen[:, None, :], axis=2).max(axis=1)
            small = rad <= self.r
            pieces.append(T[small])
            T = T[~small]
            if not len(T):
                break
            # bisect the longest side: corners (a, b, c) with |bc| longest -> (a, b, m), (a, m, c)
            L = np.stack([np.linalg.norm(T[:, 1] - T[:, 2], axis=1),
                          np.linalg.norm(T[:, 2] - T[:, 0], axis=1),
                          np.linalg.norm(T[:, 0] - T[:, 1], axis=1)], axis=1)
            k = L.argmax(axis=1)
            rows = np.arange(len(T))
            a, b, c = T[rows, k], T[rows, (k + 1) % 3], T[rows, (k + 2) % 3]
            m = (b + c) / 2
            T = np.concatenate([np.stack([a, b, m], axis=1), np.stack([a, m, c], axis=1)])
        self.P = np.concatenate(pieces)
        self.tree = cKDTree(self.P.mean(axis=1))
        # Pieces by radius class: class j holds the radii in (r/2^(j+1), r/2^j] (the last
        # class everything smaller), each class with its own tree and bound r_j.
        rad = np.linalg.norm(self.P - self.P.mean(axis=1)[:, None, :], axis=2).max(axis=1)
        cls = np.minimum(np.floor(np.log2(self.r / np.maximum(rad, 1e-300))), 8).astype(int)
        self.levels = []
        for j in np.unique(cls):
            ids = np.flatnonzero(cls == j)
            self.levels.append((ids, cKDTree(self.P[ids].mean(axis=1)), float(rad[ids].max())))

    def area(self):
        T = self.T
        return 0.5 * np.linalg.norm(np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0]), axis=1)

    def sample(self, n, seed=SEED):
        """n points uniformly by area (fixed seed), then every vertex of the surface."""
        rng = np.random.default_rng(seed)
        a = self.area()
        if a.sum() <= 0:
            return self.vertices
        t = rng.choice(len(a), size=n, p=a / a.sum())
        u, v = rng.random(n), rng.random(n)
        su = np.sqrt(u)
        w0, w1, w2 = 1 - su, su * (1 - v), su * v
        T = self.T[t]
        pts = w0[:, None] * T[:, 0] + w1[:, None] * T[:, 1] + w2[:, None] * T[:, 2]
        return np.concatenate([pts, self.vertices])

    def distance(self, Q, chunk=20000):
        """Exact distance from each point of Q to this surface. A first guess d from the
        16 nearest piece centres; every piece of distance below d has its centre within
        d + r_j of the point in its radius class j, so those pieces (a ball query per
        class) are examined exactly."""
        out = np.empty(len(Q))
        k = min(16, len(self.P))
        for s in range(0, len(Q), chunk):
            q = Q[s:s + chunk]
            _, idx = self.tree.query(q, k=k)
            idx = idx.reshape(len(q), -1)
            T = self.P[idx.ravel()]
            d = point_triangle_distance(np.repeat(q, k, axis=0), T[:, 0], T[:, 1], T[:, 2])
            best = d.reshape(len(q), -1).min(axis=1)
            guess = best.copy()
            for ids, tree, rj in self.levels:
                balls = tree.query_ball_point(q, guess + rj)
                lens = np.fromiter((len(x) for x in balls), dtype=np.int64, count=len(q))
                cand = np.fromiter((i for x in balls for i in x), dtype=np.int64,
                                   count=lens.sum())
                owner = np.repeat(np.arange(len(q)), lens)
                T = self.P[ids[cand]]
                d = point_triangle_distance(q[owner], T[:, 0], T[:, 1], T[:, 2])
                np.minimum.at(best, owner, d)
            out[s:s + chunk] = best
        return out


def hausdorff(a_surf, a_pts, b_surf, b_pts):
    """(max, mean) of the two one-sided distances: samples of a to b and of b to a."""
    ab = b_surf.distance(a_pts)
    ba = a_surf.distance(b_pts)
    return float(max(ab.max(), ba.max())), float((ab.mean() + ba.mean()) / 2)


def distance_self_test():
    """The exact distance against brute force over dense barycentric grids."""
    rng = np.random.default_rng(1)
    n = 400
    A, B, C = rng.normal(size=(3, n, 3))
    C[:20] = A[:20] + 0.5 * (B[:20] - A[:20])  # degenerate: collinear
    P = 2 * rng.normal(size=(n, 3))
    d = point_triangle_distance(P, A, B, C)
    g = np.linspace(0, 1, 81)
    u, v = np.meshgrid(g, g)
    keep = (u + v) <= 1
    u, v = u[keep], v[keep]
    for i in range(n):
        pts = A[i] + u[:, None] * (B[i] - A[i]) + v[:, None] * (C[i] - A[i])
        brute = np.linalg.norm(pts - P[i], axis=1).min()
        h = np.linalg.norm(np.stack([B[i] - A[i], C[i] - A[i], C[i] - B[i]]), axis=1).max() / 80
        assert d[i] <= brute + 1e-12 and d[i] >= brute - h, (i, d[i], brute, h)
    # Surface.distance against all pieces, on a coarse and a fine sphere-like mesh.
    from run import read_off_gz
    V, F = read_off_gz(REPO_MESHES / "bunny_npm.off.gz")
    s = Surface(V, F[::7])
    Q = V[::5] + 0.3 * rng.normal(size=(len(V[::5]), 3))
    fast = s.distance(Q)
    T = s.T
    slow = np.array([point_triangle_distance(np.repeat(q[None], len(T), 0), T[:, 0], T[:, 1],
                                             T[:, 2]).min() for q in Q])
    assert np.allclose(fast, slow, rtol=0, atol=1e-12), np.abs(fast - slow).max()


# --------------------------------------------------------------------------------------


def bbox_diagonal(V):
    return float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))


def pick_meshes(args):
    """[(name, source, path)]: the repository's closed meshes, plus the corpus if asked."""
    out = []
    names = set(args.meshes.split(",")) if args.meshes else None
    for p in sorted(REPO_MESHES.glob("*.off.gz")):
        n = p.name[:-len(".off.gz")]
        if names is None or n in names:
            out.append((n, "repository", p))
    if args.corpus:
        root = Path(os.environ.get("CONTRACTIBLE_CORPUS") or REPO.parent / "shared" / "meshes")
        man = root / "manifest.csv"
        if not man.exists():
            raise SystemExit(f"--corpus: no {man} (set CONTRACTIBLE_CORPUS)")
        with open(man, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["set"] == "closed"]
        if args.corpus_meshes == "all":
            picked = None
        elif args.corpus_meshes:
            picked = set(args.corpus_meshes.split(","))
        else:  # the selection of run.py: small and medium meshes of every kind
            from run import SMALL_MEDIUM
            picked = set(SMALL_MEDIUM)
        for r in sorted(rows, key=lambda r: int(r["F"])):
            if picked is not None and r["name"] not in picked:
                continue
            if picked is None and not (args.corpus_min_faces <= int(r["F"]) <= args.corpus_max_faces):
                continue
            if r["name"] in {m[0] for m in out}:
                continue  # the repository carries it (adis16480_stl): measured once
            out.append((r["name"], "corpus", root / r["file"]))
    return out


def versions():
    v = {}
    for pkg in ["contractible", "fast_simplification", "pyfqmr", "open3d", "pyvista", "vtk",
                "pymeshlab", "libigl", "meshoptimizer", "numpy", "scipy"]:
        try:
            v[pkg] = metadata.version(pkg)
        except metadata.PackageNotFoundError:
            v[pkg] = None
    v["contractible commit"] = subprocess.run(
        ["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"], capture_output=True,
        text=True).stdout.strip() or "?"
    return v


def measure(args, log):
    from run import read_off_gz, surface_report, topology_kept, machine, self_test
    self_test()
    distance_self_test()
    vers = versions()
    decimators = [d for d in (args.decimators.split(",") if args.decimators else DECIMATORS)]
    missing = [d for d in decimators if vers.get(PACKAGES[d]) is None]
    for d in missing:
        log(f"{d}: package {PACKAGES[d]} not installed, not run")
    decimators = [d for d in decimators if d not in missing]
    meshes = pick_meshes(args)
    tmp = Path(tempfile.mkdtemp(prefix="decimate-peers-"))
    cases, info = [], {}
    for name, source, path in meshes:
        V, F = read_off_gz(path)
        before = surface_report(F)
        if not before["closed"]:
            log(f"{name}: not a closed 2-manifold, skipped")
            continue
        mf = tmp / f"mesh-{name}.npz"
        np.savez(mf, V=V, F=F)
        info[name] = {"source": source, "path": str(path.relative_to(REPO) if source ==
                      "repository" else path.name), "faces": int(len(F)),
                      "vertices": int(len(V)), "components": before["components"],
                      "diagonal": bbox_diagonal(V)}
        for frac in TARGETS:
            t = int(np.ceil(frac * len(F)))
            cases.append({"mesh": name, "mesh_file": str(mf), "target": t,
                          "target_pct": f"{100 * frac:g}", "faces_in": int(len(F))})
    (tmp / "cases.json").write_text(json.dumps(cases))
    # The workers run a copy of this script, so that editing it during a run changes nothing.
    shutil.copy(Path(__file__).resolve(), tmp / "decimate_worker.py")
    log(f"{len(info)} meshes, {len(cases)} cases, {len(decimators)} decimators; "
        f"load {os.getloadavg()[0]:.1f}")

    t_start = time.perf_counter()
    loads = [os.getloadavg()[0]]
    raw = {}
    for d in decimators:
        raw[d] = run_decimator(d, cases, tmp, args.reps, args.case_budget, args.timeout,
                               args.memory, log)
        loads.append(os.getloadavg()[0])
    bench_s = time.perf_counter() - t_start

    log("checking outputs and measuring distances")
    rows = []
    cur = None
    for i, c in enumerate(cases):
        if cur != c["mesh"]:
            cur = c["mesh"]
            V, F = read_off_gz(meshes[[m[0] for m in meshes].index(cur)][2])
            before = surface_report(F)
            src = Surface(V, F)
            src_pts = src.sample(args.samples)
            diag = info[cur]["diagonal"]
        for d in decimators:
            r = raw[d].get(i, {"failed": "not run"})
            row = {"mesh": c["mesh"], "source": info[c["mesh"]]["source"],
                   "faces_in": c["faces_in"], "target_pct": c["target_pct"],
                   "target": c["target"], "decimator": d}
            if "failed" in r:
                row["failed"] = r["failed"]
                rows.append(row)
                continue
            z = np.load(r["out"])
            U, G = z["U"], z["G"]
            rep = surface_report(G)
            med = statistics.median(r["times_s"])
            row.update({
                "faces_out": rep["faces"], "faces_ratio": rep["faces"] / c["target"],
                "topology_kept": topology_kept(before, rep), "closed_manifold": rep["closed"],
                "components_out": rep["components"],
                "defects": {k: rep[k] for k in ("degenerate", "duplicate", "nonmanifold_edges",
                                                "nonmanifold_vertices", "boundary_edges")
                            if rep[k]},
                "median_s": med, "runs": len(r["times_s"]), "times_s": r["times_s"],
                "faces_per_s": c["faces_in"] / med if med > 0 else None,
                "load": r["load"]})
            if rep["faces"]:
                out = Surface(U, G)
                h, mean = hausdorff(src, src_pts, out, out.sample(args.samples))
                row["hausdorff_rel"] = h / diag
                row["mean_dist_rel"] = mean / diag
            if r.get("stats") is not None:
                st = r["stats"]
                row["stats"] = {k: st.get(k) for k in ("faces_in", "faces_out", "stopped",
                                                       "refused", "remaining", "collapses",
                                                       "max_error", "seconds", "verified")}
                issues = []
                if st.get("faces_in") != c["faces_in"]:
                    issues.append(f"stats faces_in {st.get('faces_in')} != {c['faces_in']}")
                if st.get("faces_out") != len(G):
                    issues.append(f"stats faces_out {st.get('faces_out')} != {len(G)}")
                if st.get("stopped") == "target" and len(G) > c["target"]:
                    issues.append(f"stopped 'target' with {len(G)} > {c['target']} faces")
                if st.get("stopped") != "target" and len(G) <= c["target"]:
                    issues.append(f"stopped {st.get('stopped')!r} but the target was reached")
                if not row["topology_kept"]:
                    issues.append("topology not kept")
                if issues:
                    row["contractible_issues"] = issues
                    log(f"  CONTRACTIBLE ISSUE {c['mesh']} {c['target_pct']} %: {issues}")
            rows.append(row)
        log(f"  {c['mesh']} {c['target_pct']} %: done")
    best_of(rows)
    meta = {"command": shlex.join(["python", "bench/peers/decimate.py"] + sys.argv[1:]),
            "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
            "machine": machine(), "versions": vers, "load": loads,
            "load_at_start": loads[0], "bench_seconds": bench_s,
            "samples": args.samples, "reps": args.reps, "case_budget_s": args.case_budget,
            "timeout_s": args.timeout, "memory_gib": args.memory, "seed": SEED, "decimators": decimators,
            "not_installed": missing, "note": args.note}
    return {"meta": meta, "meshes": info, "results": rows}


def best_of(rows):
    """For each (mesh, target): the topology-keeping peer of least Hausdorff distance among
    those within SAME_FACES of contractible's output face count; contractible's ratio."""
    groups = {}
    for r in rows:
        groups.setdefault((r["mesh"], r["target_pct"]), []).append(r)
    for g, name in [(g, n) for g in groups.values() for n in OURS_ALL]:
        ours = next((r for r in g if r["decimator"] == name and "hausdorff_rel" in r), None)
        if ours is None:
            continue
        f0 = ours["faces_out"]
        peers = [r for r in g if r["decimator"] not in OURS_ALL and r.get("topology_kept")
                 and "hausdorff_rel" in r and abs(r["faces_out"] - f0) <= SAME_FACES * f0]
        if peers:
            b = min(peers, key=lambda r: r["hausdorff_rel"])
            ours["best_peer"] = b["decimator"]
            ours["best_peer_hausdorff_rel"] = b["hausdorff_rel"]
            ours["best_peer_faces_out"] = b["faces_out"]
            ours["error_ratio"] = (ours["hausdorff_rel"] / b["hausdorff_rel"]
                                   if b["hausdorff_rel"] > 0 else None)


# --------------------------------------------------------------------------------------
# Report


def pct(x):
    if x is None:
        return "–"
    x *= 100
    return f"{x:.3g} %" if x < 10 else f"{x:.0f} %"


def ms(s):
    v = 1000 * s
    return f"{v:.3g}" if v < 100 else f"{v:.0f}"


def rate(x):
    if x is None:
        return "–"
    return f"{x / 1e6:.2f} M" if x >= 1e6 else f"{x / 1e3:.0f} k"


def report(data):
    meta, rows = data["meta"], data["results"]
    decs = meta["decimators"]
    L = []
    w = L.append
    load = meta["load"]
    nproc = int(meta["machine"]["nproc"] or 1)
    w("## Decimation to a face budget")
    w("")
    w("`contractible.decimate(V, F, faces=t)` in its default configuration (optimal "
      "placement, fold-over guard, the exact schedule; every collapse passes the link "
      "condition), and with `schedule=\"passes\"`, the fast option (`contractible.passes`), "
      "beside the "
      "decimators people use, all from PyPI (`bench/peers/requirements-decimate.txt`): "
      "fast-simplification (what `trimesh.simplify_quadric_decimation` calls), pyfqmr, "
      "open3d `simplify_quadric_decimation`, pyvista `decimate` (vtkQuadricDecimation) and "
      "`decimate_pro(preserve_topology=True)`, pymeshlab "
      "`meshing_decimation_quadric_edge_collapse` without and with `preservetopology=True` "
      "(`quadric_pt`), `igl.decimate` (shortest edge, midpoint) and `igl.qslim`, and "
      "meshoptimizer `simplify` (`target_error=1`, so that only the count stops it). "
      "Targets t = ⌈10 %⌉ and ⌈1 %⌉ of the input faces.")
    w("")
    w("Command (one worker process per decimator; one entry point, "
      "[bench/peers/README.md](../bench/peers/README.md)):")
    w("")
    w(f"    {meta['command']}")
    w("")
    hi = max(load)
    w(f"Run on {meta['date']}: {meta['machine']['cpu']}, `nproc` = {meta['machine']['nproc']}, "
      f"{meta['machine']['memory']}, Python {meta['machine']['python']}; contractible "
      f"{meta['versions']['contractible']} at commit {meta['versions']['contractible commit']}. "
      f"1-min load average at the start and after each decimator: {min(load):.1f} to {hi:.1f}.")
    if hi > nproc + 0.5:
        w("")
        w(f"**Provisional figures: the machine was shared with other builds during the run "
          f"(load up to {hi:.1f} on {nproc} cores), so the times are slower and noisier than "
          f"on an idle machine; the outputs, checks and distances do not depend on it.**")
    if meta.get("note"):
        w("")
        w(f"**Note:** {meta['note']}")
    w("")
    w("Versions: " + ", ".join(f"{k} {v}" for k, v in meta["versions"].items() if v) + ".")
    if meta["not_installed"]:
        w(f" Not installed, not run: {', '.join(meta['not_installed'])}.")
    w("")
    w("How it is measured:")
    w("")
    w(f"- Time: the whole call, NumPy arrays in → NumPy arrays out (building the library's "
      f"mesh object and reading its arrays back included), median of {meta['reps']} runs "
      f"(fewer, `n=` in the raw data, once a case's runs took {meta['case_budget_s']:g} s); "
      f"faces/s = input faces / median.")
    w("- Topology kept (✓): the output is a closed 2-manifold (no degenerate or duplicate "
      "face, every edge in exactly two faces, one cycle of faces around each vertex) and its "
      "components have the input's Euler characteristic and orientability, in number too, "
      "checked by the script's own `surface_report` (run.py) for every library; "
      "unreferenced vertices are ignored.")
    w(f"- Error: the two-sided Hausdorff distance, in % of the input's bounding-box diagonal. "
      f"Each surface gets {meta['samples']:,} points uniformly by area (seed {meta['seed']}) "
      f"plus its vertices; each point's distance to the other surface is exact "
      f"(point–triangle, over every triangle piece whose bounding ball can hold a nearer "
      f"point, found by k-d tree ball queries), so the figure can miss the true maximum "
      f"between samples but never exceeds it. \"0 faces\": the decimator returned an "
      f"empty mesh.")
    w(f"- faces ÷ t: output faces over the target (1.00 = reached; above: the decimator "
      f"stopped early). \"Best peer\": the topology-keeping peer of least error among those "
      f"within ±{SAME_FACES:.0%} of contractible's output face count; ratio = contractible's "
      f"error / that peer's (below 1: contractible is closer to the input).")
    w("")

    sources = list(dict.fromkeys(r["source"] for r in rows))
    for src, tp in [(s, t) for s in sources for t in ("10", "1")]:
        sel = [r for r in rows if r["target_pct"] == tp and r["source"] == src]
        if not sel:
            continue
        where = ("the repository's meshes (tests/data/meshes/closed)" if src == "repository"
                 else "the shared corpus")
        w(f"### Target {tp} % of the faces: summary over {len({r['mesh'] for r in sel})} "
          f"meshes of {where}")
        w("")
        w("| decimator | topology kept | target reached (faces ≤ 1.05 t) | median faces ÷ t | "
          "median error | max error | median faces/s |")
        w("|---|---:|---:|---:|---:|---:|---:|")
        for d in decs:
            rs = [r for r in sel if r["decimator"] == d]
            ok = [r for r in rs if "faces_out" in r]
            fail = len(rs) - len(ok)
            if not ok:
                w(f"| {d} | – | – | – | – | – | – |")
                continue
            kept = sum(r["topology_kept"] for r in ok)
            reached = sum(r["faces_ratio"] <= 1.05 for r in ok)
            errs = [r["hausdorff_rel"] for r in ok if "hausdorff_rel" in r]
            fps = [r["faces_per_s"] for r in ok if r.get("faces_per_s")]
            extra = f" ({fail} failed)" if fail else ""
            w(f"| {d} | {kept}/{len(rs)}{extra} | {reached}/{len(rs)} | "
              f"{statistics.median(r['faces_ratio'] for r in ok):.2f} | "
              f"{pct(statistics.median(errs)) if errs else '–'} | "
              f"{pct(max(errs)) if errs else '–'} | "
              f"{rate(statistics.median(fps)) if fps else '–'} |")
        w("")

    speed_lines(rows, w)
    for name in [d for d in OURS_ALL if d in decs]:
        ours_table(rows, name, w)
    w("### Every case: error (% of the diagonal), ✓ topology kept, faces ÷ t when above 1.05")
    w("")
    w("| mesh | target | " + " | ".join(decs) + " |")
    w("|---|---:|" + "---|" * len(decs))
    for key in dict.fromkeys((r["mesh"], r["target_pct"]) for r in rows):
        g = {r["decimator"]: r for r in rows if (r["mesh"], r["target_pct"]) == key}
        cells = []
        for d in decs:
            r = g.get(d)
            if r is None or "faces_out" not in r:
                cells.append(r.get("failed", "–") if r else "–")
                continue
            s = (pct(r.get("hausdorff_rel")) if r["faces_out"] else "0 faces") + (
                " ✓" if r["topology_kept"] else " ✗")
            if r["faces_ratio"] > 1.05:
                s += f" ({r['faces_ratio']:.2f}×t)"
            cells.append(s)
        w(f"| {key[0]} | {key[1]} % | " + " | ".join(cells) + " |")
    w("")
    w("Times of the whole call (ms, median):")
    w("")
    w("| mesh | target | " + " | ".join(decs) + " |")
    w("|---|---:|" + "---:|" * len(decs))
    for key in dict.fromkeys((r["mesh"], r["target_pct"]) for r in rows):
        g = {r["decimator"]: r for r in rows if (r["mesh"], r["target_pct"]) == key}
        cells = [ms(g[d]["median_s"]) if d in g and "median_s" in g[d] else "–" for d in decs]
        w(f"| {key[0]} | {key[1]} % | " + " | ".join(cells) + " |")
    w("")
    issues = [r for r in rows if r.get("contractible_issues")]
    if issues:
        w("**contractible misbehaved:** " + "; ".join(
            f"{r['mesh']} {r['target_pct']} %: {', '.join(r['contractible_issues'])}"
            for r in issues) + ".")
        w("")
    return "\n".join(L) + "\n"


def ours_table(rows, name, w):
    """One configuration of this library against the best topology-keeping peer per case."""
    w(f"### {name} against the best topology-keeping peer at the same face count")
    w("")
    w(f"| mesh | faces | target | {name} faces | error | best peer (faces) | its error | ratio |")
    w("|---|---:|---:|---:|---:|---|---:|---:|")
    ratios = {"10": [], "1": []}
    for r in rows:
        if r["decimator"] != name:
            continue
        if "faces_out" not in r:
            w(f"| {r['mesh']} | {r['faces_in']} | {r['target_pct']} % | {r.get('failed')} | | | | |")
            continue
        mark = "" if r["topology_kept"] else " **✗**"
        if "best_peer" in r:
            rr = r.get("error_ratio")
            if rr is not None:
                ratios[r["target_pct"]].append(rr)
            w(f"| {r['mesh']} | {r['faces_in']} | {r['target_pct']} % | {r['faces_out']}{mark} | "
              f"{pct(r.get('hausdorff_rel'))} | {r['best_peer']} ({r['best_peer_faces_out']}) | "
              f"{pct(r['best_peer_hausdorff_rel'])} | "
              f"{'–' if rr is None else f'{rr:.2f}'} |")
        else:
            w(f"| {r['mesh']} | {r['faces_in']} | {r['target_pct']} % | {r['faces_out']}{mark} | "
              f"{pct(r.get('hausdorff_rel'))} | none | | |")
    w("")
    for tp, rs in ratios.items():
        if rs:  # noqa: SIM102
            w(f"- {tp} %: {name}'s error / the best peer's, median "
              f"{statistics.median(rs):.2f} (min {min(rs):.2f}, max {max(rs):.2f}) over "
              f"{len(rs)} meshes; {name} closer on {sum(x < 1 for x in rs)}.")
    w("")


# The speed ratios the issue of record asks for: over the meshes of at least this many faces.
SPEED_MIN_FACES = 80_000


def speed_lines(rows, w):
    """Per configuration of this library: its whole-call time against igl.decimate's (the
    fastest topology-keeping peer), open3d's, igl.qslim's and meshoptimizer's, as the
    median over the cases of meshes with at least SPEED_MIN_FACES faces of the ratio of
    the two medians measured in this run (above 1: this library is faster)."""
    others = ["igl.decimate", "open3d", "igl.qslim", "meshoptimizer"]
    times = {}
    for r in rows:
        if r["faces_in"] >= SPEED_MIN_FACES and "median_s" in r:
            times.setdefault((r["mesh"], r["target_pct"]), {})[r["decimator"]] = r["median_s"]
    if not times:
        return
    w(f"### Speed ratios (meshes of at least {SPEED_MIN_FACES:,} faces)")
    w("")
    w("Each cell: the median over the cases (both targets) of the peer's time ÷ this "
      "library's, both measured in this run (above 1: this library is faster); the number "
      "of cases in brackets.")
    w("")
    w("| configuration | " + " | ".join(others) + " |")
    w("|---|" + "---:|" * len(others))
    for name in OURS_ALL:
        cells = []
        for o in others:
            rs = [t[o] / t[name] for t in times.values() if name in t and o in t and t[name] > 0]
            cells.append(f"{statistics.median(rs):.2f} ({len(rs)})" if rs else "–")
        w(f"| {name} | " + " | ".join(cells) + " |")
    w("")



def write_doc(section, raw_name, picture):
    text = DOC.read_text() if DOC.exists() else ""
    block = (BEGIN + "\n" + section + f"\nRaw results: [`raw/{raw_name}.json`](raw/{raw_name}.json), "
             f"[`raw/{raw_name}.csv`](raw/{raw_name}.csv).\n")
    if picture:
        block += ("\n![decimate: contractible beside the best topology-keeping peer]"
                  "(images/decimate.png)\n")
    block += END
    if BEGIN in text and END in text:
        a, b = text.index(BEGIN), text.index(END) + len(END)
        text = text[:a] + block + text[b:]
    else:
        text = text.rstrip("\n") + "\n\n" + block + "\n"
    DOC.write_text(text)


def write_raw(data, stem):
    RAW.mkdir(parents=True, exist_ok=True)
    (RAW / f"{stem}.json").write_text(json.dumps(data, indent=1) + "\n")
    cols = ["mesh", "source", "faces_in", "target_pct", "target", "decimator", "faces_out",
            "faces_ratio", "topology_kept", "closed_manifold", "hausdorff_rel",
            "mean_dist_rel", "median_s", "runs", "faces_per_s", "failed"]
    with open(RAW / f"{stem}.csv", "w", newline="") as f:
        wr = csv.writer(f)
        wr.writerow(cols)
        for r in data["results"]:
            wr.writerow([("" if r.get(c) is None else
                          f"{r[c]:.6g}" if isinstance(r.get(c), float) else r.get(c))
                         for c in cols])


# --------------------------------------------------------------------------------------
# Picture


def picture(raw_json, out_png, mesh="bunny_npm", target_pct="10"):
    """contractible's output beside the best topology-keeping peer's, on one mesh, drawn as
    docs/render_pictures.py draws the other pictures."""
    sys.path.insert(0, str(REPO / "docs"))
    import render_pictures as rp
    from run import read_off_gz
    data = json.loads(Path(raw_json).read_text())
    ours = next(r for r in data["results"] if r["mesh"] == mesh
                and r["target_pct"] == target_pct and r["decimator"] == OURS)
    peer = ours["best_peer"]
    V, F = read_off_gz(REPO_MESHES / f"{mesh}.off.gz")
    t = ours["target"]
    outs = {}
    for d in (OURS, peer):
        o = make_decimator(d)(V, F, t)
        outs[d] = rp.Mesh(np.asarray(o[0], dtype=np.float64),
                          [tuple(f) for f in np.asarray(o[1]).tolist()]).used()
    peer_r = next(r for r in data["results"] if r["mesh"] == mesh
                  and r["target_pct"] == target_pct and r["decimator"] == peer)
    view = rp.BUNNY_VIEW
    box = rp.bbox(rp.Mesh(V, [tuple(f) for f in F.tolist()]), view)

    def ttl(label, m, r):
        return (f"{label}\nV = {len(m.vertices):,}   F = {len(m.faces):,} triangles\n"
                f"Hausdorff {pct(r['hausdorff_rel'])} of the diagonal, "
                f"{'topology kept' if r['topology_kept'] else 'topology changed'}")
    fig, a, b = rp.figure(
        ttl(f"contractible.decimate(V, F, faces={t})", outs[OURS], ours),
        ttl(f"{peer} (best topology-keeping peer here)", outs[peer], peer_r))
    rp.draw(a, outs[OURS], view, box, lw=0.3, edge_alpha=0.8)
    rp.draw(b, outs[peer], view, box, lw=0.3, edge_alpha=0.8)
    rp.save(fig, Path(out_png),
            f"{mesh} ({len(F):,} faces) to {target_pct} %: python bench/peers/decimate.py --picture")


# --------------------------------------------------------------------------------------


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--worker":
        worker(*sys.argv[2:5])
        return
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--meshes", help="comma-separated names of the repository's meshes "
                    "(default: all of tests/data/meshes/closed)")
    ap.add_argument("--corpus", action="store_true", help="add the shared corpus: "
                    "$CONTRACTIBLE_CORPUS or ../shared/meshes, closed meshes of its manifest.csv "
                    "(read in place, never copied)")
    ap.add_argument("--corpus-meshes", help="comma-separated corpus names, or 'all' for "
                    "every closed mesh within --corpus-min-faces .. --corpus-max-faces "
                    "(default: run.py's selection of small and medium meshes)")
    ap.add_argument("--corpus-min-faces", type=int, default=0)
    ap.add_argument("--corpus-max-faces", type=int, default=200_000)
    ap.add_argument("--decimators", help="comma-separated subset of: " + ", ".join(DECIMATORS))
    ap.add_argument("--reps", type=int, default=None, help="runs per case (median; default 3, "
                    "1 with --quick)")
    ap.add_argument("--case-budget", type=float, default=30.0,
                    help="stop repeating a case once its runs took this many seconds")
    ap.add_argument("--timeout", type=float, default=60.0,
                    help="give up a case (kill its worker) after this many seconds")
    ap.add_argument("--memory", type=float, default=6.0,
                    help="address-space limit of each worker process, GiB (default 6; 0: none)")
    ap.add_argument("--samples", type=int, default=None,
                    help="points per surface for the Hausdorff distance (default 20000; "
                    "5000 with --quick)")
    ap.add_argument("--quick", action="store_true", help="smoke test: 2 small meshes, one "
                    "run, 5000 samples, nothing written to docs/")
    ap.add_argument("--no-doc", action="store_true", help="print the section, leave docs/ alone")
    ap.add_argument("--note", help="a sentence added to the report")
    ap.add_argument("--report", metavar="RAW_JSON", help="rewrite the docs/peers.md section "
                    "from raw results, without measuring")
    ap.add_argument("--picture", nargs="?", const="latest", metavar="RAW_JSON",
                    help="render docs/images/decimate.png from raw results (default: the "
                    "newest docs/raw/decimate_peers_*.json) and exit")
    args = ap.parse_args()
    sys.path.insert(0, str(HERE))
    if args.picture:
        src = (sorted(RAW.glob("decimate_peers_*.json"))[-1] if args.picture == "latest"
               else Path(args.picture))
        picture(src, REPO / "docs" / "images" / "decimate.png")
        return
    if args.report:
        data = json.loads(Path(args.report).read_text())
        section = report(data)
        write_doc(section, Path(args.report).stem,
                  (REPO / "docs" / "images" / "decimate.png").exists())
        print(section)
        return
    if args.reps is None:
        args.reps = 1 if args.quick else 3
    if args.samples is None:
        args.samples = 5000 if args.quick else 20_000
    if args.quick and not args.meshes:
        args.meshes = ",".join(QUICK)
    log = lambda s: print(s, flush=True)  # noqa: E731
    data = measure(args, log)
    section = report(data)
    stem = "decimate_peers_" + data["meta"]["date"][:10] + ("_corpus" if args.corpus else "")
    if args.quick or args.no_doc:
        out = Path(tempfile.mkdtemp(prefix="decimate-quick-"))
        (out / f"{stem}.json").write_text(json.dumps(data, indent=1))
        print(section)
        log(f"raw results in {out}/{stem}.json (docs/ untouched)")
    else:
        write_raw(data, stem)
        write_doc(section, stem, (REPO / "docs" / "images" / "decimate.png").exists())
        print(section)
        log(f"wrote docs/raw/{stem}.json, .csv and the decimation section of docs/peers.md")
    bad = [r for r in data["results"] if r.get("contractible_issues")]
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
