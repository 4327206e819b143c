"""The conformance protocol (spec/conformance.md) answered with the Python package:
contractible conformance --impl 'python python/examples/conformance_adapter.py'"""
import json, sys
import numpy as np
import contractible as c

case = json.load(sys.stdin)
V = None if case["positions"] is None else np.array(case["positions"], dtype=float)
F = np.array(case["faces"], dtype=np.int64).reshape(-1, 3)
o, n = case["options"], case["vertex_count"]
try:
    if case["task"] == "reduce":
        r = c.reduce(V, F, algo=o.get("algorithm", "rs"), seed=o.get("seed", 0))
        answer = {"faces": r.vertex_map[r.faces].tolist(), "positions": None}
    elif case["task"] == "quad":
        q = c.quad(V, F, algo=o.get("algorithm", "lrs"), seed=o.get("seed", 0))
        answer = {"faces": q.quads.tolist(), "triangles": q.triangles.tolist(),
                  "pairs": q.pairs.tolist(), "positions": None}
    else:
        s = c.simplify(V, F, o.get("eps"), eps_rel=o.get("eps_rel"), mode=o.get("mode", "nested"),
                       side=o.get("side", "count"), position=o.get("position", "midpoint"),
                       guard=o.get("guard", True))
        answer = {"faces": s.faces.tolist(), "positions": s.vertices.tolist()}
except (c.MeshError, ValueError) as e:
    print(json.dumps({"error": {"kind": getattr(e, "kind", "bad_option"), "message": str(e)}}))
    sys.exit(2)
print(json.dumps(answer))
