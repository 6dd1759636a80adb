#!/usr/bin/env python3
"""Plots a GrainLab run file (run.h5) with h5py and matplotlib.

Writes two PNG files into the output folder:

  q_over_p.png          q/p against the axial strain eps1 during shear, one curve per test,
                        each test's peak checkpoint marked
  checkpoint-<name>.png one checkpoint: the grains as ovals with the force chains (lines
                        through the contact points, width proportional to the contact force),
                        and the void cells (polygons coloured by valence)

The checkpoint is the peak of q/p of the first shear test unless --checkpoint names another
(a checkpoint name, or "last"). Every periodic object is drawn with its images and clipped to
the periodic cell. docs/h5py.md walks through this script; docs/formats.md lists every dataset.

Usage: plot_run.py RUN_H5 [--out DIR] [--checkpoint NAME|last] [--dpi N]
Needs python3, h5py, numpy and matplotlib (Debian: python3-h5py python3-numpy
python3-matplotlib).
"""

import argparse
import os
import sys

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from matplotlib.patches import Patch, Polygon  # noqa: E402

# Fill colour of a void cell by its valence (number of sides); the last one for 9 and more.
VALENCE_COLOURS = {
    3: "#4e79a7",
    4: "#f28e2b",
    5: "#59a14f",
    6: "#e15759",
    7: "#b07aa1",
    8: "#edc948",
    9: "#9c755f",
}
FIGURE_SIZE = (12.0, 6.0)  # inches: two panels side by side
SERIES_SIZE = (8.0, 6.0)


def text(value):
    """An HDF5 fixed-length string (bytes in h5py) as str."""
    return value.decode() if isinstance(value, bytes) else str(value)


def checkpoints_in_write_order(f):
    """Names of the complete checkpoints, in the order they were written."""
    cps = f["checkpoints"]
    names = [n for n in cps if not n.endswith(".writing")]
    return sorted(names, key=lambda n: int(cps[n].attrs["index"]))


def tests_in_write_order(f):
    tests = f["tests"]
    return sorted(tests, key=lambda n: int(tests[n].attrs["index"]))


def read_series(f, test):
    """One test's series as a dict of numpy arrays, column name -> values, with stage_kind."""
    g = f["tests"][test]["series"]
    series = {text(c): g[text(c)][:] for c in g.attrs["columns"]}
    series["stage_kind"] = np.array([text(s) for s in g["stage_kind"][:]])
    return series


def peak_checkpoint(f, test):
    """The name of the test's peak checkpoint of q/p, or None (not finished, or format 2)."""
    attrs = f["tests"][test].attrs
    return text(attrs["peak_checkpoint"]) if "peak_checkpoint" in attrs else None


def plot_series(f, out_path, dpi):
    fig, ax = plt.subplots(figsize=SERIES_SIZE)
    for test in tests_in_write_order(f):
        s = read_series(f, test)
        shear = s["stage_kind"] == "shear"
        if not shear.any():
            continue  # the compaction
        pressure = f["tests"][test]["series"]["stage_pressure"][:][shear][0]
        (line,) = ax.plot(100 * s["eps1"][shear], s["q_over_p"][shear],
                          label=f"{pressure / 1000:g} kPa")
        peak = peak_checkpoint(f, test)
        if peak is not None:
            cp = f["checkpoints"][peak].attrs
            ax.plot(100 * cp["axial_strain"], cp["q_over_p"], "o", color=line.get_color())
    ax.set_xlabel("axial strain ε1 [%]")
    ax.set_ylabel("q/p [-]")
    ax.set_title("q/p during shear (dots: the peak checkpoints)")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.savefig(out_path, dpi=dpi)
    plt.close(fig)


def cell_images(h):
    """Offsets of the periodic images of the 3 x 3 neighbourhood of the cell [m]."""
    return [h @ np.array([i, j]) for i in (-1, 0, 1) for j in (-1, 0, 1)]


def cell_outline(h):
    return np.array([[0, 0], h[:, 0], h[:, 0] + h[:, 1], h[:, 1]])


def prepare_axes(ax, h, title):
    """The cell's outline, drawn, and returned as the clip path of everything in the cell."""
    outline = swap(cell_outline(h))  # x1 is the axial direction: drawn vertically, x2 across
    clip = Polygon(outline, closed=True, facecolor="none", edgecolor="black", linewidth=1.0)
    ax.add_patch(clip)
    low, high = outline.min(axis=0), outline.max(axis=0)
    margin = 0.02 * (high - low).max()
    ax.set_xlim(low[0] - margin, high[0] + margin)
    ax.set_ylim(low[1] - margin, high[1] + margin)
    ax.set_aspect("equal")
    ax.set_xlabel("x2 [m]")
    ax.set_ylabel("x1 [m]")
    ax.set_title(title)
    return clip


def swap(points):
    """(x1, x2) -> plot coordinates (x2 across, x1 up)."""
    return points[..., ::-1]


def grain_outlines(cp):
    """Each grain's outline in world coordinates, shape (N, K, 2), about its wrapped centre."""
    centre = np.stack([cp["contacts/centre1"][:], cp["contacts/centre2"][:]], axis=1)
    theta = cp["grains/theta"][:]
    shape = cp["grains/shape"][:]
    ox = cp["shape_outline1"][:][shape]  # (N, K), body frame
    oy = cp["shape_outline2"][:][shape]
    c, s = np.cos(theta)[:, None], np.sin(theta)[:, None]
    x1 = centre[:, 0, None] + c * ox - s * oy
    x2 = centre[:, 1, None] + s * ox + c * oy
    return np.stack([x1, x2], axis=2)


