#!/usr/bin/env python3
"""Render the before/after pictures of docs/pictures.md into docs/images/.

Each picture runs one task of the command line on a mesh the repository carries (or one
it generates) and draws the input and the output side by side, with the same camera:

    reduce.png          reduce   tests/data/meshes/closed/bunny_npm.off.gz
    reduce-genus3.png   reduce   tests/data/meshes/closed/high_genus_3.off.gz
    quad.png            quad     tests/data/meshes/closed/bunny_npm.off.gz
    simplify.png        simplify tests/data/meshes/closed/bunny_npm.off.gz  --eps-rel 0.02
    simplify-open.png   simplify (gen isosurface --surface hyperboloid)     --eps-rel 0.02

Usage (from anywhere; needs Python 3 with docs/requirements-pictures.txt installed):

    python docs/render_pictures.py                 # builds the command line, writes docs/images
    python docs/render_pictures.py --cli PATH      # uses an existing `contractible` binary
    python docs/render_pictures.py --out DIR       # writes the PNGs elsewhere
    python docs/render_pictures.py --keep DIR      # keeps the meshes it made in DIR

The output is deterministic: the command line is, the meshes are fixed, and nothing here
draws random numbers. Only matplotlib and numpy are used; the meshes the command line
writes are read by the small readers below (ASCII OFF, OBJ, PLY ascii or binary).
"""

from __future__ import annotations

import argparse
import gzip
import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib
from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
MESHES = REPO / "tests" / "data" / "meshes" / "closed"

# 1200 x 600 pixels.
FIG_SIZE = (12.0, 6.0)
DPI = 100

FACE_COLOR = np.array([0.55, 0.68, 0.85])
HIGHLIGHT_COLOR = np.array([0.93, 0.62, 0.35])
EDGE_COLOR = (0.10, 0.12, 0.18)
# Light direction in plotting coordinates (z up), so the facets read as relief.
LIGHT = np.array([-0.4, -0.6, 0.7])
# Brightness steps of the flat shading: fewer distinct colours leave more of the PNG
# palette to the anti-aliased edges, and no step is visible at 48.
LEVELS = 48


# ---------------------------------------------------------------------------
# Mesh files
# ---------------------------------------------------------------------------


@dataclass
class Mesh:
    """Vertex positions (n x 3) and faces (a list of index tuples; all of one size)."""

    vertices: np.ndarray
    faces: list[tuple[int, ...]]

    def used(self) -> "Mesh":
        """The same faces over only the vertices they use (files may keep spares)."""
        idx = sorted({v for f in self.faces for v in f})
        remap = {old: new for new, old in enumerate(idx)}
        return Mesh(self.vertices[idx], [tuple(remap[v] for v in f) for f in self.faces])


def _open_text(path: Path) -> str:
    data = path.read_bytes()
    if path.suffix == ".gz":
        data = gzip.decompress(data)
    return data.decode("utf-8")


def read_off(path: Path) -> Mesh:
    """ASCII OFF: `OFF`, counts `V F E`, V lines `x y z`, F lines `n i j k ...` (0-based)."""
    tokens: list[str] = []
    for line in _open_text(path).splitlines():
        tokens.extend(line.split("#", 1)[0].split())
    if not tokens or not tokens[0].endswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    pos = 1
    nv, nf = int(tokens[pos]), int(tokens[pos + 1])
    pos += 3
    verts = np.array(tokens[pos : pos + 3 * nv], dtype=float).reshape(nv, 3)
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(tokens[pos])
        faces.append(tuple(int(t) for t in tokens[pos + 1 : pos + 1 + n]))
        pos += 1 + n
    return Mesh(verts, faces)


def read_obj(path: Path) -> Mesh:
    """OBJ: `v x y z` and `f a b c ...` lines (1-based or negative, `a/t/n` allowed)."""
    verts: list[list[float]] = []
    faces = []
    for line in _open_text(path).splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            verts.append([float(t) for t in parts[1:4]])
        elif parts[0] == "f":
            face = []
            for t in parts[1:]:
                i = int(t.split("/", 1)[0])
                face.append(i - 1 if i > 0 else len(verts) + i)
            faces.append(tuple(face))
    return Mesh(np.array(verts, dtype=float), faces)


_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}  # fmt: skip


