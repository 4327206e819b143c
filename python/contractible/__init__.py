"""contractible: topology-preserving edge contraction on triangulated surfaces.

NumPy in, NumPy out. ``V`` is a real array of shape (n, 3) (optional where the
algorithm is combinatorial), ``F`` an integer array of shape (m, 3). C-contiguous
float64 or float32 ``V`` and int64, int32 or uint32 ``F`` are read where they are, with
no converted copy; other dtypes and layouts are converted first. Any object with
``.vertices`` and ``.faces`` (a ``trimesh.Trimesh``, say) is accepted in place of
``(V, F)``.

Functions:
    read(path) -> (V, F)                    OFF, OBJ, PLY, STL (optionally .gz)
    write(path, V, F)                       triangles (m, 3) or quads (m, 4)
    info(V, F) -> dict                      topology per component (boundary allowed)
    reduce(V, F, algo="rs", seed=0)         irreducible triangulation  -> Reduced
    quad(V, F, algo="lrs", seed=0)          perfect triangle pairing   -> Quadrangulated
    simplify(V, F, eps, mode="nested")      short-edge simplification  -> Simplified
    decimate(V, F, faces=n | keep=f)        quadric-error decimation   -> Decimated
    check(task, V, F, V_out, F_out)         verdict on any implementation's output -> dict

Every problem of a mesh raises :class:`MeshError` (a ``ValueError``) with ``kind`` and
``location``; a wrong array shape or dtype, an unknown algorithm name or a bad ``eps``
raises ``ValueError``; a file that cannot be opened or written raises ``OSError``. The
functions are a thin layer over the library's task calls and release the GIL while
they work. Results are checked independently before they are returned, deterministic
for a given input and seed, and equal to the command line's
(``contractible reduce|quad|simplify|decimate``) for the same mesh, statistics included.
"""

import operator
from dataclasses import dataclass, field
from os import PathLike
from typing import Any, Dict, Optional, Tuple, Union

import numpy as np

from . import _native
from ._errors import MeshError

__all__ = [
    "MeshError",
    "Reduced",
    "Quadrangulated",
    "Simplified",
    "Decimated",
    "read",
    "write",
    "info",
    "reduce",
    "quad",
    "simplify",
    "decimate",
    "check",
]

__version__ = _native.__version__


# Index and coordinate dtypes the native functions read as they are (native byte order).
_INDEX_DTYPES = (np.dtype(np.int64), np.dtype(np.int32), np.dtype(np.uint32))
_REAL_DTYPES = (np.dtype(np.float64), np.dtype(np.float32))


