"""The exception raised for every problem of a mesh (kept apart so the native module can
raise it without importing the package's ``__init__``)."""

from typing import Dict, Optional


class MeshError(ValueError):
    """A mesh the library refuses, with what is wrong and where.

    Attributes:
        message: the library's message (the same text as the command line's error).
        kind: a stable key for the problem: ``"vertex_out_of_range"``,
            ``"non_finite_coordinate"``, ``"degenerate_face"``, ``"duplicate_face"``,
            ``"boundary_edge"``, ``"non_manifold_edge"``, ``"multiple_edges"``,
            ``"pinched_vertex"``, ``"pinched_boundary_vertex"``,
            ``"vertex_degree_too_low"``, ``"empty"``, ``"too_large"`` (too many
            vertices, or a component too large for the algorithm),
            ``"no_coordinates"`` (every vertex at one point), ``"read"`` (a file that
            does not parse) ...: the library's ``Error::kind``.
        location: where, as a dict of 0-based indices: ``face``, ``vertex``, ``a`` and
            ``b`` (an edge's ends), ``first`` (the face a duplicate repeats),
            ``component`` (in the order of the smallest face index), ``count`` (a count
            too large), ``locked`` (the position of a bad id in ``decimate``'s
            ``locked``), or for files ``line`` (1-based, as editors count) or
            ``byte_offset``.
    """

    def __init__(self, message: str, kind: str = "invalid_mesh",
                 location: Optional[Dict[str, int]] = None) -> None:
        super().__init__(message)
        self.message = message
        self.kind = kind
        self.location = dict(location or {})

    def __str__(self) -> str:
        return self.message

    def __reduce__(self):
        # Picklable (process pools, Dask): rebuilt from the same three values.
        return (type(self), (self.message, self.kind, self.location))
