"""`decimate` on the repository's real meshes and on surfaces built with NumPy (closed,
with boundary, non-orientable, several components), each output checked by code written
here from the definitions: the topology of every component (χ, orientability, boundary
loops) against its input component's, the maps against the faces, the targets, the error
cap (the quadric error recomputed from the input's planes), the locks and the placements;
then bad arguments, determinism, trimesh, and the command line's `decimate`."""

import json

import numpy as np
import pytest

import contractible as c
from conftest import (bunny_open_mesh, components, data_mesh, edges_of,
                      is_closed_manifold_faces, surface_signature)

# Genus 0 (a real scan), 3 and 5 (one component each); 10 components of genus 0 to 6.
CLOSED = ["bunny_npm", "high_genus_3", "plate_holes_stl", "box_stl"]


def mobius(n_u=40, n_v=6):
    """A Möbius strip (non-orientable, one boundary loop, χ = 0): an n_u × n_v grid on
    the strip, the last column glued to the first one upside down."""
    u = np.linspace(0, 2 * np.pi, n_u, endpoint=False)
    v = np.linspace(-1, 1, n_v)
    U, W = np.meshgrid(u, v, indexing="ij")
    r = 2 + W * np.cos(U / 2)
    V = np.stack([r * np.cos(U), r * np.sin(U), W * np.sin(U / 2)], axis=-1).reshape(-1, 3)

    def at(i, k):
        if i == n_u:  # across the seam: the first column, upside down
            return n_v - 1 - k
        return i * n_v + k

    F = []
    for i in range(n_u):
        for k in range(n_v - 1):
            a, b = at(i, k), at(i, k + 1)
            cc, d = at(i + 1, k), at(i + 1, k + 1)
            F += [[a, cc, d], [a, d, b]]
    return V, np.array(F, dtype=np.int64)


def two_spheres_and_a_strip():
    """Three components with positions: the bunny, the open bunny moved aside, and a
    Möbius strip moved further."""
    Vb, Fb = c.read(data_mesh("bunny_npm"))
    Vo, Fo = bunny_open_mesh()
    Vm, Fm = mobius()
    shift = 2 * np.ptp(Vb, axis=0).max()
    V = np.vstack([Vb, Vo + [shift, 0, 0], Vm + [0, shift, 0]])
    F = np.vstack([Fb, Fo + len(Vb), Fm + len(Vb) + len(Vo)])
    return V, F


def boundary_vertices(F):
    return np.unique([v for e, fs in edges_of(F).items() if len(fs) == 1 for v in e])


def boundary_loop_count(F):
    return sum(s[2] for s in surface_signature(F))


def quadric_errors(V, F, d):
    """Per output vertex, sqrt(Q(x) / W): the root mean square distance of its position
    from the planes of the input faces at the input vertices merged into it (weighted by
    area) and of the boundary planes at those vertices (through each boundary edge,
    perpendicular to its face, weighted by 10 × the face's area), written from the
    definition of `decimate`'s error."""
    V, F = np.asarray(V, dtype=np.float64), np.asarray(F)
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    twice = np.linalg.norm(n, axis=1)
    ok = twice > 0
    unit = np.zeros_like(n)
    unit[ok] = n[ok] / twice[ok, None]
    w = np.where(ok, 0.5 * twice, 0.0)
    # Planes: (input vertex, normal, point on the plane, weight).
    who, normal, point, weight = [], [], [], []
    for k in range(3):
        who.append(F[:, k])
        normal.append(unit)
        point.append(V[F[:, 0]])
        weight.append(w)
    count = edges_of(F)
    for (a, b), fs in count.items():
        if len(fs) != 1:
            continue
        f = fs[0]
        m = np.cross(V[b] - V[a], unit[f])
        length = np.linalg.norm(m)
        if length == 0 or not ok[f]:
            continue
        for x in (a, b):
            who.append(np.array([x]))
            normal.append((m / length)[None])
            point.append(V[a][None])
            weight.append(np.array([10 * w[f]]))
    who, normal = np.concatenate(who), np.concatenate(normal)
    point, weight = np.concatenate(point), np.concatenate(weight)
    o = d.collapse_map[who]
    residual = np.einsum("ij,ij->i", normal, d.vertices[o] - point)
    k = len(d.vertices)
    q = np.bincount(o, weights=weight * residual ** 2, minlength=k)
    total = np.bincount(o, weights=weight, minlength=k)
    return np.sqrt(np.divide(q, total, out=np.zeros(k), where=total > 0))