def read_ply(path: Path) -> Mesh:
    """PLY, ascii or binary: element `vertex` (x, y, z) and `face` (vertex_indices list).

    The command line writes binary little-endian with `double` coordinates and `list uchar
    uint vertex_indices`; the header is parsed rather than assumed, other elements and
    properties are skipped.
    """
    data = path.read_bytes()
    if path.suffix == ".gz":
        data = gzip.decompress(data)
    end = data.index(b"end_header\n") + len(b"end_header\n")
    elements: list[tuple[str, int, list[tuple]]] = []
    fmt = "ascii"
    for line in data[:end].decode("ascii").splitlines():
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            if w[1] == "list":
                elements[-1][2].append(("list", w[4], _PLY_TYPES[w[2]], _PLY_TYPES[w[3]]))
            else:
                elements[-1][2].append(("scalar", w[2], _PLY_TYPES[w[1]]))
    verts = np.zeros((0, 3))
    faces: list[tuple[int, ...]] = []
    if fmt == "ascii":
        tokens = data[end:].split()
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = {}
                for p in props:
                    if p[0] == "scalar":
                        row[p[1]] = float(tokens[pos])
                        pos += 1
                    else:
                        n = int(tokens[pos])
                        row[p[1]] = tuple(int(t) for t in tokens[pos + 1 : pos + 1 + n])
                        pos += 1 + n
                rows.append(row)
            if name == "vertex":
                verts = np.array([[r["x"], r["y"], r["z"]] for r in rows], dtype=float)
            elif name == "face":
                faces = [r.get("vertex_indices", r.get("vertex_index")) for r in rows]
        return Mesh(verts, faces)
    order = {"binary_little_endian": "<", "binary_big_endian": ">"}[fmt]
    pos = end
    for name, count, props in elements:
        if all(p[0] == "scalar" for p in props):
            dt = np.dtype([(p[1], order + p[2]) for p in props])
            arr = np.frombuffer(data, dtype=dt, count=count, offset=pos)
            pos += dt.itemsize * count
            if name == "vertex":
                verts = np.stack([arr["x"], arr["y"], arr["z"]], axis=1).astype(float)
            continue
        rows = []
        for _ in range(count):
            row = {}
            for p in props:
                if p[0] == "scalar":
                    dt = np.dtype(order + p[2])
                    row[p[1]] = np.frombuffer(data, dt, 1, pos)[0]
                    pos += dt.itemsize
                else:
                    ct, it = np.dtype(order + p[2]), np.dtype(order + p[3])
                    n = int(np.frombuffer(data, ct, 1, pos)[0])
                    pos += ct.itemsize
                    row[p[1]] = tuple(int(x) for x in np.frombuffer(data, it, n, pos))
                    pos += it.itemsize * n
            rows.append(row)
        if name == "face":
            faces = [r.get("vertex_indices", r.get("vertex_index")) for r in rows]
    return Mesh(verts, faces)


def read_mesh(path: Path) -> Mesh:
    name = path.name[:-3] if path.name.endswith(".gz") else path.name
    ext = name.rsplit(".", 1)[-1].lower()
    return {"off": read_off, "obj": read_obj, "ply": read_ply}[ext](path)


# ---------------------------------------------------------------------------
# The command line
# ---------------------------------------------------------------------------


class Cli:
    def __init__(self, binary: Path):
        self.binary = binary

    def run(self, *args: str | Path) -> str:
        cmd = [str(self.binary), "--quiet", *map(str, args)]
        print("  $ contractible " + " ".join(_shown(a) for a in args), flush=True)
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"command failed ({done.returncode}): {' '.join(cmd)}\n{done.stderr}")
        return done.stdout

    def info(self, path: Path) -> dict:
        return json.loads(self.run("--json", "info", path))


def _shown(a: str | Path) -> str:
    """An argument as a reader would type it: repository files relative, temporaries bare."""
    p = Path(a)
    if p.is_absolute():
        try:
            return str(p.relative_to(REPO))
        except ValueError:
            return p.name
    return str(a)


def build_cli() -> Path:
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    if not target.is_absolute():
        target = REPO / target
    print("building the command line (cargo build --release -p contractible-cli)", flush=True)
    built = subprocess.run(["cargo", "build", "--release", "-p", "contractible-cli"], cwd=REPO)
    if built.returncode != 0:
        sys.exit("cargo build failed; fix the build or pass --cli PATH")
    exe = target / "release" / ("contractible.exe" if os.name == "nt" else "contractible")
    if not exe.exists():
        sys.exit(f"built, but {exe} is not there")
    return exe


