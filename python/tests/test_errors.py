"""Bad arrays and bad files raise typed exceptions with their location, never crash the
interpreter; the GIL is released while the library works; results pickle."""

import pickle
import threading
import time
import types

import numpy as np
import pytest

import contractible as c
from conftest import DATA, data_mesh, manifest

# The octahedron: 6 vertices, 8 faces, a sphere.
OCT_V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                 dtype=np.float64)
OCT_F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
                  [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
EVERY = [
    lambda V, F: c.info(V, F),
    lambda V, F: c.reduce(V, F),
    lambda V, F: c.quad(V, F),
    lambda V, F: c.simplify(V, F, eps=0.1),
    lambda V, F: c.decimate(V, F, keep=0.5),
]
NAMES = ["info", "reduce", "quad", "simplify", "decimate"]


@pytest.mark.parametrize("f", EVERY, ids=NAMES)
def test_octahedron_works_everywhere(f):
    f(OCT_V, OCT_F)


@pytest.mark.parametrize("f", EVERY, ids=NAMES)
@pytest.mark.parametrize("F", [OCT_F[:, :2], OCT_F.ravel(), OCT_F.astype(np.float64),
                               OCT_F.astype(bool), np.zeros((0, 3, 1), dtype=np.int64)],
                         ids=["two-columns", "flat", "float", "bool", "3d"])
def test_bad_face_arrays_raise_value_error(f, F):
    with pytest.raises(ValueError):
        f(OCT_V, F)


@pytest.mark.parametrize("f", EVERY, ids=NAMES)
@pytest.mark.parametrize("V", [OCT_V[:, :2], OCT_V.ravel(), OCT_V.astype(str)],
                         ids=["two-columns", "flat", "strings"])
def test_bad_vertex_arrays_raise_value_error(f, V):
    with pytest.raises(ValueError):
        f(V, OCT_F)


@pytest.mark.parametrize("f", EVERY, ids=NAMES)
@pytest.mark.parametrize("bad,dtype", [(-1, np.int64), (6, np.int64), (2**40, np.int64),
                                       (-2**63, np.int64), (-1, np.int32),
                                       (2**31 - 1, np.int32), (6, np.uint32),
                                       (2**32 - 1, np.uint32)])
def test_out_of_range_index_names_the_face(f, bad, dtype):
    F = OCT_F.astype(dtype)
    F[5, 1] = bad
    with pytest.raises(c.MeshError) as e:
        f(OCT_V, F)
    assert e.value.kind == "vertex_out_of_range"
    assert e.value.location["face"] == 5
    assert "face 5" in str(e.value)


def test_uint64_indices_beyond_int64():
    F = OCT_F.astype(np.uint64)
    F[3, 0] = np.uint64(2**64 - 1)
    with pytest.raises(c.MeshError) as e:
        c.info(OCT_V, F)
    assert e.value.location["face"] == 3


@pytest.mark.parametrize("f", EVERY, ids=NAMES)
@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_non_finite_coordinates_name_the_vertex(f, value):
    V = OCT_V.copy()
    V[4, 2] = value
    with pytest.raises(c.MeshError) as e:
        f(V, OCT_F)
    assert e.value.kind == "non_finite_coordinate"
    assert e.value.location == {"vertex": 4}


def test_mesh_problems_are_located():
    # A boundary: reduce and quad need closed surfaces; info, simplify and decimate
    # accept it.
    open_f = OCT_F[1:]
    for f in [c.reduce, c.quad]:
        with pytest.raises(c.MeshError) as e:
            f(OCT_V, open_f)
        assert e.value.kind == "boundary_edge"
        assert "needs closed surfaces" in str(e.value)
        assert {"face", "a", "b"} <= set(e.value.location)
    assert c.info(OCT_V, open_f)["boundary_loops"] == 1
    c.simplify(OCT_V, open_f, eps=0.1)
    c.decimate(OCT_V, open_f, keep=0.5)
    # A degenerate face, a duplicate face, a non-manifold edge.
    cases = [
        (np.vstack([OCT_F, [[0, 0, 1]]]), "degenerate_face", {"face": 8}),
        (np.vstack([OCT_F, OCT_F[2:3]]), "duplicate_face", {"face": 8, "first": 2}),
        (np.vstack([OCT_F, [[0, 2, 1], [0, 1, 2]]]), None, None),
    ]
    for F, kind, loc in cases:
        for f in EVERY:
            with pytest.raises(c.MeshError) as e:
                f(OCT_V, F)
            if kind:
                assert e.value.kind == kind
                assert e.value.location == loc


def test_misc_arguments():
    with pytest.raises(ValueError):
        c.reduce(OCT_V, OCT_F, algo="nope")
    with pytest.raises(ValueError):
        c.quad(OCT_V, OCT_F, algo="nope")
    with pytest.raises(ValueError):
        c.simplify(OCT_V, OCT_F, eps=0.1, mode="nope")
    with pytest.raises(ValueError):
        c.simplify(OCT_V, OCT_F)  # no eps
    with pytest.raises(ValueError):
        c.simplify(OCT_V, OCT_F, eps=0.1, eps_rel=0.1)
    for eps in [0.0, -1.0, np.nan, np.inf]:
        with pytest.raises(ValueError):
            c.simplify(OCT_V, OCT_F, eps=eps)
    with pytest.raises(ValueError):
        c.simplify(None, OCT_F, eps=0.1)  # simplification needs positions
    with pytest.raises(TypeError):
        c.info(OCT_V)
    # Combinatorial algorithms need no positions.
    assert c.reduce(None, OCT_F).vertices is None
    assert c.quad(None, OCT_F).quads.shape == (4, 4)


def test_mesh_objects_are_accepted():
    mesh = types.SimpleNamespace(vertices=OCT_V, faces=OCT_F)
    assert c.info(mesh)["faces"] == 8
    assert c.reduce(mesh).faces.shape == (4, 3)  # the tetrahedron
    assert c.quad(mesh).quads.shape == (4, 4)
    assert c.simplify(mesh, eps=0.1).faces.shape == (8, 3)
    assert c.decimate(mesh).faces.shape == (4, 3)  # the tetrahedron


def test_trimesh_objects_are_accepted():
    # A test dependency (python[test]): missing, this test fails rather than skips.
    import trimesh

    V, F = c.read(data_mesh("adis16480_stl"))
    m = trimesh.Trimesh(V, F, process=False)
    assert c.info(m)["faces"] == len(F)
    assert np.array_equal(c.reduce(m).faces, c.reduce(V, F).faces)


def test_bad_files(tmp_path):
    p = tmp_path / "bad.off"
    p.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 x 0\n3 0 1 2\n")
    with pytest.raises(c.MeshError) as e:
        c.read(p)
    assert e.value.kind == "read"
    assert e.value.location == {"line": 5}
    p.write_text("OFF\n3 999999999999 0\n0 0 0\n")
    with pytest.raises(c.MeshError):
        c.read(p)
    with pytest.raises(OSError):
        c.read(tmp_path / "missing.off")
    with pytest.raises(ValueError):
        c.write(tmp_path / "x.unknown", OCT_V, OCT_F)
    with pytest.raises(OSError):
        c.write(tmp_path / "missing_dir" / "x.off", OCT_V, OCT_F)
    assert not list((tmp_path).glob(".contractible-*"))


def test_decimated_write(tmp_path):
    d = c.decimate(OCT_V, OCT_F)
    p = tmp_path / "d.off"
    c.write(p, d)  # the result is a (vertices, faces) mesh
    V, F = c.read(p)
    assert np.array_equal(V, d.vertices) and np.array_equal(F, d.faces)


def test_quads_write(tmp_path):
    q = c.quad(OCT_V, OCT_F)
    p = tmp_path / "q.obj"
    c.write(p, q)  # the result is a (vertices, faces) mesh of quads
    text = p.read_text()
    assert sum(line.startswith("f ") and len(line.split()) == 5
               for line in text.splitlines()) == 4


def test_mesh_error_pickles():
    try:
        c.reduce(OCT_V, OCT_F[1:])
    except c.MeshError as e:
        e2 = pickle.loads(pickle.dumps(e))
        assert (e2.message, e2.kind, e2.location) == (e.message, e.kind, e.location)
        assert isinstance(e2, ValueError)
    else:
        pytest.fail("no error")


def _ticks_while(work):
    """How many times another Python thread got to run while `work()` ran, and for how
    long `work()` ran."""
    done = threading.Event()
    ticks = [0]

    def count():
        while not done.is_set():
            ticks[0] += 1
            time.sleep(0)

    t = threading.Thread(target=count)
    t.start()
    start = time.perf_counter()
    work()
    elapsed = time.perf_counter() - start
    done.set()
    t.join()
    return ticks[0], elapsed


def test_gil_is_released(cli, tmp_path):
    """While one thread simplifies a large mesh, another keeps running Python code: with
    the GIL held it could run only at the interpreter's forced switches, as it does
    beside a pure-Python loop of the same length (the baseline, measured in the same
    run so that a loaded machine slows both alike)."""
    # The bunny subdivided twice: 16 times its 3,674 faces.
    big = tmp_path / "bunny16.off"
    cli("gen", "subdivide", "--input", data_mesh("bunny_npm"), "--levels", 2, "-o", big,
        "--quiet")
    V, F = c.read(big)
    bunny = next(m for m in manifest(DATA) if m["name"] == "bunny_npm")
    assert len(F) == 16 * int(bunny["F"])

    def calls():
        c.reduce(V, F)
        c.quad(V, F)
        c.simplify(V, F, eps_rel=0.01)
        c.decimate(V, F, keep=0.1)

    during_calls, elapsed = _ticks_while(calls)

    def python_loop():
        end = time.perf_counter() + elapsed
        while time.perf_counter() < end:
            pass

    beside_python, _ = _ticks_while(python_loop)
    assert during_calls > 4 * beside_python + 100, (during_calls, beside_python, elapsed)