def check(V, F, d, locked=(), lock_boundary=False, cap=None):
    """Everything a decimation of (V, F) promises, checked from the input and the
    returned arrays alone."""
    V, F = np.asarray(V), np.asarray(F)
    k, f = len(d.vertices), len(d.faces)
    assert d.vertices.dtype == np.float64 and d.vertices.shape == (k, 3)
    assert d.faces.dtype == np.int64 and d.faces.shape == (f, 3)
    for a in (d.vertex_map, d.collapse_map, d.face_origin):
        assert a.dtype == np.int64 and a.ndim == 1
    # The maps.
    used = np.zeros(len(V), dtype=bool)
    used[F.ravel()] = True
    assert d.vertex_map.shape == (k,) and d.collapse_map.shape == (len(V),)
    assert d.face_origin.shape == (f,)
    assert np.all(np.diff(d.vertex_map) > 0) and np.all(used[d.vertex_map])
    assert np.array_equal(d.collapse_map[d.vertex_map], np.arange(k))
    assert np.all(d.collapse_map[~used] == -1)
    assert np.all((d.collapse_map[used] >= 0) & (d.collapse_map[used] < k))
    assert np.all(np.diff(d.face_origin) > 0)
    assert np.array_equal(d.faces, d.collapse_map[F[d.face_origin]])
    # Every output vertex is used; no face degenerate or repeated.
    assert np.array_equal(np.unique(d.faces), np.arange(k))
    assert np.all((d.faces[:, 0] != d.faces[:, 1]) & (d.faces[:, 1] != d.faces[:, 2])
                  & (d.faces[:, 2] != d.faces[:, 0]))
    assert len(np.unique(np.sort(d.faces, axis=1), axis=0)) == f
    assert all(len(fs) <= 2 for fs in edges_of(d.faces).values())
    if is_closed_manifold_faces(F):
        assert is_closed_manifold_faces(d.faces)
    # The topology, component by component: each output component descends from one
    # input component, one to one, with the same (χ, orientable, boundary loops).
    comp_in = np.empty(len(F), dtype=np.int64)
    parts_in = components(F)
    for i, part in enumerate(parts_in):
        comp_in[part] = i
    parts_out = components(d.faces)
    assert len(parts_out) == len(parts_in)
    origin = set()
    for part in parts_out:
        from_ = np.unique(comp_in[d.face_origin[part]])
        assert len(from_) == 1
        origin.add(int(from_[0]))
        assert surface_signature(d.faces[part]) == surface_signature(F[parts_in[from_[0]]])
    assert origin == set(range(len(parts_in)))
    # Locked vertices survive where they were.
    for x in locked:
        o = d.collapse_map[x]
        assert d.vertex_map[o] == x
        assert np.array_equal(d.vertices[o], V[x])
    if lock_boundary:
        b = boundary_vertices(F)
        assert np.array_equal(d.vertex_map[d.collapse_map[b]], b)
        assert np.array_equal(d.vertices[d.collapse_map[b]], V[b])
    # The statistics against the arrays.
    s = d.stats
    assert (s["faces_in"], s["faces_out"]) == (len(F), f)
    assert (s["vertices_in"], s["vertices_out"]) == (int(used.sum()), k)
    assert s["collapses"] == s["vertices_in"] - s["vertices_out"]
    assert s["components"] == len(parts_in)
    assert s["boundary_loops"] == boundary_loop_count(F)
    assert s["dropped_vertices"] == int((~used).sum())
    assert len(s["component_list"]) == len(parts_in)
    assert sum(p["faces_out"] for p in s["component_list"]) == f
    assert s["stopped"] in ("target", "error", "blocked")
    guards = {"lock", "boundary", "error", "link_condition", "foldover"}
    assert set(s["refused"]) == guards and set(s["remaining"]) == guards
    if s["stopped"] == "target":
        assert s["target_faces"] is not None and f <= s["target_faces"]
        assert all(v == 0 for v in s["remaining"].values())
    else:
        assert s["target_faces"] is None or f > s["target_faces"]
        assert sum(s["remaining"].values()) > 0
        assert (s["remaining"]["error"] > 0) == (s["stopped"] == "error")
    # The error: every output vertex's quadric error is at most the largest collapse
    # error reported, and that at most the cap. The library evaluates the quadric in its
    # expanded form (x'Ax + 2b'x + c), whose rounding leaves about sqrt(ε_machine) × the
    # coordinates' magnitude (R) of noise in the error: a vertex of nearly coplanar
    # faces (float32 STL coordinates) can be 1e-8 R off its planes with a reported error
    # of 0.
    R = np.abs(V[used]).max()
    noise2 = 64 * np.finfo(np.float64).eps * R * R
    errors = quadric_errors(V, F, d)
    assert np.all(errors ** 2 <= s["max_error"] ** 2 + noise2), \
        (errors.max(initial=0), s["max_error"])
    if cap is not None:
        assert s["max_error_cap"] == pytest.approx(cap, rel=1e-12)
        assert s["max_error"] <= s["max_error_cap"]
    return s


