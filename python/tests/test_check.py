"""`contractible.check`: the library's verdict on any implementation's output, equal to
the command line's `check --json` on the same files; right answers pass, each kind of
wrong answer fails with its located reason, inputs the task refuses raise."""

import json

import numpy as np
import pytest

import contractible as c
from conftest import data_mesh

CASES = ["bunny_npm", "high_genus_3", "two_objects", "torus7", "klein", "tetrahedron"]


@pytest.mark.parametrize("name", CASES)
def test_our_reductions_pass_and_the_inputs_fail_as_the_cli_says(name, cli, tmp_path, mesh_file):
    src = mesh_file(name)
    V, F = c.read(src)
    r = c.reduce(V, F)
    n = None if V is not None else int(F.max()) + 1
    ok = c.check("reduce", V, F, r.vertices, r.faces, vertex_count=n,
                 out_vertex_count=None if V is not None else n)
    if V is None:
        # Without positions the output is read in the input's ids.
        ok = c.check("reduce", V, F, None, r.vertex_map[r.faces], vertex_count=n,
                     out_vertex_count=n)
    assert ok["passed"], ok
    assert ok == {"task": "reduce", "passed": True, "counts": {}, "failures": []}
    # The input as its own answer, against the command line's verdict.
    theirs = cli("--json", "check", "reduce", src, src, check=False)
    ours = c.check("reduce", V, F, V, F, vertex_count=n, out_vertex_count=n)
    assert theirs.returncode == (0 if ours["passed"] else 1)
    t = json.loads(theirs.stdout)
    for k in ("task", "passed", "counts", "failures"):
        assert ours[k] == t[k], k
    if name in ("tetrahedron", "torus7", "klein"):
        # Irreducible already (the 7-vertex torus, the 9-vertex Klein bottle).
        assert ours["passed"], ours
    else:
        assert set(ours["counts"]) == {"contractible_edge"}
        assert all(f["kind"] == "contractible_edge" and len(f["edge"]) == 2
                   for f in ours["failures"])


def test_wrong_answers_are_located():
    V, F = c.read(data_mesh("bunny_npm"))
    r = c.reduce(V, F)
    # A moved vertex (the output's list is compacted: matched by position).
    Vm = r.vertices.copy()
    Vm[0, 0] += 1.0
    v = c.check("reduce", V, F, Vm, r.faces)
    assert not v["passed"]
    assert v["counts"] == {"unknown_vertex": 1}
    assert v["failures"][0]["vertex"] == 0
    # A face dropped: boundary edges.
    v = c.check("reduce", V, F, r.vertices, r.faces[1:])
    assert v["counts"] == {"boundary_edge": 3}
    assert all("edge" in f and "face" in f for f in v["failures"])
    # A repeated face.
    v = c.check("reduce", V, F, r.vertices, np.vstack([r.faces, r.faces[:1]]))
    assert v["counts"]["repeated_face"] == 1
    assert v["failures"][0] == {
        "kind": "repeated_face", "face": len(r.faces),
        "message": f"output faces 0 and {len(r.faces)} have the same vertices "
                   f"{sorted(r.faces[0].tolist())}"}


def test_inputs_the_task_refuses_raise():
    V, F = c.read(data_mesh("bunny_npm"))
    with pytest.raises(c.MeshError):
        c.check("reduce", V, F[1:], V, F)
    with pytest.raises(ValueError, match="unknown task"):
        c.check("simplify-all", V, F, V, F)


def _holed(V, F):
    """The mesh without the faces around vertex 0: one boundary loop more."""
    return V, F[~(F == 0).any(axis=1)]


SIMPLIFY_RUNS = [("naive", "midpoint", True), ("nested", "midpoint", True),
                 ("naive", "midpoint", False), ("naive", "quadric", True),
                 ("nested", "quadric", False)]


@pytest.mark.parametrize("name", ["bunny_npm", "high_genus_3", "two_objects"])
@pytest.mark.parametrize("holed", [False, True])
def test_our_simplifications_pass(name, holed):
    V, F = c.read(data_mesh(name))
    if holed:
        V, F = _holed(V, F)
    for mode, position, guard in SIMPLIFY_RUNS:
        s = c.simplify(V, F, eps_rel=0.03, mode=mode, position=position, guard=guard)
        v = c.check("simplify", V, F, s.vertices, s.faces, eps_rel=0.03,
                    position=position, guard=guard)
        assert v == {"task": "simplify", "passed": True, "counts": {}, "failures": []}, \
            (mode, position, guard)


