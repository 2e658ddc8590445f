#!/usr/bin/env python3
"""Plots the contact tractions and the slip of an elastic scene's run along Γ_C.

Reads DIR/boundary_<effect>.csv (columns x,y,s_arc,u_n,u_t,gap,pressure,traction_t, written by
`hpcontact solve` for the effects frictionless, tresca, coulomb) and DIR/summary.json, and writes
DIR/boundary_elastic.png: the pressure, the tangential traction with the Coulomb cone ±F·p, and
the tangential displacement, each against the arc length s on Γ_C, one colour per effect, in the
window S_MIN … S_MAX of s, by default the contact sets and their surroundings.
Usage: plot_elastic_boundary.py DIR [S_MIN S_MAX]
"""
import csv
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_file import save_figure  # noqa: E402
from plot_run import contact_window  # noqa: E402

STYLES = {"frictionless": ("tab:blue", "-"), "tresca": ("tab:green", "--"), "coulomb": ("tab:red", "-")}


def read(path):
    with open(path, newline="") as handle:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]


def main():
    if len(sys.argv) not in (2, 4):
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    summary = json.loads((folder / "summary.json").read_text())
    effects = [e for e in summary.get("effects", []) if (folder / f"boundary_{e}.csv").exists()]
    if not effects:
        sys.exit(f"plot_elastic_boundary.py: no boundary_<effect>.csv of an elastic effect in {folder}")
    if len(sys.argv) == 4:
        window = (float(sys.argv[2]), float(sys.argv[3]))
    else:  # the window that holds every effect's contact set
        windows = [contact_window([r["s_arc"] for r in rows], [r["pressure"] for r in rows])
                   for rows in (read(folder / f"boundary_{e}.csv") for e in effects)]
        window = (min(w[0] for w in windows), max(w[1] for w in windows))

    figure, (pressure_axis, traction_axis, slip_axis) = plt.subplots(1, 3, figsize=(15, 4.4))
    for effect in effects:
        rows = read(folder / f"boundary_{effect}.csv")
        rows = [r for r in rows if window[0] <= r["s_arc"] <= window[1]]
        s = [r["s_arc"] for r in rows]
        colour, line = STYLES.get(effect, ("tab:grey", "-"))
        pressure_axis.plot(s, [r["pressure"] for r in rows], line, color=colour, label=effect)
        traction_axis.plot(s, [r["traction_t"] for r in rows], line, color=colour, label=f"{effect}: σ_nt")
        slip_axis.plot(s, [r["u_t"] for r in rows], line, color=colour, label=effect)
        coefficient = summary.get(effect, {}).get("friction_coefficient")
        if coefficient is not None:
            cone = [coefficient * max(r["pressure"], 0.0) for r in rows]
            traction_axis.plot(s, cone, ":", color=colour, linewidth=1, label=f"{effect}: ±F·p (F = {coefficient:g})")
            traction_axis.plot(s, [-c for c in cone], ":", color=colour, linewidth=1)
    for axis, label, title in (
        (pressure_axis, "pressure p = −σ_nn", "Contact pressure"),
        (traction_axis, "tangential traction σ_nt", "Tangential traction and Coulomb cone"),
        (slip_axis, "tangential displacement u_t", "Tangential displacement"),
    ):
        axis.set_xlabel("arc length s on Γ_C")
        axis.set_ylabel(label)
        axis.set_title(title)
        axis.grid(True, alpha=0.3)
        axis.legend(fontsize=8)
    figure.suptitle(f"{summary.get('scene', '')}: p = {summary.get('p')}, p_C = {summary.get('pC')}", fontsize=10)
    figure.tight_layout()
    save_figure(figure, folder / "boundary_elastic.png")


if __name__ == "__main__":
    main()