# ---------------------------------------------------------------------------- targets

@pytest.mark.parametrize("name", CLOSED)
def test_keep_reaches_the_target_and_keeps_the_topology(name):
    V, F = c.read(data_mesh(name))
    d = c.decimate(V, F, keep=0.25)
    s = check(V, F, d)
    target = int(np.ceil(0.25 * len(F)))
    assert s["target_faces"] == target
    if s["stopped"] == "target":
        assert len(d.faces) <= target
    assert len(d.faces) < len(F)
    # Not just the input's vertices: optimal placement moved some.
    assert not np.array_equal(d.vertices, V[d.vertex_map])


def test_faces_target_on_a_sphere_is_reached():
    V, F = c.read(data_mesh("bunny_npm"))
    for target in [3000, 1000, 200, 20]:
        d = c.decimate(V, F, faces=target)
        s = check(V, F, d)
        assert s["stopped"] == "target" and s["target_faces"] == target
        assert target - 2 <= len(d.faces) <= target  # a collapse removes two faces


def test_faces_and_keep_combine_to_the_larger_count():
    V, F = c.read(data_mesh("high_genus_3"))
    d = c.decimate(V, F, faces=500, keep=0.5)
    assert check(V, F, d)["target_faces"] == len(F) // 2
    assert d.stats["targets"] == {"faces": 500, "keep": 0.5, "max_error": None,
                                  "max_error_rel": None}
    d = c.decimate(V, F, faces=2000, keep=0.1)
    assert check(V, F, d)["target_faces"] == 2000


def test_no_target_goes_as_far_as_the_guards_allow():
    V, F = c.read(data_mesh("high_genus_3"))
    d = c.decimate(V, F)
    s = check(V, F, d)
    assert s["target_faces"] is None and s["max_error_cap"] is None
    assert s["stopped"] == "blocked"
    # Genus 3: at least the 10 vertices of an irreducible triangulation of it remain.
    assert 10 <= len(d.vertices) < 200


@pytest.mark.parametrize("name", CLOSED)
def test_the_pass_schedule_reaches_the_target_keeping_the_topology(name):
    V, F = c.read(data_mesh(name))
    d = c.decimate(V, F, keep=0.1, schedule="passes")
    s = check(V, F, d)
    assert s["schedule"] == "passes" and s["passes"] >= 1
    if s["stopped"] == "target":
        assert len(d.faces) <= s["target_faces"]
    else:
        assert sum(s["remaining"].values()) > 0
    exact = c.decimate(V, F, keep=0.1)
    assert exact.stats["schedule"] == "exact" and exact.stats["passes"] == 0
    # The same when asked twice.
    again = c.decimate(V, F, keep=0.1, schedule="passes")
    assert np.array_equal(d.faces, again.faces) and np.array_equal(d.vertices, again.vertices)


def test_keep_zero_and_one():
    V, F = c.read(data_mesh("plate_holes_stl"))
    d = c.decimate(V, F, keep=1.0)
    check(V, F, d)
    assert d.stats["stopped"] == "target" and d.stats["collapses"] == 0
    assert np.array_equal(d.vertices, V) and np.array_equal(d.faces, F)
    assert np.array_equal(d.face_origin, np.arange(len(F)))
    d = c.decimate(V, F, keep=0.0)
    assert check(V, F, d)["stopped"] == "blocked"


@pytest.mark.parametrize("rel", [0.002, 0.01])
def test_the_error_cap_holds(rel):
    V, F = c.read(data_mesh("bunny_npm"))
    diag = np.linalg.norm(np.ptp(V, axis=0))
    d = c.decimate(V, F, max_error_rel=rel)
    s = check(V, F, d, cap=rel * diag)
    assert s["stopped"] == "error" and s["collapses"] > 0
    assert s["bbox_diagonal"] == pytest.approx(diag, rel=1e-12)
    # The same cap given as an absolute distance: the same output.
    e = c.decimate(V, F, max_error=rel * diag)
    assert np.array_equal(e.faces, d.faces) and np.array_equal(e.vertices, d.vertices)
    # A larger cap goes further.
    assert len(c.decimate(V, F, max_error_rel=2 * rel).faces) < len(d.faces)