def test_the_input_as_its_own_simplification_fails_as_the_cli_says(cli):
    src = data_mesh("bunny_npm")
    V, F = c.read(src)
    ours = c.check("simplify", V, F, V, F, eps_rel=0.02)
    theirs = cli("--json", "check", "simplify", src, src, "--eps-rel", "0.02", check=False)
    assert theirs.returncode == 1
    t = json.loads(theirs.stdout)
    for k in ("task", "passed", "counts", "failures"):
        assert ours[k] == t[k], k
    assert set(ours["counts"]) == {"short_contractible_edge"}
    assert all(len(f["edge"]) == 2 and "face" in f for f in ours["failures"])
    # Judged against a larger ε than its run's, a simplification has short edges left;
    # with the guard off more of them count.
    s = c.simplify(V, F, eps_rel=0.02, mode="naive")
    on = c.check("simplify", V, F, s.vertices, s.faces, eps_rel=0.03)
    off = c.check("simplify", V, F, s.vertices, s.faces, eps_rel=0.03, guard=False)
    assert set(on["counts"]) == {"short_contractible_edge"}
    assert off["counts"]["short_contractible_edge"] >= on["counts"]["short_contractible_edge"]
    # An ε below every edge: nothing to contract.
    assert c.check("simplify", V, F, V, F, eps=1e-9)["passed"]


def test_wrong_simplifications_are_located():
    V, F = c.read(data_mesh("bunny_npm"))
    s = c.simplify(V, F, eps_rel=0.02)
    # A face dropped: a boundary loop more, χ one less (the output's list is compacted:
    # compared by surface type).
    v = c.check("simplify", V, F, s.vertices, s.faces[1:], eps_rel=0.02)
    assert v["counts"].get("surface_changed") == 1, v
    f = next(f for f in v["failures"] if f["kind"] == "surface_changed")
    assert f["component"] == 0 and "1 boundary loop" in f["message"], f
    # No positions (non-finite ones never get past the array reader).
    v = c.check("simplify", V, F, None, s.faces, eps_rel=0.02)
    assert v["counts"] == {"invalid_position": 1}
    assert "vertex" not in v["failures"][0]
    with pytest.raises(c.MeshError, match="non-finite"):
        Vn = s.vertices.copy()
        Vn[5, 2] = np.nan
        c.check("simplify", V, F, Vn, s.faces, eps_rel=0.02)


def test_simplify_check_refusals():
    V, F = c.read(data_mesh("bunny_npm"))
    with pytest.raises(ValueError, match="exactly one of eps and eps_rel"):
        c.check("simplify", V, F, V, F)
    with pytest.raises(ValueError, match="exactly one of eps and eps_rel"):
        c.check("simplify", V, F, V, F, eps=0.1, eps_rel=0.1)
    with pytest.raises(ValueError, match="options of"):
        c.check("reduce", V, F, V, F, eps=0.1)
    with pytest.raises(ValueError):
        c.check("simplify", V, F, V, F, eps=0.0)
    with pytest.raises(ValueError):
        c.check("simplify", V, F, V, F, eps=0.1, position="nowhere")
    with pytest.raises(ValueError):
        c.check("simplify", None, F, V, F, eps=0.1)
    with pytest.raises(c.MeshError):
        c.check("simplify", V, np.vstack([F, F[:1]]), V, F, eps=0.1)


@pytest.mark.parametrize("algo", ["lrs", "ps", "matching", "ds"])
def test_quad_answers_pass_and_the_cli_agrees(algo, cli, tmp_path, mesh_file):
    src = mesh_file("high_genus_3")
    V, F = c.read(src)
    q = c.quad(V, F, algo=algo)
    ok = c.check("quad", V, F, q.vertices, q.quads, triangles=q.triangles, pairs=q.pairs)
    assert ok == {"task": "quad", "passed": True, "counts": {}, "failures": []}
    # Without K the quads must pair the input's faces: true when no edge was flipped.
    bare = c.check("quad", V, F, q.vertices, q.quads)
    flipped = not np.array_equal(q.triangles, F)
    assert bare["passed"] or flipped
    # The command line's verdict on the files `quad` writes is the same.
    out, k, p = tmp_path / "q.off", tmp_path / "k.off", tmp_path / "p.txt"
    cli("quad", src, "--algo", algo, "-o", out, "--triangles", k, "--pairs", p, "-q")
    for extra, expected in (([], bare), (["--triangles", k, "--pairs", p], ok)):
        r = cli("--json", "check", "quad", src, out, *extra, check=False)
        assert r.returncode == (0 if expected["passed"] else 1), r.stderr
        t = json.loads(r.stdout)
        for key in ("task", "passed", "counts", "failures"):
            assert t[key] == expected[key], key


def test_wrong_quad_answers_are_located():
    V, F = c.read(data_mesh("bunny_npm"))
    q = c.quad(V, F, algo="matching")
    Q = q.quads.copy()
    Q[3] = Q[0]
    v = c.check("quad", V, F, q.vertices, Q)
    assert v["counts"] == {"triangle_used_twice": 2, "triangle_unused": 2}
    P = q.pairs.copy()
    P[[0, 1]] = P[[1, 0]]
    v = c.check("quad", V, F, q.vertices, q.quads, pairs=P)
    assert v["counts"]["wrong_pair"] == 2
    assert v["failures"][0]["face"] == 0
    Q = q.quads.copy()
    Q[7, [1, 2]] = Q[7, [2, 1]]
    v = c.check("quad", V, F, q.vertices, Q)
    assert "quad_not_two_triangles" in v["counts"]
    with pytest.raises(ValueError, match="options of \"quad\""):
        c.check("reduce", V, F, V, F, pairs=q.pairs)
    with pytest.raises(ValueError, match="shape"):
        c.check("quad", V, F, q.vertices, q.quads, pairs=q.pairs[:, :1])
    with pytest.raises(ValueError, match="shape"):
        c.check("quad", V, F, V, F)
    with pytest.raises(c.MeshError):
        c.check("quad", V, F[1:], q.vertices, q.quads)


