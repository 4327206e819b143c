"""Run one contractible task over many mesh files on a Dask cluster: the route for
datasets that outgrow one machine.

    python dask_batch.py FILE... --task reduce [--workers 2 | --scheduler tcp://HOST:8786]
                         [--algo rs] [--seed 0] [--eps-rel 0.01] [-o results.jsonl]

Each file becomes one task of a ``dask.bag`` (one partition per file, so a slow mesh never
holds up a batch of quick ones). A worker reads the file with the package, runs the task and
returns one JSON-ready dict per file, in the order the files were given:

    {"file": ..., "task": ..., "ok": true,  "result": {<the statistics of the task>}}
    {"file": ..., "task": ..., "ok": false, "error": {"kind": "input", "exit_code": 2,
                                                      "message": ..., "problem": ...,
                                                      "location": {...}}}

the same lines as ``contractible batch FILE... --task TASK`` prints (``result`` holds the
task's statistics under the same keys: ``info``'s topology report, the statistics of
``reduce``/``quad``/``simplify``; ``error`` the same kind and exit code, plus the
``MeshError``'s ``problem`` key and ``location`` dict). A bad file never stops the run.

Without ``--scheduler`` a LocalCluster of ``--workers`` single-threaded processes runs on
this machine; with it, the bag runs on that cluster (every worker needs the package and
the files at the same paths).
"""

import argparse
import json
import sys
from typing import Any, Dict, List, Optional


def run_one(path: str, task: str, options: Dict[str, Any]) -> Dict[str, Any]:
    """One file's line (runs on a worker)."""
    import contractible as c

    line: Dict[str, Any] = {"file": path, "task": task}
    try:
        V, F = c.read(path)
        if task == "info":
            result = c.info(V, F)
        elif task == "reduce":
            # ε counted, as the command line does, so that the lines equal batch's.
            result = c.reduce(V, F, algo=options.get("algo", "rs"),
                              seed=options.get("seed", 0), count_retests=True).stats
        elif task == "quad":
            result = c.quad(V, F, algo=options.get("algo", "lrs"),
                            seed=options.get("seed", 0)).stats
        elif task == "simplify":
            result = c.simplify(V, F, eps_rel=options.get("eps_rel", 0.01)).stats
        else:
            raise ValueError(f"unknown task {task!r}")
        line["ok"] = True
        line["result"] = result
    except c.MeshError as e:
        line["ok"] = False
        line["error"] = {"kind": "input", "exit_code": 2, "message": e.message,
                         "problem": e.kind, "location": e.location}
    except (OSError, ValueError) as e:
        line["ok"] = False
        line["error"] = {"kind": "input", "exit_code": 2, "message": str(e)}
    return line


def run(files: List[str], task: str, options: Dict[str, Any], workers: int = 2,
        scheduler: Optional[str] = None) -> List[Dict[str, Any]]:
    """The lines of every file, in input order, computed on a Dask cluster."""
    import dask.bag as db
    from dask.distributed import Client, LocalCluster

    if not files:
        return []
    bag = db.from_sequence(files, npartitions=len(files)).map(run_one, task, options)
    if scheduler:
        with Client(scheduler) as client:
            return client.compute(bag).result()
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        return client.compute(bag).result()


def main(argv: Optional[List[str]] = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("files", nargs="+")
    p.add_argument("--task", choices=["info", "reduce", "quad", "simplify"], required=True)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--scheduler", help="address of an existing Dask scheduler")
    p.add_argument("--algo")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--eps-rel", type=float, default=0.01)
    p.add_argument("-o", "--output", help="write JSON lines here instead of stdout")
    a = p.parse_args(argv)
    options: Dict[str, Any] = {"seed": a.seed, "eps_rel": a.eps_rel}
    if a.algo:
        options["algo"] = a.algo
    lines = run(a.files, a.task, options, a.workers, a.scheduler)
    out = open(a.output, "w") if a.output else sys.stdout
    try:
        for line in lines:
            out.write(json.dumps(line) + "\n")
    finally:
        if a.output:
            out.close()
    return 0 if all(line["ok"] for line in lines) else 1


if __name__ == "__main__":
    sys.exit(main())