def test_target_and_cap_stop_at_the_first_reached():
    V, F = c.read(data_mesh("bunny_npm"))
    diag = np.linalg.norm(np.ptp(V, axis=0))
    loose = c.decimate(V, F, faces=2000, max_error_rel=0.05)
    assert check(V, F, loose, cap=0.05 * diag)["stopped"] == "target"
    tight = c.decimate(V, F, faces=100, max_error_rel=0.001)
    s = check(V, F, tight, cap=0.001 * diag)
    assert s["stopped"] == "error" and len(tight.faces) > 100
    # A zero cap collapses only what costs nothing.
    check(V, F, c.decimate(V, F, max_error=0.0), cap=0.0)


# ------------------------------------------------------------------------- topologies

def test_boundary_non_orientable_and_several_components():
    V, F = two_spheres_and_a_strip()
    sig = surface_signature(F)
    assert sig == [(0, False, 1), (1, True, 1), (2, True, 0)]
    for keep in [0.5, 0.1, 0.0]:
        d = c.decimate(V, F, keep=keep)
        s = check(V, F, d)
        assert surface_signature(d.faces) == sig
        assert s["components"] == 3 and s["boundary_loops"] == 2


def test_mobius_strip_alone():
    V, F = mobius(60, 8)
    d = c.decimate(V, F, faces=40)
    check(V, F, d)
    assert surface_signature(d.faces) == [(0, False, 1)]


# --------------------------------------------------------------- locks and placements

def test_locked_vertices_stay():
    V, F = c.read(data_mesh("bunny_npm"))
    rng = np.random.default_rng(5)
    locked = rng.choice(len(V), 40, replace=False)
    for kind in [list, np.int32, np.uint64, np.int64]:
        lock = locked.tolist() if kind is list else locked.astype(kind)
        d = c.decimate(V, F, keep=0.1, locked=lock)
        check(V, F, d, locked=locked)
        assert d.stats["locked"] == sorted(locked.tolist())
        assert d.stats["target_faces"] == int(np.ceil(0.1 * len(F)))
    # Everything locked: nothing moves or goes.
    d = c.decimate(V, F, keep=0.1, locked=np.arange(len(V)))
    assert d.stats["collapses"] == 0 and d.stats["stopped"] == "blocked"
    assert d.stats["remaining"]["lock"] == len(edges_of(F))
    assert np.array_equal(d.vertices, V) and np.array_equal(d.faces, F)
    # Empty is no lock.
    a, b = c.decimate(V, F, keep=0.2, locked=[]), c.decimate(V, F, keep=0.2)
    assert np.array_equal(a.faces, b.faces)


def test_lock_boundary():
    V, F = bunny_open_mesh()
    Vm, Fm = mobius()
    V, F = np.vstack([V, Vm + [1, 0, 0]]), np.vstack([F, Fm + len(V)])
    d = c.decimate(V, F, keep=0.05, lock_boundary=True)
    s = check(V, F, d, lock_boundary=True)
    assert s["lock_boundary"] is True
    free = c.decimate(V, F, keep=0.05)
    # Without the lock the Möbius strip's border moves.
    b = boundary_vertices(Fm) + len(V) - len(Vm)
    moved = (free.vertex_map[free.collapse_map[b]] != b) | np.any(
        free.vertices[free.collapse_map[b]] != V[b], axis=1)
    assert moved.any()


@pytest.mark.parametrize("name", ["bunny_npm", "box_stl"])
def test_endpoint_placement_keeps_input_positions(name):
    V, F = c.read(data_mesh(name))
    d = c.decimate(V, F, keep=0.1, placement="endpoint")
    check(V, F, d)
    assert d.stats["placement"] == "endpoint"
    assert np.array_equal(d.vertices, V[d.vertex_map])


def test_midpoint_placement():
    V, F = c.read(data_mesh("bunny_npm"))
    d = c.decimate(V, F, keep=0.2, placement="midpoint")
    check(V, F, d)
    # Every position is a convex combination of the input positions of the vertices
    # merged into it (midpoints of midpoints): it lies in their bounding box.
    for o in range(0, len(d.vertices), 37):
        merged = V[d.collapse_map == o]
        assert np.all(merged.min(axis=0) - 1e-12 <= d.vertices[o])
        assert np.all(d.vertices[o] <= merged.max(axis=0) + 1e-12)