def _faces(F: Any, corners: Tuple[int, ...] = (3,)) -> np.ndarray:
    """F as a C-contiguous (m, k) array of int64, int32 or uint32 (the caller's array
    itself when it is one already, else an int64 copy); ValueError for anything else."""
    a = np.asarray(F)
    if a.dtype == np.bool_ or not np.issubdtype(a.dtype, np.integer):
        raise ValueError(f"faces must be an integer array, got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] not in corners:
        want = " or ".join(f"(m, {k})" for k in corners)
        raise ValueError(f"faces must have shape {want}, got {a.shape}")
    if a.dtype == np.uint64 and a.size and int(a.max()) > np.iinfo(np.int64).max:
        bad = int(np.argmax(a.max(axis=1) > np.iinfo(np.int64).max))
        raise MeshError(f"face {bad}: vertex index out of range", "vertex_out_of_range",
                        {"face": bad})
    if a.dtype in _INDEX_DTYPES:
        return np.ascontiguousarray(a)
    return np.ascontiguousarray(a, dtype=np.int64)


def _vertices(V: Any) -> Optional[np.ndarray]:
    """V as a C-contiguous (n, 3) array of float64 or float32 (the caller's array itself
    when it is one already, else a float64 copy), or None; ValueError for anything else."""
    if V is None:
        return None
    a = np.asarray(V)
    if not (np.issubdtype(a.dtype, np.floating) or np.issubdtype(a.dtype, np.integer)):
        raise ValueError(f"vertices must be a real array, got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"vertices must have shape (n, 3), got {a.shape}")
    if a.dtype in _REAL_DTYPES:
        return np.ascontiguousarray(a)
    return np.ascontiguousarray(a, dtype=np.float64)


def _vf(V: Any, F: Any) -> Tuple[Optional[np.ndarray], Any]:
    """(V, F) from either two arrays or one mesh object with .vertices and .faces."""
    if F is None and hasattr(V, "vertices") and hasattr(V, "faces"):
        return V.vertices, V.faces
    if F is None:
        raise TypeError("pass (V, F) or one object with .vertices and .faces")
    return V, F


@dataclass
class Reduced:
    """An irreducible triangulation of each component (``reduce``).

    Attributes:
        vertices: positions of the surviving vertices (None without input positions).
        faces: (k, 3) faces over the survivors, numbered 0.. in input order.
        vertex_map: (n_out,) the input index of each surviving vertex.
        stats: the command line's ``reduce --json`` statistics (totals and a
            ``component_list``).
        history: the contractions; ``history.records()`` is a (c, 5) array of
            ``component, u, v, x, y`` (v contracted into u, {x, y} the edge's link;
            input vertex ids), ``history.contractions()`` its (c, 2) columns ``u, v``
            (what ``check("reduce", ..., history=)`` replays) and ``history.expand(steps)`` the faces (input ids) after
            undoing the last ``steps`` contractions by vertex splits (all: the input).
    """

    vertices: Optional[np.ndarray]
    faces: np.ndarray
    vertex_map: np.ndarray
    stats: Dict[str, Any]
    history: Any = field(repr=False)


@dataclass
class Quadrangulated:
    """A perfect pairing of the triangles (``quad``).

    Attributes:
        vertices: the input positions (same vertex set; None without positions).
        quads: (m/2, 4) quads, input vertex ids.
        triangles: (m, 3) the paired triangulation K: row i is input face i (after the
            edge flips of ``lrs``; the input itself for the other algorithms).
        pairs: (m/2, 2) rows of ``triangles`` paired into one quad each.
        stats: the command line's ``quad --json`` statistics.
    """

    vertices: Optional[np.ndarray]
    quads: np.ndarray
    triangles: np.ndarray
    pairs: np.ndarray
    stats: Dict[str, Any]

    @property
    def faces(self) -> np.ndarray:
        """The quads (so that the result is a ``(vertices, faces)`` mesh)."""
        return self.quads


@dataclass
class Simplified:
    """The mesh with every edge shorter than ε contracted where the surface allows.

    Attributes:
        vertices: (k, 3) positions.
        faces: (f, 3) faces over them.
        stats: the command line's ``simplify --json`` statistics (``eps`` absolute,
            ``eps_rel`` when relative).
    """

    vertices: np.ndarray
    faces: np.ndarray
    stats: Dict[str, Any]


@dataclass
class Decimated:
    """The mesh after quadric-error edge collapses, each passing the link condition: every
    component has the input's topology (``decimate``).

    Attributes:
        vertices: (k, 3) float64 positions of the surviving vertices, in input order.
        faces: (f, 3) int64 faces over them: the surviving input faces in input order,
            each with its input corner order (so its orientation).
        vertex_map: (k,) int64, per output vertex the input vertex that survives as it
            (increasing).
        collapse_map: (n,) int64, per input vertex the output vertex it went into; -1
            for an input vertex no face uses. ``faces == collapse_map[F[face_origin]]``.
        face_origin: (f,) int64, per output face the input face it descends from
            (increasing).
        stats: the command line's ``decimate --json`` statistics: ``faces_in``,
            ``faces_out``, ``vertices_in``, ``vertices_out``, ``components``,
            ``boundary_loops``, ``target_faces``, ``max_error_cap``, ``stopped``
            (``"target"``, ``"error"`` or ``"blocked"``), ``collapses``, ``max_error``,
            ``passes`` (0 under the exact schedule), ``refused`` and ``remaining``
            (dicts of counts by guard: ``lock``,
            ``boundary``, ``error``, ``link_condition``, ``foldover``),
            ``component_list``, ``seconds``; the options: ``targets`` (``faces``,
            ``keep``, ``max_error``, ``max_error_rel`` as given, None when not),
            ``placement``, ``schedule``, ``guard``, ``lock_boundary``, ``locked``
            (sorted, without repeats); and ``bbox_diagonal``, ``verified``, ``dropped_vertices``.
    """

    vertices: np.ndarray
    faces: np.ndarray
    vertex_map: np.ndarray
    collapse_map: np.ndarray
    face_origin: np.ndarray
    stats: Dict[str, Any]


def read(path: Union[str, "PathLike[str]"]) -> Tuple[Optional[np.ndarray], np.ndarray]:
    """Reads a triangle mesh (OFF, OBJ, PLY, STL; ``.gz`` allowed).

    Returns ``(V, F)``; ``V`` is None when the file has no coordinates. A malformed file
    raises :class:`MeshError` with ``location["line"]`` (text) or ``["byte_offset"]``.
    """
    V, F, _ = _native.read(str(path))
    return V, F


def write(path: Union[str, "PathLike[str]"], V: Any, F: Any = None) -> None:
    """Writes triangles (m, 3) or quads (m, 4); the format follows the extension
    (``.off``, ``.obj``, ``.ply``, ``.stl`` for triangles; ``.gz`` compresses). The file
    appears complete or not at all (written beside it, then renamed)."""
    V, F = _vf(V, F)
    _native.write(str(path), _vertices(V), _faces(F, (3, 4)))


def info(V: Any, F: Any = None) -> Dict[str, Any]:
    """Topology of every component, as ``contractible info --json`` reports it:
    V, E, F, χ, orientability, genus, boundary loops. Surfaces with boundary are allowed."""
    V, F = _vf(V, F)
    return _native.info(_vertices(V), _faces(F))


def reduce(V: Any, F: Any = None, algo: str = "rs", seed: int = 0,
           count_retests: bool = False, parallel: bool = False) -> Reduced:
    """An irreducible triangulation (no edge contractible under the link condition) of
    every component, by ``rs`` (Ramaswami–Siqueira, default), ``schipper`` or ``brute``
    (randomised by ``seed``). Closed surfaces only (orientable or not); vertex positions
    are optional and carried along.

    ``count_retests=True`` counts ε (``edges_tested_more_than_once``, as the command
    line does); off by default, as in the Rust library, since it costs about a quarter
    of the reduction's time (ε is then 0).

    ``parallel=True`` reduces the components of the mesh on one thread per CPU; the
    result is the same (the GIL is released either way)."""
    V, F = _vf(V, F)
    d = _native.reduce(_vertices(V), _faces(F), algo, int(seed), None, bool(count_retests),
                       bool(parallel))
    return Reduced(d["vertices"], d["faces"], d["vertex_map"], d["stats"], d["history"])


def quad(V: Any, F: Any = None, algo: str = "lrs", seed: int = 0,
         parallel: bool = False) -> Quadrangulated:
    """A quadrangulation on the same vertices: a perfect pairing of edge-adjacent
    triangles by ``lrs`` (contraction/expansion with flips, default), ``ps``
    (Pulli–Segal), ``sg`` (simple greedy) or ``matching``, each completed by augmenting
    paths, or by Frink's reduction (``ds``: Diks–Stańczyk, dynamic connectivity and
    link–cut trees, O(F log² F); ``bbdl``: Biedl–Bose–Demaine–Lubiw, dynamic
    2-edge-connectivity, O(F² log F) in the worst case with this package's structure;
    ``frink-lct``: the link–cut cover-count strategy;
    ``ds-naive``: the quadratic reference, refused above 100,000 faces per component
    with a :class:`MeshError` of kind ``too_large``), perfect without completion. Closed
    surfaces only; positions optional. ``parallel=True`` pairs the components on one
    thread per CPU, with the same result."""
    V, F = _vf(V, F)
    d = _native.quad(_vertices(V), _faces(F), algo, int(seed), None, bool(parallel))
    return Quadrangulated(d["vertices"], d["quads"], d["triangles"], d["pairs"], d["stats"])


def simplify(V: Any, F: Any = None, eps: Optional[float] = None, *, eps_rel: Optional[float] = None,
             mode: str = "nested", side: str = "count", position: str = "midpoint",
             guard: bool = True, parallel: bool = False) -> Simplified:
    """Contracts every edge shorter than ``eps`` (absolute) or ``eps_rel`` (a fraction of
    the bounding-box diagonal) without changing the surface: closed surfaces and surfaces
    with boundary, orientable or not; every boundary loop is kept.

    ``mode``: ``nested`` (the paper's processEdge, default) or ``naive`` (skip edges that
    fail the link condition). ``side``: ``count``, ``path`` or ``euclidean``.
    ``position``: ``midpoint`` or ``quadric``. ``guard=False`` allows fold-overs.
    ``parallel=True`` simplifies the components of the mesh on one thread per CPU; the
    result is the same (the GIL is released either way).
    """
    V, F = _vf(V, F)
    if (eps is None) == (eps_rel is None):
        raise ValueError("give exactly one of eps and eps_rel")
    value = eps if eps is not None else eps_rel
    d = _native.simplify(_vertices(V), _faces(F), float(value), eps_rel is not None,
                         mode, side, position, bool(guard), bool(parallel))
    return Simplified(d["vertices"], d["faces"], d["stats"])


def _locked(locked: Any, vertex_count: Optional[int]) -> Optional[np.ndarray]:
    """The locked vertex ids as a C-contiguous uint32 array, or None; ValueError for an
    array that is not a 1-D list of integers, :class:`MeshError` (kind
    ``vertex_out_of_range``, located by ``locked`` index and ``vertex``) for an id that
    is negative or, given ``vertex_count``, not below it."""
    if locked is None:
        return None
    a = np.asarray(locked)
    if a.size == 0:
        return np.zeros(0, dtype=np.uint32)
    if a.dtype == np.bool_ or not np.issubdtype(a.dtype, np.integer):
        raise ValueError(f"locked must be integer vertex indices, got dtype {a.dtype}")
    if a.ndim > 1:
        raise ValueError(f"locked must be a 1-D list of vertex indices, got shape {a.shape}")
    a = a.reshape(-1)
    bad = a < 0
    limit = vertex_count if vertex_count is not None else 2**32
    bad |= a >= limit
    if bad.any():
        i = int(np.argmax(bad))
        v = int(a[i])
        count = f" (vertex count {vertex_count})" if vertex_count is not None else ""
        raise MeshError(f"locked[{i}]: vertex index {v} out of range{count}",
                        "vertex_out_of_range", {"locked": i, "vertex": v})
    return np.ascontiguousarray(a, dtype=np.uint32)


def decimate(V: Any, F: Any = None, *, faces: Optional[int] = None,
             keep: Optional[float] = None, max_error: Optional[float] = None,
             max_error_rel: Optional[float] = None, placement: str = "optimal",
             guard: bool = True, lock_boundary: bool = False,
             locked: Any = None, schedule: str = "exact") -> Decimated:
    """Collapses edges, cheapest quadric error first, without changing the topology:
    every component of the output has the input's Euler characteristic, orientability
    and boundary loops, since every collapse passes the link condition (closed surfaces
    and surfaces with boundary, orientable or not, several components at once). Every
    output vertex is an input vertex that survived, every output face an input face
    with its corners renamed; the maps say which (see :class:`Decimated`).

    Targets combine; the run stops at the first reached, or when no edge can go:
    ``faces``, at most this many faces; ``keep``, at most ``ceil(keep × len(F))`` faces
    (a fraction in [0, 1]; with both, the larger count is the target); ``max_error``
    (absolute) or ``max_error_rel`` (a fraction of the bounding-box diagonal), no
    collapse whose error (the root mean square distance of the merged vertex from the
    planes of the input faces merged into it) exceeds the cap. With none, it goes as
    far as the guards allow. ``stats["stopped"]`` says why it stopped (``"target"``,
    ``"error"``, ``"blocked"``) and ``stats["remaining"]`` what refuses the edges left.

    ``placement``: ``optimal`` (the quadric's minimiser, default), ``midpoint``, or
    ``endpoint`` (every output position is an input position). ``guard=False`` allows
    collapses that turn a face by 90° or more or leave it without area.
    ``lock_boundary=True`` keeps every boundary vertex where it is; ``locked`` (input
    vertex ids, any integer array-like) survive at their input positions.
    ``schedule``: ``exact`` (every collapse is of the cheapest edge the guards allow,
    default) or ``passes`` (the fast option: passes of independent collapses over a
    sorted edge list, with a somewhat larger error; every guarantee above still holds).

    Deterministic, and the same as ``contractible decimate`` for the same mesh and
    options. A negative or out-of-range ``locked`` id raises :class:`MeshError` (kind
    ``vertex_out_of_range``, ``location`` ``{"locked": i, "vertex": v}``); both
    ``max_error`` and ``max_error_rel``, a negative ``faces``, ``keep`` outside [0, 1]
    or a cap that is negative or not finite raise ``ValueError``.
    """
    V, F = _vf(V, F)
    if max_error is not None and max_error_rel is not None:
        raise ValueError("give at most one of max_error and max_error_rel")
    target = None
    if faces is not None:
        try:
            if isinstance(faces, (bool, np.bool_)):
                raise TypeError
            target = operator.index(faces)
        except TypeError:
            raise ValueError(f"faces must be an integer face count, got {faces!r}") from None
        if target < 0:
            raise ValueError(f"faces = {target}: the face target must be >= 0")
        # A target above any face count keeps every face; the native call takes a usize.
        target = min(target, 2**63 - 1)
    cap = max_error if max_error is not None else max_error_rel
    Va, Fa = _vertices(V), _faces(F)
    d = _native.decimate(Va, Fa, target, None if keep is None else float(keep),
                         None if cap is None else float(cap), max_error_rel is not None,
                         placement, bool(guard), bool(lock_boundary),
                         _locked(locked, None if Va is None else len(Va)), schedule)
    return Decimated(d["vertices"], d["faces"], d["vertex_map"], d["collapse_map"],
                     d["face_origin"], d["stats"])


def check(task: str, V: Any, F: Any, V_out: Any, F_out: Any, *,
          vertex_count: Optional[int] = None,
          out_vertex_count: Optional[int] = None,
          eps: Optional[float] = None, eps_rel: Optional[float] = None,
          position: str = "midpoint", guard: bool = True,
          triangles: Any = None, pairs: Any = None,
          faces: Optional[int] = None, keep: Optional[float] = None,
          max_error: Optional[float] = None, max_error_rel: Optional[float] = None,
          placement: str = "optimal", lock_boundary: bool = False, locked: Any = None,
          vertex_map: Any = None, collapse_map: Any = None,
          face_origin: Any = None, history: Any = None) -> Dict[str, Any]:
    """Judges ``(V_out, F_out)``, made by any implementation, as an output of ``task``
    on ``(V, F)``, by its properties (not its bytes); the command line's
    ``contractible check TASK INPUT OUTPUT --json`` without the file names.

    ``task`` is ``"reduce"``: the output must be a closed 2-manifold on input vertices
    (by index when it keeps the input's vertex list, else by exact position) with the
    input's positions, one component per input component of the same surface, and
    irreducible. Either ``V`` may be None (combinatorial meshes; then the counts say
    how many vertices there are, by default one more than the largest index). With
    ``history`` (``(k, 2)``, ``u, v`` per contraction, input indices, oldest first, as
    ``reduce(...).history.contractions()`` gives them), the contractions are replayed on
    the input: each must pass the link condition on the surface the earlier ones left
    (``invalid_history``), and the replay must end at the output's faces
    (``history_mismatch``).

    Or ``"simplify"``, with the run's ``eps`` (absolute) or ``eps_rel`` (a fraction of
    the bounding-box diagonal of the vertices the input's faces use), and its
    ``position`` and ``guard`` (:func:`simplify`'s names and defaults): the output must
    be a 2-manifold (boundary allowed) with finite positions, of the input's surface per
    component (χ, orientability, boundary loops; by index when it keeps the input's
    vertex list, else as multisets of surface types), and no edge strictly shorter than
    ε may pass the link condition of the surface with boundary unless the guard refuses
    it (recomputed at the midpoint; with ``position="quadric"`` and the guard on, no
    short edge is judged).

    Or ``"quad"``, with ``F_out`` the quads ``(m, 4)`` and, from a conversion that
    flips edges, the ``triangles`` K it paired (``(t, 3)``, in the output's indices)
    and optionally the ``pairs`` (``(m, 2)``, rows of K, of ``F`` without
    ``triangles``), as :func:`quadrangulate` returns them: every quad must be two
    triangles of K split along one of its diagonals (the stated pair, if given), every
    triangle in exactly one quad, and K a closed surface on the input's vertices of
    its surface per component.

    Or ``"decimate"``, with the run's target and options (:func:`decimate`'s names:
    ``faces``, ``keep``, ``max_error`` or ``max_error_rel``, ``placement``, ``guard``,
    ``lock_boundary``, ``locked``) and, if known, its maps (``vertex_map``,
    ``collapse_map`` with -1 for an unused vertex, ``face_origin``, as :func:`decimate`
    returns them): the output must be a surface of the input's type per component with
    finite positions, the maps consistent with each other and the faces, locked vertices
    kept, every position an input position with ``placement="endpoint"``, and a face
    count the target explains (at most one collapse below it; above it, for a run with
    ``guard=False`` and no cap, no unlocked edge passing the link condition).

    Returns a dict: ``task``, ``passed`` (bool), ``counts`` (per failure kind, every
    reason found) and ``failures`` (at most 20 of a kind: ``kind``, ``message`` and,
    where known, ``face``, ``edge``, ``vertex``, ``component``). Raises
    :class:`MeshError` when the input is not one the task accepts (for ``reduce``: not a
    closed surface; for ``simplify``: no surface), ``ValueError`` for an unknown task, a
    bad array, a missing, doubled or bad ε, ε given for another task than ``simplify``,
    ``triangles`` or ``pairs`` for another than ``quad``, or no input positions for
    ``simplify``.
    """
    task = str(task)
    Va, Fa = _vertices(V), _faces(F)
    Vb, Fb = _vertices(V_out), _faces(F_out, (4,) if task == "quad" else (3,))
    if task != "reduce" and history is not None:
        raise ValueError(f"check: history is an option of \"reduce\", not {task!r}")
    if task != "quad" and (triangles is not None or pairs is not None):
        raise ValueError(f"check: triangles and pairs are options of \"quad\", not {task!r}")
    decimate_options = dict(faces=faces, keep=keep, max_error=max_error,
                            max_error_rel=max_error_rel, locked=locked, vertex_map=vertex_map,
                            collapse_map=collapse_map, face_origin=face_origin)
    given = [k for k, v in decimate_options.items() if v is not None]
    given += [k for k, on in (("placement", placement != "optimal"),
                              ("lock_boundary", bool(lock_boundary))) if on]
    if task != "decimate" and given:
        raise ValueError(f"check: {given[0]} is an option of \"decimate\", not {task!r}")
    if task == "decimate":
        if eps is not None or eps_rel is not None:
            raise ValueError("check: eps and eps_rel are options of \"simplify\", not 'decimate'")
        if max_error is not None and max_error_rel is not None:
            raise ValueError("check: give at most one of max_error and max_error_rel")
        cap = max_error if max_error is not None else max_error_rel
        ints = lambda a: None if a is None else [int(x) for x in np.asarray(a).reshape(-1)]
        return _native.check(task, Va, Fa, vertex_count, Vb, Fb, out_vertex_count,
                             None if cap is None else float(cap), max_error_rel is not None,
                             "midpoint", bool(guard), None, None,
                             None if faces is None else int(faces),
                             None if keep is None else float(keep), str(placement),
                             bool(lock_boundary), ints(locked), ints(vertex_map),
                             ints(collapse_map), ints(face_origin))
    if task != "simplify":
        if eps is not None or eps_rel is not None:
            raise ValueError(f"check: eps and eps_rel are options of \"simplify\", not {task!r}")
        if task == "quad":
            K = None if triangles is None else _faces(triangles)
            P = None
            if pairs is not None:
                if np.asarray(pairs).ndim != 2 or np.asarray(pairs).shape[1] != 2:
                    raise ValueError(f"pairs must have shape (m, 2), got {np.asarray(pairs).shape}")
                P = _faces(pairs, (2,))
            return _native.check(task, Va, Fa, vertex_count, Vb, Fb, out_vertex_count,
                                 triangles=K, pairs=P)
        if history is not None:
            H = np.asarray(history)
            if H.size == 0:
                H = H.reshape(0, 2).astype(np.int64)
            if H.ndim != 2 or H.shape[1] != 2:
                raise ValueError(f"history must have shape (k, 2), got {H.shape}")
            return _native.check(task, Va, Fa, vertex_count, Vb, Fb, out_vertex_count,
                                 history=_faces(H, (2,)))
        return _native.check(task, Va, Fa, vertex_count, Vb, Fb, out_vertex_count)
    if (eps is None) == (eps_rel is None):
        raise ValueError("check: give exactly one of eps and eps_rel for \"simplify\"")
    value = eps if eps is not None else eps_rel
    return _native.check(task, Va, Fa, vertex_count, Vb, Fb, out_vertex_count,
                         float(value), eps_rel is not None, str(position), bool(guard))
