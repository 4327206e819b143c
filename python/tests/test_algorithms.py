"""Every function on real meshes (the repository's `tests/data/meshes`) and on meshes
generated at test time, checked by the independent checks of conftest.py and against the
command line's outputs for the same files. The sweeps over every small closed mesh also
run over the real-mesh corpus with `--corpus` (class TestCorpus, at the end)."""

import json

import numpy as np
import pytest

import contractible as c
from conftest import (CORPUS_SMALL_MIN, DATA, DATA_SMALL_MIN, contractible_edges,
                      corpus_meshes, edges_of, is_closed_manifold_faces, manifest,
                      small_closed, surface_signature)

SMALL = small_closed(manifest(DATA))
SMALL_IDS = [m["name"] for m in SMALL]
# A spread of sizes, genera and component counts for the comparisons with the CLI: the
# tetrahedron, octahedron, 7-vertex torus and Klein bottle; genus 2 (an isosurface and a
# random surface); genus 3, 5 and 24; 2, 10 and 120 components; and a mesh orientable
# but not consistently oriented (see conftest.GENERATED and tests/data/meshes).
CLI_SET = ["tetrahedron", "octahedron", "torus7", "klein", "genus2_iso", "random_g2",
           "high_genus_3", "plate_holes_stl", "adis16480_stl", "two_objects", "box_stl",
           "many_components", "multibody_stl"]


@pytest.fixture(scope="module")
def nonorientable(tmp_path_factory, cli):
    """Non-orientable closed surfaces made by the CLI's generators (the real meshes are
    all orientable): the 6-vertex RP², the 9-vertex Klein bottle, and random surfaces of
    Euler genus 1, 3 and 6."""
    d = tmp_path_factory.mktemp("nonorientable")
    out = []
    for kind in ["rp2", "klein"]:
        p = d / f"{kind}.off"
        cli("gen", kind, "-o", p, "--quiet")
        out.append(p)
    for h in [1, 3, 6]:
        p = d / f"random_h{h}.off"
        cli("gen", "random", "--crosscaps", h, "--faces", 600, "--seed", h, "-o", p, "--quiet")
        out.append(p)
    return out


# ------------------------------------------------------------------------ read / info

def test_the_sweeps_cover_the_repositorys_meshes():
    """The sweeps below run over every small closed mesh of tests/data/meshes: none of
    its files went missing."""
    assert len(SMALL) >= DATA_SMALL_MIN, SMALL_IDS
    for m in SMALL:
        assert (DATA / m["file"]).is_file(), m["file"]


def check_read_and_info(meshes, m):
    V, F = c.read(meshes / m["file"])
    assert V.dtype == np.float64 and V.shape == (int(m["V"]), 3)
    assert F.dtype == np.int64 and F.shape == (int(m["F"]), 3)
    i = c.info(V, F)
    assert (i["vertices"], i["edges"], i["faces"]) == (int(m["V"]), int(m["E"]), int(m["F"]))
    assert i["components"] == int(m["components"])
    assert i["euler_characteristic"] == int(m["euler"])
    assert i["orientable"] == (m["orientable"] == "True")
    # And against the definition: per-component χ and orientability from the faces.
    sig = surface_signature(F)
    assert sorted((d["euler_characteristic"], d["orientable"], 0)
                  for d in i["component_list"]) == sig


@pytest.mark.parametrize("m", SMALL, ids=SMALL_IDS)
def test_read_and_info_match_the_manifest(m):
    check_read_and_info(DATA, m)


@pytest.mark.parametrize("name", CLI_SET)
def test_info_equals_the_cli(name, cli, mesh_file):
    src = mesh_file(name)
    V, F = c.read(src)
    mine = c.info(V, F)
    theirs = json.loads(cli("info", src, "--json").stdout)
    for k in ["vertices", "edges", "faces", "components", "euler_characteristic",
              "orientable", "dropped_vertices"]:
        assert mine[k] == theirs[k], k
    assert len(mine["component_list"]) == len(theirs["component_list"])
    for a, b in zip(mine["component_list"], theirs["component_list"]):
        for k in a:
            assert a[k] == b[k], k