def test_guard_off_still_keeps_the_topology():
    V, F = c.read(data_mesh("plate_holes_stl"))
    d = c.decimate(V, F, guard=False)
    s = check(V, F, d)
    assert s["guard"] is False and s["remaining"]["foldover"] == 0
    assert s["refused"]["foldover"] == 0


# ------------------------------------------------------------------- results and I/O

def test_deterministic_and_written(tmp_path):
    V, F = c.read(data_mesh("box_stl"))
    a, b = c.decimate(V, F, keep=0.3), c.decimate(V, F, keep=0.3)
    for k in ["vertices", "faces", "vertex_map", "collapse_map", "face_origin"]:
        assert np.array_equal(getattr(a, k), getattr(b, k)), k
    untimed = {k: v for k, v in a.stats.items() if k != "seconds"}
    assert untimed == {k: v for k, v in b.stats.items() if k != "seconds"}
    p = tmp_path / "d.off"
    c.write(p, a)
    V2, F2 = c.read(p)
    assert np.array_equal(F2, a.faces) and np.array_equal(V2, a.vertices)


def test_unused_vertices_are_marked():
    V, F = c.read(data_mesh("bunny_npm"))
    # Two vertices no face uses, first and in the middle.
    V2 = np.vstack([[9.0, 9.0, 9.0], V[:100], [7.0, 7.0, 7.0], V[100:]])
    F2 = np.where(F < 100, F + 1, F + 2)
    d = c.decimate(V2, F2, keep=0.3)
    check(V2, F2, d)
    assert d.collapse_map[0] == -1 and d.collapse_map[101] == -1
    assert d.stats["dropped_vertices"] == 2
    ref = c.decimate(V, F, keep=0.3)
    assert np.array_equal(d.faces, ref.faces) and np.array_equal(d.vertices, ref.vertices)


def test_dtypes_and_mesh_objects_give_the_same_result():
    V, F = c.read(data_mesh("plate_holes_stl"))
    ref = c.decimate(V, F, keep=0.2)
    for Fd in [F.astype(np.int32), F.astype(np.uint32), F.astype(np.int16)]:
        assert np.array_equal(c.decimate(V, Fd, keep=0.2).faces, ref.faces)
    import types
    mesh = types.SimpleNamespace(vertices=V, faces=F)
    assert np.array_equal(c.decimate(mesh, keep=0.2).vertices, ref.vertices)


def test_trimesh_in_and_out():
    # A test dependency (python[test]): missing, this test fails rather than skips.
    import trimesh

    V, F = c.read(data_mesh("bunny_npm"))
    m = trimesh.Trimesh(V, F, process=False)
    d = c.decimate(m, faces=500)
    ref = c.decimate(V, F, faces=500)
    assert np.array_equal(d.faces, ref.faces) and np.array_equal(d.vertices, ref.vertices)
    out = trimesh.Trimesh(d.vertices, d.faces, process=False)
    assert out.is_watertight and out.is_winding_consistent
    assert out.euler_number == m.euler_number == 2
    assert len(out.faces) <= 500


# --------------------------------------------------------------------- bad arguments

OCT_V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                 dtype=np.float64)
OCT_F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
                  [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])


@pytest.mark.parametrize("bad", [-1, 6, 2**32, 2**40, -2**63])
@pytest.mark.parametrize("dtype", [np.int64, list])
def test_locked_out_of_range_is_located(bad, dtype):
    lock = [0, 3, bad, 1]
    lock = lock if dtype is list else np.array(lock, dtype=dtype)
    with pytest.raises(c.MeshError) as e:
        c.decimate(OCT_V, OCT_F, locked=lock)
    assert isinstance(e.value, ValueError)
    assert e.value.kind == "vertex_out_of_range"
    assert e.value.location == {"locked": 2, "vertex": bad}
    assert "locked[2]" in str(e.value)


def test_locked_unsigned_beyond_the_vertices():
    with pytest.raises(c.MeshError) as e:
        c.decimate(OCT_V, OCT_F, locked=np.array([2**64 - 1], dtype=np.uint64))
    assert e.value.location == {"locked": 0, "vertex": 2**64 - 1}


