"""python/examples/dask_batch.py on a local cluster of 2 worker processes: one line per
file, in order, equal to `contractible batch`'s lines for the same files; bad files give
located errors and never stop the run."""

import importlib.util
import json
from pathlib import Path

from conftest import DATA, data_mesh, manifest

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "dask_batch.py"
# Genus 1, 5 and 3 (one component each) and 10 components.
NAMES = ["letter", "plate_holes_stl", "high_genus_3", "box_stl"]
FILES = [data_mesh(n) for n in NAMES]
TIMING = {"seconds", "initial_seconds", "completion_seconds", "total_seconds"}


def load_example():
    spec = importlib.util.spec_from_file_location("dask_batch", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def same_statistics(mine, theirs):
    """Every non-timing key of the example's result equals the CLI's JSON."""
    for k, v in mine.items():
        if k in TIMING or k not in theirs:
            continue
        if isinstance(v, list):
            for a, b in zip(v, theirs[k]):
                same_statistics(a, b) if isinstance(a, dict) else None
            assert len(v) == len(theirs[k]), k
        else:
            assert v == theirs[k], k


def test_dask_batch_reduce_and_quad_equal_contractible_batch(cli, mesh_file):
    ex = load_example()
    # Open (a real mesh missing a face; the hyperboloid cut by its box) and non-manifold.
    bad = [mesh_file("bunny_open"), mesh_file("hyperboloid"),
           data_mesh("shared_edge_stl", "invalid")]
    files = [str(f) for f in FILES + bad]
    for task, extra in [("reduce", ["--algo", "brute", "--seed", "4"]), ("quad", [])]:
        options = {"algo": "brute", "seed": 4} if task == "reduce" else {}
        lines = ex.run(files, task, options, workers=2)
        assert [line["file"] for line in lines] == files
        r = cli("--quiet", "batch", *files, "--task", task, "--", *extra, check=False)
        assert r.returncode == 1  # the bad files
        theirs = [json.loads(s) for s in r.stdout.splitlines()]
        # batch sorts its inputs; compare file by file.
        by_file = {t["file"]: t for t in theirs}
        assert sorted(by_file) == sorted(files)
        for line in lines:
            t = by_file[line["file"]]
            assert line["ok"] == t["ok"], (line, t)
            if line["ok"]:
                same_statistics(line["result"], t["result"])
            else:
                err, their = line["error"], t["error"]
                assert (err["kind"], err["exit_code"]) == (their["kind"], their["exit_code"])
                assert err["problem"] in {"boundary_edge", "non_manifold_edge",
                                          "pinched_vertex", "multiple_edges"}, err
                assert err["location"], err
                # The CLI names the same problem (its message adds the file name and
                # the file's line numbers).
                what = err["message"].split(":")[0].split(" (")[0]
                assert what.split()[0] in their["message"], (what, their["message"])
        assert sum(not line["ok"] for line in lines) == len(bad)


def test_dask_batch_main_writes_json_lines(tmp_path):
    ex = load_example()
    out = tmp_path / "info.jsonl"
    status = ex.main([str(f) for f in FILES] + ["--task", "info", "-o", str(out)])
    assert status == 0
    lines = [json.loads(s) for s in out.read_text().splitlines()]
    faces = {m["name"]: int(m["F"]) for m in manifest(DATA)}
    assert [line["result"]["faces"] for line in lines] == [faces[n] for n in NAMES]
