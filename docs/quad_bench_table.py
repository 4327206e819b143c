#!/usr/bin/env python3
"""Turns the output of `cargo bench --bench quad` (divan) into the tri-quad tables of
docs/benchmarks.md: per input and algorithm the paper's columns (a) initial step,
(b) % paired, (c) unpaired, (d) completion, (e) total, with the tri-quad paper's
Table 4.4 values beside B0 (the paper's A1) and C0 (its B1), and the ratio of
petgraph's `maximum_matching` to each of our totals on the meshes.

(a), (d), (e) are divan medians of the `initial`, `completion` and `total` groups; (b)
and (c) are counters (deterministic for the input and seed), read from the output of
`cargo run --release -p contractible-tools --bin quad_profile -- INPUTS...` when given.

Usage: cargo bench --bench quad > quad.txt
       cargo run --release -p contractible-tools --bin quad_profile -- B0 B2 B4 C0 C2 C4 mesh:botijo ... > counters.txt
       python3 docs/quad_bench_table.py quad.txt [counters.txt]
"""
import re
import sys

UNIT = {"ns": 1e-9, "µs": 1e-6, "us": 1e-6, "ms": 1e-3, "s": 1.0}
ALGS = ["lrs", "ps", "sg", "matching"]
# Tri-quad paper, Table 4.4 (PS mean of 10 runs, LRS one run): (a, b, c, d, e).
PAPER = {
    ("B0", "ps"): (5.912, 99.9968, 136, 7.192, 13.104),
    ("B0", "lrs"): (11.986, 99.9999, 4, 0.193, 12.179),
    ("C0", "ps"): (5.859, 99.9944, 238, 14.538, 20.397),
    ("C0", "lrs"): (14.417, 99.0842, 38668, 1380.94, 1395.36),
}
PAPER_NAME = {"B0": "A1", "C0": "B1"}


def seconds(text):
    value, unit = text.split()
    return float(value) * UNIT[unit]


def parse_bench(path):
    group = alg = None
    med = {}  # (group, alg, input) -> seconds
    inputs = []
    for line in open(path, encoding="utf-8"):
        m = re.match(r"^[│├╰ ]*[├╰]─ (\S+)\s*(.*)$", line.rstrip("\n"))
        if not m:
            continue
        name, rest = m.group(1), m.group(2)
        cols = [c.strip() for c in rest.split("│")]
        data = len(cols) >= 3 and cols[2]
        if name in ("total", "initial", "completion") and not data:
            group = name
        elif name == "petgraph" and not data:
            group, alg = "petgraph", "petgraph"
        elif name in ALGS and not data:
            alg = name
        elif data:
            med[(group, alg, name)] = seconds(cols[2])
            if name not in inputs:
                inputs.append(name)
    return med, inputs


def parse_counters(path):
    out = {}  # (input, alg) -> (faces, unpaired)
    name = faces = None
    for line in open(path, encoding="utf-8"):
        m = re.match(r"^(\S+): (\d+) faces", line)
        if m:
            name, faces = m.group(1), int(m.group(2))
            continue
        m = re.match(r"^\s+(\w+)\s+initial .* unpaired\s+(\d+)", line)
        if m and name:
            out[(name, m.group(1))] = (faces, int(m.group(2)))
    return out


def fmt(s):
    if s is None:
        return "–"
    return f"{s:.3f} s" if s >= 1 else f"{s * 1e3:.1f} ms"


def main(bench, counters_path=None):
    med, inputs = parse_bench(bench)
    # The paper's bricks first, then the meshes, each in the order of the run.
    inputs = [i for i in inputs if not i.startswith("mesh:")] + [i for i in inputs if i.startswith("mesh:")]
    counters = parse_counters(counters_path) if counters_path else {}
    print("| input | alg | (a) initial | (b) % paired | (c) unpaired | (d) completion | (e) total "
          "| paper (a) | paper (b) | paper (c) | paper (d) | paper (e) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name in inputs:
        for alg in ALGS:
            e = med.get(("total", alg, name))
            if e is None:
                continue
            a = med.get(("initial", alg, name))
            d = med.get(("completion", alg, name))
            if alg == "matching":
                a, d = 0.0, e
            b = c = "–"
            if (name, alg) in counters:
                faces, unpaired = counters[(name, alg)]
                c = f"{unpaired:,}"
                b = f"{100.0 * (faces - unpaired) / faces:.4f}"
            p = PAPER.get((name, alg))
            ps = (" | ".join([f"{p[0]} s", f"{p[1]}", f"{p[2]:,}", f"{p[3]} s", f"{p[4]} s"])
                  if p else "– | – | – | – | –")
            label = f"{name} (paper {PAPER_NAME[name]})" if name in PAPER_NAME else name
            print(f"| {label} | {alg.upper() if alg != 'matching' else 'matching'} | {fmt(a)} | {b} | {c} "
                  f"| {fmt(d)} | {fmt(e)} | {ps} |")
    print()
    print("| mesh | petgraph (dual build + maximum_matching) | LRS total | PS total | SG total | matching total "
          "| petgraph / LRS | petgraph / PS |")
    print("|---|---|---|---|---|---|---|---|")
    for name in inputs:
        pg = med.get(("petgraph", "petgraph", name))
        if pg is None:
            continue
        tot = {alg: med.get(("total", alg, name)) for alg in ALGS}
        r = lambda x: f"{pg / x:.0f}×" if x else "–"
        print(f"| {name} | {fmt(pg)} | {fmt(tot['lrs'])} | {fmt(tot['ps'])} | {fmt(tot['sg'])} "
              f"| {fmt(tot['matching'])} | {r(tot['lrs'])} | {r(tot['ps'])} |")


if __name__ == "__main__":
    main(*sys.argv[1:3])