def test_info_describes_boundary(cli, tmp_path):
    p = tmp_path / "hyperboloid.off"
    cli("gen", "isosurface", "--surface", "hyperboloid", "--resolution", 12, "-o", p, "--quiet")
    V, F = c.read(p)
    i = c.info(V, F)
    assert i["boundary_loops"] == 2
    assert sorted(s[2] for s in surface_signature(F)) == sorted(
        d["boundary_loops"] for d in i["component_list"])
    assert all(len(d["boundary_loop_lengths"]) == d["boundary_loops"]
               for d in i["component_list"])


@pytest.mark.parametrize("name", ["letter", "genus2_iso"])
def test_write_round_trips(name, tmp_path, mesh_file):
    # Coordinates that float32 does not hold exactly: a real mesh and an isosurface.
    V, F = c.read(mesh_file(name))
    for ext in ["off", "obj", "ply", "stl", "off.gz"]:
        p = tmp_path / f"x.{ext}"
        c.write(p, V, F)
        V2, F2 = c.read(p)
        if ext == "stl":
            # STL stores corner coordinates (float32), renumbered on welding.
            assert np.allclose(V2[F2], V[F], rtol=1e-6, atol=1e-6)
        else:
            assert np.array_equal(F2, F), ext
            assert np.array_equal(V2, V), ext


# ----------------------------------------------------------------------------- reduce

def check_reduce(meshes, m):
    V, F = c.read(meshes / m["file"])
    r = c.reduce(V, F)
    assert contractible_edges(r.faces) == []
    assert surface_signature(r.faces) == surface_signature(F)
    assert is_closed_manifold_faces(r.faces)
    # Survivors keep their input positions, numbered in input order.
    assert np.all(np.diff(r.vertex_map) > 0)
    assert np.array_equal(r.vertices, V[r.vertex_map])
    assert r.stats["vertices_out"] == len(r.vertex_map)
    assert r.stats["faces_out"] == len(r.faces)
    assert r.stats["components"] == int(m["components"])


@pytest.mark.parametrize("m", SMALL, ids=SMALL_IDS)
def test_reduce_is_irreducible_and_keeps_the_surface(m):
    check_reduce(DATA, m)


# Genus 2; genus 5 (one component); 10 components of genus 0 to 6.
@pytest.mark.parametrize("algo", ["schipper", "brute"])
@pytest.mark.parametrize("name", ["genus2_iso", "plate_holes_stl", "box_stl"])
def test_reduce_baselines(name, algo, mesh_file):
    V, F = c.read(mesh_file(name))
    r = c.reduce(V, F, algo=algo, seed=5)
    assert contractible_edges(r.faces) == []
    assert surface_signature(r.faces) == surface_signature(F)
    assert r.stats["algo"] == algo


@pytest.mark.parametrize("name", CLI_SET)
def test_reduce_equals_the_cli(name, cli, tmp_path, mesh_file):
    src = mesh_file(name)
    out = tmp_path / "out.off"
    theirs = json.loads(cli("reduce", src, "-o", out, "--json", "--seed", 3,
                            "--algo", "brute").stdout)
    V, F = c.read(src)
    r = c.reduce(V, F, algo="brute", seed=3, count_retests=True)
    V2, F2 = c.read(out)
    assert np.array_equal(r.faces, F2)
    assert np.allclose(r.vertices, V2)
    timing = {"seconds"}
    for k, v in r.stats.items():
        if k in theirs and k not in timing and k != "component_list":
            assert v == theirs[k], k
    assert len(r.stats["component_list"]) == len(theirs["component_list"])
    for a, b in zip(r.stats["component_list"], theirs["component_list"]):
        assert {k: v for k, v in a.items() if k not in timing} == \
            {k: b[k] for k in a if k not in timing}


