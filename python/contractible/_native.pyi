# Type stubs of the native module (python/src/lib.rs). The public API is in __init__.py.
from os import PathLike
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

_F64 = npt.NDArray[np.float64]
_I64 = npt.NDArray[np.int64]
# What the functions read in place (C-contiguous); the wrapper converts anything else.
_Coords = Union[npt.NDArray[np.float64], npt.NDArray[np.float32]]
_Indices = Union[npt.NDArray[np.int64], npt.NDArray[np.int32], npt.NDArray[np.uint32]]
_Path = Union[str, PathLike[str]]

class History:
    def __len__(self) -> int: ...
    def records(self) -> _I64: ...
    def contractions(self) -> _I64: ...
    def expand(self, steps: Optional[int] = None) -> _I64: ...

def read(path: _Path) -> Tuple[Optional[_F64], _I64, int]: ...
def write(path: _Path, vertices: Optional[_Coords], faces: _Indices,
          vertex_count: Optional[int] = None) -> None: ...
def info(vertices: Optional[_Coords], faces: _Indices,
         vertex_count: Optional[int] = None) -> Dict[str, Any]: ...
def reduce(vertices: Optional[_Coords], faces: _Indices, algo: str = "rs", seed: int = 0,
           vertex_count: Optional[int] = None,
           count_retests: bool = False, parallel: bool = False) -> Dict[str, Any]: ...
def quad(vertices: Optional[_Coords], faces: _Indices, algo: str = "lrs", seed: int = 0,
         vertex_count: Optional[int] = None, parallel: bool = False) -> Dict[str, Any]: ...
def simplify(vertices: Optional[_Coords], faces: _Indices, eps: float, relative: bool = False,
             mode: str = "nested", side: str = "count", position: str = "midpoint",
             guard: bool = True, parallel: bool = False) -> Dict[str, Any]: ...
def decimate(vertices: Optional[_Coords], faces: _Indices, target_faces: Optional[int] = None,
             keep: Optional[float] = None, max_error: Optional[float] = None,
             relative: bool = False, placement: str = "optimal", guard: bool = True,
             lock_boundary: bool = False,
             locked: Optional[npt.NDArray[np.uint32]] = None,
             schedule: str = "exact") -> Dict[str, Any]: ...
def check(task: str, vertices: Optional[_Coords], faces: _Indices,
          vertex_count: Optional[int], out_vertices: Optional[_Coords],
          out_faces: _Indices, out_vertex_count: Optional[int],
          eps: Optional[float] = None, relative: bool = False,
          position: str = "midpoint", guard: bool = True,
          triangles: Optional[_Indices] = None,
          pairs: Optional[_Indices] = None,
          target_faces: Optional[int] = None, keep: Optional[float] = None,
          placement: str = "optimal", lock_boundary: bool = False,
          locked: Optional[List[int]] = None, vertex_map: Optional[List[int]] = None,
          collapse_map: Optional[List[int]] = None,
          face_origin: Optional[List[int]] = None,
          history: Optional[_Indices] = None) -> Dict[str, Any]: ...