def surface_words(info: dict) -> str:
    """The surface type of an `info --json` report, in words ("sphere", "genus 3", ...)."""

    def one(c: dict) -> str:
        b = c.get("boundary_loops", 0)
        if c.get("orientable", True):
            g = c.get("genus")
            if b == 0:
                return {0: "sphere", 1: "torus"}.get(g, f"genus-{g} surface")
            if g == 0 and b == 1:
                return "disc"
            if g == 0 and b == 2:
                return "annulus"
            return f"genus {g}, {b} boundary loops"
        h = c.get("euler_genus")
        return f"non-orientable, Euler genus {h}" + (f", {b} boundary loops" if b else "")

    comps = info.get("component_list")
    if comps is None:
        # A polygon mesh is described as a whole: with one component, that is its type.
        if info["components"] != 1:
            return f"{info['components']} components"
        b = info.get("boundary_loops", 0)
        chi = info["euler_characteristic"]
        orientable = info["orientable"]
        g = (2 - chi - b) // 2 if orientable else None
        comps = [{"orientable": orientable, "genus": g, "euler_genus": 2 - chi - b,
                  "boundary_loops": b}]  # fmt: skip
    kinds = [one(c) for c in comps]
    if len(set(kinds)) == 1:
        if len(kinds) == 1:
            return kinds[0]
        plural = {"sphere": "spheres", "torus": "tori", "disc": "discs", "annulus": "annuli"}
        return f"{len(kinds)} {plural[kinds[0]]}" if kinds[0] in plural else \
            f"{len(kinds)} × {kinds[0]}"
    return ", ".join(kinds)


def title(label: str, mesh: Mesh, info: dict, extra: str = "") -> str:
    kind = "quads" if mesh.faces and len(mesh.faces[0]) == 4 else "triangles"
    return (
        f"{label}\nV = {len(mesh.vertices):,}   F = {len(mesh.faces):,} {kind}   "
        f"χ = {info['euler_characteristic']}   {surface_words(info)}{extra}"
    )


# ---------------------------------------------------------------------------
# Drawing
# ---------------------------------------------------------------------------


@dataclass
class View:
    """A camera: an axis permutation/flip to put the model upright, elevation, azimuth."""

    up: tuple[int, int, int] = (0, 1, 2)
    flip: tuple[float, float, float] = (1.0, 1.0, 1.0)
    elev: float = 20.0
    azim: float = -60.0
    zoom: float = 1.0

    def place(self, v: np.ndarray) -> np.ndarray:
        return v[:, list(self.up)] * np.array(self.flip)