def test_history_replays_the_input(mesh_file):
    V, F = c.read(mesh_file("box_stl"))  # 10 components
    r = c.reduce(V, F)
    rec = r.history.records()
    assert rec.shape == (len(r.history), 5) == (r.stats["contractions"], 5)
    assert np.array_equal(r.history.expand(), F)
    # No split undone: the output's faces in input ids.
    now = r.history.expand(0)
    assert sorted(map(tuple, np.sort(now, axis=1))) == \
        sorted(map(tuple, np.sort(r.vertex_map[r.faces], axis=1)))
    # Undoing the last k contractions brings back exactly the k newest removed vertices.
    k = 50
    part = r.history.expand(k)
    back = set(np.unique(part)) - set(np.unique(now))
    assert back == set(rec[-k:, 2].tolist())
    assert surface_signature(part) == surface_signature(F)


def test_reduce_nonorientable(nonorientable):
    for p in nonorientable:
        V, F = c.read(p)
        r = c.reduce(V, F)
        assert contractible_edges(r.faces) == [], p.name
        sig = surface_signature(F)
        assert not sig[0][1]
        assert surface_signature(r.faces) == sig


def test_parallel_components_give_the_same_results(nonorientable):
    """The five non-orientable surfaces as one mesh of five components: reduced and paired
    with the components in parallel and one after another, the same outputs."""
    F, n = [], 0
    for p in nonorientable:
        _, f = c.read(p)
        F.append(f + n)
        n += int(f.max()) + 1
    F = np.concatenate(F)
    one, par = c.reduce(None, F), c.reduce(None, F, parallel=True)
    assert np.array_equal(one.faces, par.faces)
    assert np.array_equal(one.vertex_map, par.vertex_map)
    assert len(par.stats["component_list"]) == len(nonorientable)
    for algo in ("lrs", "ds"):
        one, par = c.quad(None, F, algo=algo), c.quad(None, F, algo=algo, parallel=True)
        assert np.array_equal(one.quads, par.quads)
        assert np.array_equal(one.pairs, par.pairs)


def test_parallel_simplification_gives_the_same_result(mesh_file):
    """box_stl (10 components), simplified with the components in parallel and one after
    another: the same output and statistics."""
    V, F = c.read(mesh_file("box_stl"))
    for mode in ("nested", "naive"):
        one = c.simplify(V, F, eps_rel=0.02, mode=mode)
        par = c.simplify(V, F, eps_rel=0.02, mode=mode, parallel=True)
        assert np.array_equal(one.vertices, par.vertices)
        assert np.array_equal(one.faces, par.faces)
        assert one.stats["components"] == 10 and one.stats["edges_contracted"] > 0
        untimed = {k: v for k, v in one.stats.items() if "seconds" not in k}
        assert untimed == {k: v for k, v in par.stats.items() if "seconds" not in k}


# ------------------------------------------------------------------------------- quad

def check_pairing(F, q):
    """Perfect pairing of K, K a triangulation of the same surface on the same
    vertices, quads made of the pairs."""
    K, P = q.triangles, q.pairs
    assert K.shape == F.shape
    assert np.array_equal(np.unique(K), np.unique(F))
    assert is_closed_manifold_faces(K)
    assert surface_signature(K) == surface_signature(F)
    assert np.array_equal(np.sort(P.ravel()), np.arange(len(F)))
    for (f, g), quad in zip(P.tolist(), q.quads.tolist()):
        shared = set(K[f]) & set(K[g])
        assert len(shared) == 2
        assert set(quad) == set(K[f]) | set(K[g])
        # The quad's cycle runs around both triangles: the shared edge is its diagonal.
        a, b = shared
        i, j = quad.index(a), quad.index(b)
        assert (i - j) % 4 == 2