@pytest.mark.parametrize("kwargs", [
    {"max_error": 0.1, "max_error_rel": 0.1},
    {"faces": -1},
    {"faces": 2.5},
    {"faces": True},
    {"keep": -0.1},
    {"keep": 1.5},
    {"keep": np.nan},
    {"max_error": -1.0},
    {"max_error": np.inf},
    {"max_error_rel": np.nan},
    {"max_error_rel": -0.5},
    {"placement": "quadric"},
    {"schedule": "fast"},
    {"locked": [0.5, 1.0]},
    {"locked": [True, False]},
    {"locked": [[0, 1], [2, 3]]},
    {"locked": ["a"]},
], ids=lambda k: ",".join(f"{a}={b!r}" for a, b in k.items()))
def test_bad_options_raise_value_error(kwargs):
    with pytest.raises(ValueError):
        c.decimate(OCT_V, OCT_F, **kwargs)


def test_bad_meshes_raise_located_errors():
    with pytest.raises(ValueError):
        c.decimate(None, OCT_F, keep=0.5)  # decimation needs positions
    with pytest.raises(c.MeshError) as e:
        c.decimate(np.zeros((6, 3)), OCT_F)
    assert e.value.kind == "no_coordinates"
    with pytest.raises(c.MeshError) as e:
        c.decimate(OCT_V, np.vstack([OCT_F, OCT_F[2:3]]))
    assert e.value.kind == "duplicate_face" and e.value.location == {"face": 8, "first": 2}
    with pytest.raises(TypeError):
        c.decimate(OCT_V)


# ----------------------------------------------------------------- the command line

def cli_has_decimate(cli):
    return cli("decimate", "--help", check=False).returncode == 0


# Genus 0 with a target, 10 components with endpoint placement, genus 3 with an error
# cap, a surface with boundary (the open bunny) locked, genus 5 without the guard.
CLI_CASES = [
    ("bunny_npm", ["--keep", 0.2], {"keep": 0.2}),
    ("box_stl", ["--faces", 3000, "--placement", "endpoint"],
     {"faces": 3000, "placement": "endpoint"}),
    ("high_genus_3", ["--max-error-rel", 0.005], {"max_error_rel": 0.005}),
    ("bunny_open", ["--keep", 0.1, "--lock-boundary", "--lock", "5,900,17", "--max-error",
                    0.2], {"keep": 0.1, "lock_boundary": True, "locked": [5, 900, 17],
                           "max_error": 0.2}),
    ("plate_holes_stl", ["--allow-foldover", "--placement", "midpoint"],
     {"guard": False, "placement": "midpoint"}),
    # The pass schedule: a target, then a cap with locks on a surface with boundary.
    ("high_genus_3", ["--keep", 0.1, "--schedule", "passes"],
     {"keep": 0.1, "schedule": "passes"}),
    ("bunny_open", ["--schedule", "passes", "--max-error-rel", 0.004, "--lock", "3,77"],
     {"schedule": "passes", "max_error_rel": 0.004, "locked": [3, 77]}),
]


@pytest.mark.parametrize("name,args,kwargs", CLI_CASES, ids=[k[0] for k in CLI_CASES])
def test_decimate_equals_the_cli(name, args, kwargs, cli, tmp_path, mesh_file):
    if not cli_has_decimate(cli):
        pytest.skip("the command line has no `decimate` command yet")
    src = mesh_file(name)
    out, maps = tmp_path / "out.off", tmp_path / "maps.json"
    theirs = json.loads(cli("decimate", src, *args, "-o", out, "--maps", maps,
                            "--json").stdout)
    V, F = c.read(src)
    d = c.decimate(V, F, **kwargs)
    check(V, F, d, locked=kwargs.get("locked", ()),
          lock_boundary=kwargs.get("lock_boundary", False))
    V2, F2 = c.read(out)
    assert np.array_equal(d.faces, F2)
    assert np.allclose(d.vertices, V2, rtol=0, atol=1e-9 * np.abs(V).max())
    m = json.loads(maps.read_text())
    assert np.array_equal(d.vertex_map, m["vertex_map"])
    assert np.array_equal(d.face_origin, m["face_origin"])
    assert d.collapse_map.tolist() == [-1 if o is None else o for o in m["collapse_map"]]
    # Every key of the report but its files and timings, with the same values.
    io = {"file", "output", "maps", "welded_vertices"}
    for k in theirs:
        if k not in io and not k.startswith("seconds"):
            assert k in d.stats, k
    for k, v in d.stats.items():
        if k == "seconds":
            continue
        if k == "component_list":
            assert v == theirs[k]
        elif isinstance(v, float):
            assert v == pytest.approx(theirs[k], rel=1e-12, abs=1e-300), k
        else:
            assert v == theirs[k], k