def test_decimations_pass_with_their_maps_and_wrong_ones_are_named(cli, tmp_path):
    src = data_mesh("bunny_npm")
    V, F = c.read(src)
    d = c.decimate(V, F, keep=0.2)
    maps = dict(vertex_map=d.vertex_map, collapse_map=d.collapse_map, face_origin=d.face_origin)
    ok = c.check("decimate", V, F, d.vertices, d.faces, keep=0.2, **maps)
    assert ok == {"task": "decimate", "passed": True, "counts": {}, "failures": []}
    # The command line's verdict on the files decimate writes is the same.
    out, mp = tmp_path / "d.off", tmp_path / "d.maps"
    cli("decimate", src, "--keep", "0.2", "-o", out, "--maps", mp, "-q")
    r = cli("--json", "check", "decimate", src, out, "--keep", "0.5", check=False)
    t = json.loads(r.stdout)
    ours = c.check("decimate", V, F, d.vertices, d.faces, keep=0.5)
    assert r.returncode == 1 and not ours["passed"]
    for key in ("task", "passed", "counts", "failures"):
        assert ours[key] == t[key], key
    # Wrong maps, a moved locked vertex, the input as an unguarded run's answer.
    bad = d.vertex_map.copy()
    bad[[0, 1]] = bad[[1, 0]]
    v = c.check("decimate", V, F, d.vertices, d.faces, keep=0.2, vertex_map=bad,
                collapse_map=d.collapse_map)
    assert "inconsistent_map" in v["counts"]
    lk = c.decimate(V, F, keep=0.2, locked=[5])
    Vm = lk.vertices.copy()
    Vm[lk.collapse_map[5], 0] += 1.0
    v = c.check("decimate", V, F, Vm, lk.faces, keep=0.2, locked=[5], vertex_map=lk.vertex_map)
    assert v["counts"] == {"moved_vertex": 1}
    v = c.check("decimate", V, F, V, F, keep=0.2, guard=False)
    assert set(v["counts"]) == {"target_missed"}
    with pytest.raises(ValueError, match="option of \"decimate\""):
        c.check("reduce", V, F, V, F, keep=0.2)
    with pytest.raises(ValueError, match="no id"):
        c.check("decimate", V, F, V, F, vertex_map=[-5])
    with pytest.raises(ValueError, match="decimate needs coordinates"):
        c.check("decimate", None, F, V, F)


def test_a_reduction_s_history_replays_as_the_cli_and_library_say(cli, tmp_path, mesh_file):
    src = mesh_file("bunny_npm")
    V, F = c.read(src)
    r = c.reduce(V, F)
    steps = r.history.contractions()
    assert steps.shape == (len(r.history), 2) and steps.dtype == np.int64
    # The columns u, v of records(), and what `reduce --history` writes.
    assert (steps == r.history.records()[:, 1:3]).all()
    out, hist = tmp_path / "r.off", tmp_path / "steps.txt"
    cli("reduce", src, "-o", out, "--history", hist, "-q")
    written = np.loadtxt(hist, dtype=np.int64, ndmin=2)
    assert (written == steps).all()
    ok = c.check("reduce", V, F, r.vertices, r.faces, history=steps)
    assert ok["passed"], ok
    # One step too few, and a step repeated: as `check reduce --history` says.
    for edited, kind in ((steps[:-1], "history_mismatch"),
                         (np.vstack([steps[:1], steps]), "invalid_history")):
        np.savetxt(hist, edited, fmt="%d")
        theirs = json.loads(cli("--json", "check", "reduce", src, out, "--history", hist,
                                check=False).stdout)
        ours = c.check("reduce", V, F, r.vertices, r.faces, history=edited)
        assert not ours["passed"] and kind in ours["counts"], ours
        for k in ("task", "passed", "counts", "failures"):
            assert ours[k] == theirs[k], k
    # An empty history of a reducible input replays to the input, not the output.
    v = c.check("reduce", V, F, r.vertices, r.faces, history=[])
    assert "history_mismatch" in v["counts"]
    with pytest.raises(ValueError, match="history must have shape"):
        c.check("reduce", V, F, r.vertices, r.faces, history=[1, 2, 3])
    with pytest.raises(ValueError, match="history is an option of"):
        c.check("simplify", V, F, r.vertices, r.faces, eps=0.1, history=steps)