def check_quad_lrs(meshes, m):
    V, F = c.read(meshes / m["file"])
    q = c.quad(V, F)
    check_pairing(F, q)
    # K differs from the input by the flips only: every face not in a flip is unchanged.
    assert q.stats["quads"] * 2 == len(F)
    assert q.stats["flips"] >= 0


@pytest.mark.parametrize("m", SMALL, ids=SMALL_IDS)
def test_quad_lrs_is_perfect(m):
    check_quad_lrs(DATA, m)


# Genus 2; genus 5 and genus 24 (one component each); 10 components of genus 0 to 6.
@pytest.mark.parametrize("algo", ["ps", "sg", "matching", "ds", "bbdl", "frink-lct", "ds-naive"])
@pytest.mark.parametrize("name", ["genus2_iso", "plate_holes_stl", "adis16480_stl", "box_stl"])
def test_quad_other_algorithms(name, algo, mesh_file):
    V, F = c.read(mesh_file(name))
    q = c.quad(V, F, algo=algo, seed=2)
    check_pairing(F, q)
    assert np.array_equal(q.triangles, F)  # no flips outside LRS
    assert q.stats["flips"] == 0


@pytest.mark.parametrize("name", CLI_SET)
def test_quad_equals_the_cli(name, cli, tmp_path, mesh_file):
    src = mesh_file(name)
    pairs = tmp_path / "pairs.txt"
    theirs = json.loads(cli("quad", src, "--pairs", pairs, "--json").stdout)
    V, F = c.read(src)
    q = c.quad(V, F)
    lines = np.loadtxt(pairs, dtype=np.int64, ndmin=2)
    assert np.array_equal(q.pairs, lines)
    for k in ["faces", "quads", "initial_unpaired", "flips", "augmenting_paths", "phases"]:
        assert q.stats[k] == theirs[k], k


def test_quad_nonorientable(nonorientable):
    for p in nonorientable:
        V, F = c.read(p)
        for algo in ["lrs", "ps"]:
            check_pairing(F, c.quad(V, F, algo=algo))


# --------------------------------------------------------------------------- simplify

# Genus 1, 5 and 24 (one component each) and 10 components of genus 0 to 6, with
# positions.
@pytest.mark.parametrize("name", ["letter", "plate_holes_stl", "adis16480_stl", "box_stl"])
@pytest.mark.parametrize("mode", ["nested", "naive"])
def test_simplify_keeps_the_surface(name, mode, mesh_file):
    V, F = c.read(mesh_file(name))
    s = c.simplify(V, F, eps_rel=0.02, mode=mode)
    assert surface_signature(s.faces) == surface_signature(F)
    assert is_closed_manifold_faces(s.faces)
    assert s.vertices.shape == (len(np.unique(s.faces)), 3)
    assert s.stats["faces_out"] == len(s.faces) < len(F)
    assert s.stats["eps_rel"] == 0.02


def test_simplify_open_surface(cli, tmp_path):
    p = tmp_path / "h.off"
    cli("gen", "isosurface", "--surface", "hyperboloid", "--resolution", 24, "-o", p, "--quiet")
    V, F = c.read(p)
    s = c.simplify(V, F, eps_rel=0.03)
    assert surface_signature(s.faces) == surface_signature(F)
    assert s.stats["boundary_loops"] == 2


@pytest.mark.parametrize("name", ["adis16480_stl", "plate_holes_stl", "box_stl"])
def test_simplify_equals_the_cli(name, cli, tmp_path, mesh_file):
    src = mesh_file(name)
    out = tmp_path / "out.off"
    theirs = json.loads(cli("simplify", src, "--eps-rel", 0.02, "-o", out, "--json").stdout)
    V, F = c.read(src)
    s = c.simplify(V, F, eps_rel=0.02)
    V2, F2 = c.read(out)
    assert np.array_equal(s.faces, F2)
    assert np.allclose(s.vertices, V2, rtol=0, atol=1e-9 * np.abs(V).max())
    for k in ["eps", "edges_contracted", "discs_removed", "faces_out", "vertices_out",
              "passes", "short_edges_remaining"]:
        assert s.stats[k] == pytest.approx(theirs[k]), k


