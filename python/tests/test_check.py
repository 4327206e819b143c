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