def shade(polys: np.ndarray, base: np.ndarray) -> np.ndarray:
    """Flat colour per face: ambient plus two-sided diffuse by the face normal.

    `base` is one colour (3,) or one per face (n x 3).
    """
    n = np.cross(polys[:, 1] - polys[:, 0], polys[:, 2] - polys[:, 0])
    if polys.shape[1] == 4:
        n = n + np.cross(polys[:, 2] - polys[:, 0], polys[:, 3] - polys[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    light = LIGHT / np.linalg.norm(LIGHT)
    k = 0.35 + 0.65 * np.abs(n @ light)
    k = np.round(k * LEVELS) / LEVELS
    base = np.broadcast_to(base, (len(polys), 3))
    rgb = np.clip(base * k[:, None] + 0.08 * k[:, None] ** 8, 0, 1)
    return np.concatenate([rgb, np.ones((len(rgb), 1))], axis=1)


def draw(ax, mesh: Mesh, view: View, box: tuple[np.ndarray, np.ndarray], *,
         base=FACE_COLOR, lw=0.15, edge_alpha=0.55, face_alpha=1.0):  # fmt: skip
    pts = view.place(mesh.vertices)
    polys = pts[np.array(mesh.faces)]
    colors = shade(polys, base)
    colors[:, 3] = face_alpha
    coll = Poly3DCollection(
        polys,
        facecolors=colors,
        edgecolors=(*EDGE_COLOR, edge_alpha),
        linewidths=lw,
    )
    ax.add_collection3d(coll)
    frame(ax, view, box)
    return pts


def frame(ax, view: View, box: tuple[np.ndarray, np.ndarray]) -> None:
    lo, hi = box
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2 / view.zoom
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=view.elev, azim=view.azim)
    ax.set_axis_off()


def figure(before_title: str, after_title: str):
    fig = plt.figure(figsize=FIG_SIZE, dpi=DPI)
    a = fig.add_axes((0.0, 0.05, 0.5, 0.83), projection="3d")
    b = fig.add_axes((0.5, 0.05, 0.5, 0.83), projection="3d")
    fig.text(0.25, 0.985, before_title, ha="center", va="top", fontsize=11)
    fig.text(0.75, 0.985, after_title, ha="center", va="top", fontsize=11)
    fig.add_artist(plt.Line2D([0.5, 0.5], [0.04, 0.96], color="0.85", lw=1))
    return fig, a, b


def save(fig, path: Path, note: str) -> None:
    fig.text(0.5, 0.012, note, ha="center", va="bottom", fontsize=9, color="0.35",
             family="monospace")  # fmt: skip
    fig.canvas.draw()
    rgba = np.asarray(fig.canvas.buffer_rgba())
    plt.close(fig)
    write_indexed_png(path, rgba[:, :, :3])
    print(f"  wrote {_shown(path)} ({path.stat().st_size / 1024:.0f} KB)", flush=True)


def write_indexed_png(path: Path, rgb: np.ndarray) -> None:
    """Writes an 8-bit palette PNG: a third of the size of the RGB file, and no metadata,
    so the same picture gives the same bytes.

    The palette takes colours by frequency (flat-shaded faces and the edge colour come
    first), skipping one within a small distance of a colour already taken, so that a
    colour of few pixels but its own hue (a thin highlighted face) still gets an entry.
    Every other colour, mostly a blend at an anti-aliased edge, becomes its nearest
    palette entry. Ties are broken by colour value, so the result is deterministic.
    """
    flat = rgb.reshape(-1, 3).astype(np.int64)
    colours, inverse, counts = np.unique(flat, axis=0, return_inverse=True, return_counts=True)
    order = np.argsort(-counts, kind="stable")
    palette = np.empty((256, 3), dtype=np.int64)
    taken = 0
    for spacing in (64, 16, 0):
        for i in order:
            if taken == 256:
                break
            c = colours[i]
            if taken == 0 or ((palette[:taken] - c) ** 2).sum(axis=1).min() > spacing:
                palette[taken] = c
                taken += 1
    palette = palette[:taken]
    nearest = np.empty(len(colours), dtype=np.uint8)
    for start in range(0, len(colours), 4096):
        block = colours[start : start + 4096]
        d = ((block[:, None, :] - palette[None, :, :]) ** 2).sum(axis=2)
        nearest[start : start + 4096] = d.argmin(axis=1)
    index = nearest[inverse.reshape(-1)].reshape(rgb.shape[:2])
    h, w = index.shape
    rows = np.concatenate([np.zeros((h, 1), np.uint8), index], axis=1)  # filter 0 per row

    def chunk(kind: bytes, body: bytes) -> bytes:
        crc = zlib.crc32(kind + body) & 0xFFFFFFFF
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", crc)

    path.write_bytes(
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 3, 0, 0, 0))
        + chunk(b"PLTE", palette.astype(np.uint8).tobytes())
        + chunk(b"IDAT", zlib.compress(rows.tobytes(), 9))
        + chunk(b"IEND", b"")
    )


def bbox(mesh: Mesh, view: View) -> tuple[np.ndarray, np.ndarray]:
    p = view.place(mesh.vertices)
    return p.min(axis=0), p.max(axis=0)


# ---------------------------------------------------------------------------
# The pictures
# ---------------------------------------------------------------------------

BUNNY_VIEW = View(up=(0, 2, 1), flip=(1.0, -1.0, 1.0), elev=12.0, azim=-75.0, zoom=1.15)


def picture_reduce(cli: Cli, tmp: Path, out: Path, name: str, view: View, png: str) -> None:
    src = MESHES / f"{name}.off.gz"
    res = tmp / f"{name}-reduced.off"
    cli.run("reduce", src, "-o", res)
    before, after = read_mesh(src).used(), read_mesh(res)
    after_used = after.used()
    box = bbox(before, view)
    fig, a, b = figure(
        title(f"{name}: the input", before, cli.info(src)),
        title("reduce: an irreducible triangulation", after_used, cli.info(res),
              "\nthe survivors at their original positions; the input in grey"),  # fmt: skip
    )
    draw(a, before, view, box)
    # The survivors keep their original coordinates: show the input as a faint ghost
    # around the few triangles that are left, and mark the surviving vertices.
    draw(b, before, view, box, base=np.array([0.85, 0.87, 0.9]), lw=0.0, face_alpha=0.10)
    pts = draw(b, after_used, view, box, base=HIGHLIGHT_COLOR, lw=1.2, edge_alpha=0.9,
               face_alpha=0.80)  # fmt: skip
    b.scatter(pts[:, 0], pts[:, 1], pts[:, 2], s=22, c="black", depthshade=False)
    save(fig, out / png, f"contractible reduce {_shown(src)} -o {res.name}")