def test_results_are_deterministic(mesh_file):
    V, F = c.read(mesh_file("plate_holes_stl"))
    for f in [lambda: c.reduce(V, F, algo="brute", seed=9).faces,
              lambda: c.quad(V, F, algo="sg", seed=9).pairs,
              lambda: c.simplify(V, F, eps_rel=0.02).faces]:
        assert np.array_equal(f(), f())


def test_index_and_coordinate_dtypes_give_the_same_results(mesh_file):
    """int64, int32 and uint32 faces and float64 and float32 vertices are read as they
    are (the wrapper passes the caller's C-contiguous array itself, no converted copy);
    other dtypes, byte orders and layouts are converted. Every combination gives the
    results of float64/int64 arrays holding the same values."""
    V, F = c.read(mesh_file("plate_holes_stl"))
    V32 = V.astype(np.float32)
    reference = {}
    for name, Vr in [("float64", V32.astype(np.float64)), ("float32", V32)]:
        reduced = c.reduce(Vr, F, algo="brute", seed=3)
        quad = c.quad(Vr, F, algo="ps", seed=3)
        simple = c.simplify(Vr, F, eps_rel=0.02)
        got = (reduced.faces, reduced.vertices.astype(np.float64), quad.quads, quad.pairs,
               simple.faces, simple.vertices)
        reference.setdefault("all", got)
        for a, b in zip(reference["all"], got):
            assert np.array_equal(a, b), name
    for dtype in [np.int32, np.uint32, np.int64]:
        Fd = F.astype(dtype)
        assert c._faces(Fd) is Fd
    for dtype in [np.float32, np.float64]:
        Vd = V.astype(dtype)
        assert c._vertices(Vd) is Vd
    variants = [F.astype(np.int32), F.astype(np.uint32), F.astype(np.int16),
                F.astype(">i4"), np.asfortranarray(F.astype(np.int32)), F.astype(np.uint64)]
    for Fd in variants:
        assert np.array_equal(c.reduce(V, Fd, algo="brute", seed=3).faces,
                              c.reduce(V, F, algo="brute", seed=3).faces), Fd.dtype
        assert np.array_equal(c.quad(None, Fd, algo="ps", seed=3).pairs,
                              c.quad(None, F, algo="ps", seed=3).pairs), Fd.dtype
    for Vd in [V.astype(">f8"), np.asfortranarray(V), V.astype(np.float16)]:
        expected = c.simplify(Vd.astype(np.float64), F, eps_rel=0.02)
        got = c.simplify(Vd, F, eps_rel=0.02)
        assert np.array_equal(got.faces, expected.faces), Vd.dtype
        assert np.array_equal(got.vertices, expected.vertices), Vd.dtype


# ------------------------------------------------------------------------ corpus

@pytest.mark.corpus
class TestCorpus:
    """The sweeps above over every closed mesh of the real-mesh corpus with at most
    conftest.SMALL_FACES faces (run with --corpus; they fail when the corpus is
    missing)."""

    def test_the_sweeps_cover_the_corpus(self):
        meshes = corpus_meshes()
        rows = small_closed(manifest(meshes))
        assert len(rows) >= CORPUS_SMALL_MIN, [m["name"] for m in rows]
        for m in rows:
            assert (meshes / m["file"]).is_file(), m["file"]

    def test_read_and_info_match_the_manifest(self, corpus_small):
        check_read_and_info(corpus_meshes(), corpus_small)

    def test_reduce_is_irreducible_and_keeps_the_surface(self, corpus_small):
        check_reduce(corpus_meshes(), corpus_small)

    def test_quad_lrs_is_perfect(self, corpus_small):
        check_quad_lrs(corpus_meshes(), corpus_small)
