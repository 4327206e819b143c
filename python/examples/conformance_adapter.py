"""Answers one conformance case (spec/conformance.md) with the Python package."""
import json, sys
import numpy as np
import contractible as c

case = json.load(sys.stdin)
V = None if case["positions"] is None else np.array(case["positions"], dtype=float)
F = np.array(case["faces"], dtype=np.int64).reshape(-1, 3)
o, task = case["options"], case["task"]
try:
    if task == "reduce":
        r = c.reduce(V, F, algo=o.get("algorithm", "rs"), seed=o.get("seed", 0))
        answer = {"faces": r.vertex_map[r.faces].tolist(), "positions": None,
                  "history": r.history.contractions().tolist()}
    elif task == "quad":
        q = c.quad(V, F, algo=o.get("algorithm", "lrs"), seed=o.get("seed", 0))
        answer = {"faces": q.quads.tolist(), "triangles": q.triangles.tolist(),
                  "pairs": q.pairs.tolist(), "positions": None}
    elif task == "simplify":
        s = c.simplify(V, F, o.get("eps"), **{k: o[k] for k in o if k != "eps"})
        answer = {"faces": s.faces.tolist(), "positions": s.vertices.tolist()}
    else:
        d = c.decimate(V, F, **o)
        answer = {"faces": d.faces.tolist(), "positions": d.vertices.tolist(),
                  "vertex_map": d.vertex_map.tolist(), "face_origin": d.face_origin.tolist(),
                  "collapse_map": [None if x < 0 else x for x in d.collapse_map.tolist()]}
except (c.MeshError, ValueError, TypeError) as e:
    print(json.dumps({"error": {"kind": getattr(e, "kind", "bad_option"), "message": str(e)}}))
    sys.exit(2)
print(json.dumps(answer))