def picture_quad(cli: Cli, tmp: Path, out: Path) -> None:
    src = MESHES / "bunny_npm.off.gz"
    res = tmp / "bunny_npm-quads.obj"
    cli.run("quad", src, "-o", res)
    # The quads use the input's vertex numbers: compare edges before any renumbering.
    before, after = read_mesh(src), read_mesh(res)
    edges = {frozenset(p) for f in before.faces for p in zip(f, f[1:] + f[:1])}
    # The default algorithm pairs the triangles of a triangulation reached by edge flips:
    # a quad with a side the input lacks comes from flipped triangles.
    flipped = np.array(
        [any(frozenset(p) not in edges for p in zip(q, q[1:] + q[:1])) for q in after.faces]
    )
    colors = np.where(flipped[:, None], HIGHLIGHT_COLOR[None, :], FACE_COLOR[None, :])
    view = BUNNY_VIEW
    box = bbox(before, view)
    fig, a, b = figure(
        title("bunny_npm: the input", before, cli.info(src)),
        title("quad: the triangles paired into quads, same vertices", after, cli.info(res),
              f"\norange: {flipped.sum():,} quads with a side the input lacks (after flips)"),
    )  # fmt: skip
    draw(a, before, view, box, lw=0.25, edge_alpha=0.8)
    draw(b, after, view, box, base=colors, lw=0.25, edge_alpha=0.8)
    save(fig, out / "quad.png", f"contractible quad {_shown(src)} -o {res.name}")


def picture_simplify(cli: Cli, tmp: Path, out: Path) -> None:
    src = MESHES / "bunny_npm.off.gz"
    res = tmp / "bunny_npm-simplified.ply"
    cli.run("simplify", src, "-o", res, "--eps-rel", "0.02")
    before, after = read_mesh(src).used(), read_mesh(res).used()
    view = BUNNY_VIEW
    box = bbox(before, view)
    fig, a, b = figure(
        title("bunny_npm: the input", before, cli.info(src)),
        title("simplify, ε = 2 % of the bounding-box diagonal", after, cli.info(res)),
    )
    draw(a, before, view, box)
    draw(b, after, view, box)
    save(fig, out / "simplify.png",
         f"contractible simplify {_shown(src)} -o {res.name} --eps-rel 0.02")  # fmt: skip


def picture_simplify_open(cli: Cli, tmp: Path, out: Path) -> None:
    src = tmp / "hyperboloid.off"
    res = tmp / "hyperboloid-simplified.off"
    cli.run("gen", "isosurface", "--surface", "hyperboloid", "--resolution", "16", "-o", src)
    cli.run("simplify", src, "-o", res, "--eps-rel", "0.02")
    before, after = read_mesh(src).used(), read_mesh(res).used()
    view = View(elev=25.0, azim=-55.0, zoom=1.1)
    box = bbox(before, view)
    fig, a, b = figure(
        title("gen isosurface --surface hyperboloid", before, cli.info(src)),
        title("simplify, ε = 2 % of the bounding-box diagonal", after, cli.info(res)),
    )
    draw(a, before, view, box, lw=0.3, edge_alpha=0.8)
    draw(b, after, view, box, lw=0.3, edge_alpha=0.8)
    save(fig, out / "simplify-open.png",
         f"contractible gen isosurface --surface hyperboloid --resolution 16 -o {src.name}\n"
         f"contractible simplify {src.name} -o {res.name} --eps-rel 0.02")  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cli", type=Path, help="an existing contractible binary (default: build)")
    ap.add_argument("--out", type=Path, default=REPO / "docs" / "images", help="output folder")
    ap.add_argument("--keep", type=Path, help="keep the meshes the command line wrote here")
    args = ap.parse_args()

    cli = Cli(args.cli.resolve() if args.cli else build_cli())
    args.out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="contractible-pictures-") as t:
        tmp = args.keep.resolve() if args.keep else Path(t)
        tmp.mkdir(parents=True, exist_ok=True)
        print("reduce.png")
        picture_reduce(cli, tmp, args.out, "bunny_npm", BUNNY_VIEW, "reduce.png")
        print("reduce-genus3.png")
        picture_reduce(cli, tmp, args.out, "high_genus_3",
                       View(elev=70.0, azim=-90.0, zoom=1.3), "reduce-genus3.png")  # fmt: skip
        print("quad.png")
        picture_quad(cli, tmp, args.out)
        print("simplify.png")
        picture_simplify(cli, tmp, args.out)
        print("simplify-open.png")
        picture_simplify_open(cli, tmp, args.out)


if __name__ == "__main__":
    main()