def plot_grains_and_forces(ax, cp, h):
    clip = prepare_axes(ax, h, "grains and force chains")
    outlines = grain_outlines(cp)
    c = cp["contacts"]
    a = np.stack([c["centre1"][:], c["centre2"][:]], axis=1)[c["first"][:]]
    point = np.stack([c["point1"][:], c["point2"][:]], axis=1)
    b = a + np.stack([c["branch1"][:], c["branch2"][:]], axis=1)  # the second grain's image
    force = np.hypot(c["normal_force"][:], c["tangential_force"][:])
    width = 4.0 * force / force.max() if len(force) and force.max() > 0 else force
    strong = c["strong"][:].astype(bool)
    for offset in cell_images(h):
        grains = PolyCollection(swap(outlines + offset), facecolor="#d9d9d9",
                                edgecolor="#7f7f7f", linewidth=0.3)
        grains.set_clip_path(clip)
        ax.add_collection(grains)
        segments = np.concatenate([np.stack([a, point], axis=1), np.stack([point, b], axis=1)])
        chains = LineCollection(swap(segments + offset), linewidths=np.concatenate([width, width]),
                                colors=np.where(np.concatenate([strong, strong])[:, None],
                                                [[0.6, 0.0, 0.0, 1.0]], [[0.2, 0.2, 0.2, 1.0]]))
        chains.set_clip_path(clip)
        ax.add_collection(chains)
    ax.legend(handles=[Patch(color="#990000", label="strong contacts"),
                       Patch(color="#333333", label="weak contacts")], loc="upper right")


def plot_void_cells(ax, cp, h):
    clip = prepare_axes(ax, h, "void cells by valence")
    v = cp["void_cells"]
    valence = v["valence"][:]
    offsets = v["vertex_offsets"][:]
    vertices = np.stack([v["vertices1"][:], v["vertices2"][:]], axis=1)
    polygons = [vertices[offsets[k]:offsets[k + 1]] for k in range(len(valence))]
    colours = [VALENCE_COLOURS[min(n, 9)] for n in valence]
    for offset in cell_images(h):
        cells = PolyCollection([swap(p + offset) for p in polygons], facecolors=colours,
                               edgecolor="white", linewidth=0.3)
        cells.set_clip_path(clip)
        ax.add_collection(cells)
    counts = {n: int((np.minimum(valence, 9) == n).sum()) for n in VALENCE_COLOURS}
    ax.legend(handles=[Patch(color=VALENCE_COLOURS[n],
                             label=f"{n}{'+' if n == 9 else ''} sides: {counts[n]}")
                       for n in VALENCE_COLOURS if counts[n]],
              loc="upper right", fontsize="small")


def plot_checkpoint(f, name, out_path, dpi):
    cp = f["checkpoints"][name]
    if "contacts" not in cp:
        sys.exit(f"{name}: this checkpoint has no contacts (a run file of format 2); "
                 "run the experiment again with this GrainLab")
    h = cp["cell"][:].reshape(2, 2, order="F")  # column-major: the columns are the cell vectors
    a = cp.attrs
    fig, (left, right) = plt.subplots(1, 2, figsize=FIGURE_SIZE)
    plot_grains_and_forces(left, cp, h)
    plot_void_cells(right, cp, h)
    kind = "peak of q/p, " if "peak" in a and a["peak"] else ""
    fig.suptitle(f"{name}: {kind}{text(a['stage_kind'])} {a['pressure'] / 1000:g} kPa, "
                 f"ε1 = {100 * a['axial_strain']:.2f} %")
    fig.tight_layout()
    fig.savefig(out_path, dpi=dpi)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run_file", help="the run file, e.g. out/run.h5")
    parser.add_argument("--out", default=".", help="folder for the PNG files (default: .)")
    parser.add_argument("--checkpoint", default=None,
                        help='checkpoint name, or "last" (default: the first peak checkpoint)')
    parser.add_argument("--dpi", type=int, default=100, help="pixels per inch (default: 100)")
    args = parser.parse_args(argv)

    os.makedirs(args.out, exist_ok=True)
    with h5py.File(args.run_file, "r") as f:
        version = int(f.attrs["format_version"])
        if version < 2:
            sys.exit(f"{args.run_file}: run file format {version}; this script reads 2 and later")
        plot_series(f, os.path.join(args.out, "q_over_p.png"), args.dpi)
        names = checkpoints_in_write_order(f)
        name = args.checkpoint
        if name is None:
            peaks = [n for n in names if f["checkpoints"][n].attrs.get("peak", 0)]
            name = peaks[0] if peaks else names[-1]
        elif name == "last":
            name = names[-1]
        elif name not in f["checkpoints"]:
            sys.exit(f"{args.run_file}: no checkpoint {name}")
        out = os.path.join(args.out, f"checkpoint-{name}.png")
        plot_checkpoint(f, name, out, args.dpi)
        print(out)


if __name__ == "__main__":
    main()
