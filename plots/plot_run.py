#!/usr/bin/env python3
"""Draws the pictures a `hpcontact solve` folder calls for, whatever the run was: one entry for
every kind of scene. It reads DIR/summary.json and the files beside it and writes into DIR:
  scalar problems (signorini, friction, friction_s)   figure_<problem>.png: u, g or s and λ along
      Γ_C beside u on Ω (plot_paper.py's figure);
  elastic problems (frictionless, tresca, coulomb, tied; one body or a contact pair of two)
      figure_<problem>.png: the pressure and the tangential traction (with the Coulomb cone) along
      Γ_C, zoomed to the contact set, beside the von Mises stress on every body;
  the effect infsup                                   mode.png: the eigenvector of α along Γ_C.
Usage: plot_run.py DIR [DIR ...]
"""
import csv
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
from figure_file import save_figure  # noqa: E402
from plot_paper import plot as plot_scalar  # noqa: E402
from vtk_lagrange import read_lagrange_vtu  # noqa: E402


def read_columns(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    return {name: [float(row[name]) for row in rows] for name in (rows[0] if rows else {})}


def contact_window(s, pressure):
    """The arc-length window around the contact set (pressure above 1e-3 of its peak), widened by
    half its length on each side; all of Γ_C if nothing is in contact."""
    peak = max((abs(p) for p in pressure), default=0.0)
    touching = [si for si, p in zip(s, pressure) if peak > 0 and p > 1e-3 * peak]
    if not touching:
        return min(s), max(s)
    low, high = min(touching), max(touching)
    margin = max(0.5 * (high - low), 0.02 * (max(s) - min(s)))
    return max(min(s), low - margin), min(max(s), high + margin)


def body_files(folder, problem):
    """The problem's VTU per body: solution_<problem>.vtu, or solution_<problem>_<body>.vtu for a pair."""
    single = [folder / f"solution_{problem}.{suffix}" for suffix in ("vtu", "pvtu")]
    found = [path for path in single if path.exists()]
    if found:
        return found[:1]
    return sorted(path for suffix in ("vtu", "pvtu") for path in folder.glob(f"solution_{problem}_*.{suffix}")
                  if "_level" not in path.stem and "_rank" not in path.stem)


def plot_elastic(folder, problem, summary):
    columns = read_columns(folder / f"boundary_{problem}.csv")
    s, pressure, traction = columns["s_arc"], columns["pressure"], columns["traction_t"]
    low, high = contact_window(s, pressure)
    inside = [k for k, si in enumerate(s) if low <= si <= high]
    figure, (left, right) = plt.subplots(1, 2, figsize=(13, 4.6))
    left.plot([s[k] for k in inside], [pressure[k] for k in inside], color="tab:blue", label="pressure p = −σ_nn")
    left.plot([s[k] for k in inside], [traction[k] for k in inside], color="tab:orange",
              label="tangential traction σ_nt")
    coefficient = summary.get(problem, {}).get("friction_coefficient")
    if coefficient is not None:
        cone = [coefficient * max(pressure[k], 0.0) for k in inside]
        left.plot([s[k] for k in inside], cone, ":", color="tab:red", label=f"±F·p (F = {coefficient:g})")
        left.plot([s[k] for k in inside], [-c for c in cone], ":", color="tab:red")
    left.set_xlabel(f"arc length s on Γ_C (the contact set and its surroundings, {low:.3g} … {high:.3g})")
    left.set_ylabel("traction")
    left.grid(True, alpha=0.3)
    left.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=3)
    files = body_files(folder, problem)
    picture = None
    for path in files:
        x, y, triangles, fields = read_lagrange_vtu(path)
        picture = right.tripcolor(mtri.Triangulation(x, y, triangles), fields["von_mises"], shading="gouraud",
                                  cmap="magma")
    if picture is not None:
        figure.colorbar(picture, ax=right, label="von Mises stress")
    right.plot(columns["x"], columns["y"], color="tab:cyan", linewidth=1.5, label="Γ_C")
    right.set_aspect("equal")
    right.set_xlabel("x")
    right.set_ylabel("y")
    right.set_title("von Mises stress" + (f" on {len(files)} bodies" if len(files) > 1 else ""))
    total = summary.get(problem, {}).get("total_force")
    figure.suptitle(f"{Path(summary.get('scene', folder.name)).stem}: {problem}, p = {summary.get('p')}, "
                    f"p_C = {summary.get('pC')}" + (f", total force P = {total:.6g}" if total is not None else ""))
    figure.tight_layout()
    save_figure(figure, folder / f"figure_{problem}.png", dpi=110)


def plot_mode(folder):
    columns = read_columns(folder / "mode.csv")
    along = "s_arc" if "s_arc" in columns else "x"
    figure, axis = plt.subplots(figsize=(7, 3.6))
    for name in (c for c in columns if c.startswith("mu")):
        axis.plot(columns[along], columns[name], label=name)
    axis.set_xlabel("arc length s on Γ_C" if along == "s_arc" else "x on Γ_C")
    axis.set_ylabel("mode of α")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=8)
    figure.tight_layout()
    save_figure(figure, folder / "mode.png")


def plot_folder(folder):
    try:
        summary = json.loads((folder / "summary.json").read_text())
    except OSError as error:
        sys.exit(f"plot_run.py: {folder}: no summary.json ({error.strerror}): give the --out folder of "
                 "`hpcontact solve` (with the output 'summary')")
    drawn = 0
    for path in sorted(folder.glob("boundary_*.csv")):
        problem = path.stem[len("boundary_"):]
        with open(path, newline="") as handle:
            header = next(csv.reader(handle), [])
        if "pressure" in header:
            plot_elastic(folder, problem, summary)
        else:
            plot_scalar(folder, problem)
        drawn += 1
    if (folder / "mode.csv").exists():
        plot_mode(folder)
        drawn += 1
    if not drawn:
        sys.exit(f"plot_run.py: {folder}: nothing to draw (no boundary_<problem>.csv, no mode.csv): the run's "
                 "[run] outputs must include 'boundary' (or 'mode')")


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for folder in map(Path, sys.argv[1:]):
        plot_folder(folder)


if __name__ == "__main__":
    main()
