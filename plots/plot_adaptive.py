#!/usr/bin/env python3
"""An adaptive run of `hpcontact solve` (a scene with [adapt]): how the error fell, and the mesh it
made. Reads DIR/adapt.csv and DIR/solution_<problem>.vtu (the last step's T_h with p per cell);
optionally a work-precision folder's cheapest.csv (the hand-graded hp family's cheapest runs to
each tolerance) to compare with. Writes DIR/adaptive.png:
  left    the energy error |E - E_ref| and the estimate (eta^2/2) against unknowns^(1/3): a
          straight line is exponential convergence, the rate of hp-FEM in 2-D;
  middle  the last T_h, each cell coloured by its degree p;
  right   the same in a window 1e-2 of the domain wide around its finest cell, or around
          --at X,Y (the Hertz free boundary, say), --width wide.
Usage: plot_adaptive.py DIR [CHEAPEST_CSV] [--at X,Y] [--width W]
"""
import argparse
import csv
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from figure_file import save_figure  # noqa: E402


def read(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def cells_with_degrees(vtu):
    """The cells' vertex polygons (the first 3 or 4 nodes of a Lagrange cell) and their p."""
    mesh = meshio.read(vtu)
    polygons, degrees = [], []
    for block, p in zip(mesh.cells, mesh.cell_data["p"]):
        corners = 4 if "QUADRILATERAL" in block.type.upper() else 3
        polygons += [mesh.points[cell[:corners], :2] for cell in block.data]
        degrees += list(np.ravel(p))
    return polygons, np.array(degrees)


def draw_mesh(axis, polygons, degrees, limits, title):
    collection = PolyCollection(polygons, array=degrees, cmap="viridis", edgecolors="k", linewidths=0.3)
    collection.set_clim(degrees.min() - 0.5, degrees.max() + 0.5)
    axis.add_collection(collection)
    axis.set_xlim(limits[0]), axis.set_ylim(limits[1])
    axis.set_aspect("equal")
    axis.set_title(title)
    return collection


def arguments():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("folder", type=Path)
    parser.add_argument("cheapest", nargs="?")
    parser.add_argument("--at", help="X,Y: the centre of the zoomed window (default: the finest cell)")
    parser.add_argument("--width", type=float, help="the zoomed window's width (default: 1e-2 of the domain)")
    return parser.parse_args()


def main():
    args = arguments()
    folder = args.folder
    rows = read(folder / "adapt.csv")
    summary = json.loads((folder / "summary.json").read_text())
    problem = summary["effects"][0]
    figure, axes = plt.subplots(1, 3, figsize=(16, 5))
    unknowns = np.array([float(r["unknowns"]) for r in rows])
    axis = axes[0]
    if "error_energy" in rows[0]:
        axis.semilogy(unknowns ** (1 / 3), [float(r["error_energy"]) for r in rows], "o-", label="error |E - E_ref|")
    axis.semilogy(unknowns ** (1 / 3), [float(r["estimate"]) for r in rows], "s--", label=r"estimate $\eta^2/2$")
    if args.cheapest:
        hand = [r for r in read(args.cheapest) if r["problem"] == problem and r["family"] == "hp geometric"]
        axis.semilogy([float(r["ndofs"]) ** (1 / 3) for r in hand], [float(r["error_energy"]) for r in hand], "k^",
                      markersize=9, label="hand-graded hp (cheapest to 1e-3, 1e-6, 1e-9)")
    axis.axhline(1e-9, color="grey", lw=0.8, ls=":")
    axis.set_xlabel(r"unknowns$^{1/3}$")
    axis.set_ylabel("error in the energy")
    axis.set_title(f"{problem}: {len(rows)} adaptive steps from a uniform start")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(loc="upper right")
    polygons, degrees = cells_with_degrees(folder / f"solution_{problem}.vtu")
    points = np.concatenate(polygons)
    whole = [(points[:, 0].min(), points[:, 0].max()), (points[:, 1].min(), points[:, 1].max())]
    collection = draw_mesh(axes[1], polygons, degrees, whole, f"last $T_h$: {len(polygons)} cells, p per cell")
    figure.colorbar(collection, ax=axes[1], label="p")
    # A window 1e-2 of the domain wide around the finest cell (or as asked), moved inside the domain.
    if args.at:
        centre = np.array([float(v) for v in args.at.split(",")])
    else:
        sizes = [np.ptp(polygon[:, 0]) for polygon in polygons]
        centre = polygons[int(np.argmin(sizes))].mean(axis=0)
    half = 0.5 * args.width if args.width else 5e-3 * max(np.ptp(points[:, 0]), np.ptp(points[:, 1]))
    window = [(min(max(c - half, low), high - 2 * half), min(max(c - half, low), high - 2 * half) + 2 * half)
              for c, (low, high) in zip(centre, whole)]
    where = "at" if args.at else "at the finest cell"
    draw_mesh(axes[2], polygons, degrees, window, f"{2 * half:.3g} wide, {where} ({centre[0]:.4g}, {centre[1]:.4g})")
    figure.tight_layout()
    save_figure(figure, folder / "adaptive.png")


if __name__ == "__main__":
    main()
