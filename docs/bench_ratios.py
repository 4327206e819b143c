#!/usr/bin/env python3
"""Turns the output of `cargo bench --bench irreducible` (divan) into the ratio tables of
docs/benchmarks.md: medians of RS, S and BF per input, t_S/t_RS and t_BF/t_RS, with the
RS paper's ratios (Tables 7, 9, 11) beside ours.

Usage: cargo bench --bench irreducible > bench.txt; python3 docs/bench_ratios.py bench.txt
"""
import re
import sys

# Paper, Tables 7, 9, 11: member -> (t_s/t_rs, t_bf/t_rs)
PAPER = {
    "B0": (3.56, 2.58), "B1": (3.45, 2.79), "B2": (3.46, 3.15), "B3": (3.90, 4.30),
    "B4": (3.32, 2.88), "B5": (3.96, 5.86), "B6": (7.37, 16.90), "B7": (11.51, 3.76),
    "B8": (10.81, 3.35), "B9": (12.28, 4.15),
    "C0": (4.44, 2.39), "C1": (2.11, 1.49), "C2": (1.82, 1.89), "C3": (1.29, 2.41),
    "C4": (2.00, 7.02), "C5": (2.05, 12.26), "C6": (3.41, 43.97), "C7": (2.61, 58.88),
    "D0": (4.69, 2.42), "D1": (4.44, 2.42), "D2": (4.22, 2.41), "D3": (4.14, 2.45),
    "D4": (4.02, 2.49), "D5": (3.86, 2.46), "D6": (3.80, 2.55), "D7": (3.82, 2.65),
    "D8": (3.70, 2.66), "D9": (3.80, 2.70),
}
UNIT = {"ns": 1e-9, "µs": 1e-6, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def seconds(text):
    value, unit = text.split()
    return float(value) * UNIT[unit]


def main(path):
    group = alg = None
    med = {}  # (group, input) -> {alg: seconds}
    order = []
    for line in open(path, encoding="utf-8"):
        m = re.match(r"^[│├╰ ]*[├╰]─ (\S+)\s*(.*)$", line.rstrip("\n"))
        if not m:
            continue
        name, rest = m.group(1), m.group(2)
        cols = [c.strip() for c in rest.split("│")]
        if name.startswith("group_") or name == "real":
            group = name
        elif name in ("rs", "schipper", "brute"):
            alg = name
        elif len(cols) >= 3 and cols[2]:
            key = (group, name)
            if key not in med:
                med[key] = {}
                order.append(key)
            med[key][alg] = seconds(cols[2])
    print("| group | input | RS median | S median | BF median | t_S/t_RS | t_BF/t_RS | paper t_S/t_RS | paper t_BF/t_RS |")
    print("|---|---|---|---|---|---|---|---|---|")
    for key in order:
        m = med[key]
        if not all(a in m for a in ("rs", "schipper", "brute")):
            continue
        rs, s, bf = m["rs"], m["schipper"], m["brute"]
        p = PAPER.get(key[1])
        ps = f"{p[0]:.2f} | {p[1]:.2f}" if p else "– | –"
        print(f"| {key[0]} | {key[1]} | {rs*1e3:.3f} ms | {s*1e3:.3f} ms | {bf*1e3:.3f} ms | "
              f"{s/rs:.2f} | {bf/rs:.2f} | {ps} |")


if __name__ == "__main__":
    main(sys.argv[1])
