#!/usr/bin/env python3
"""Plots a stability sweep written by `hpcontact sweep` (alpha.csv, verdicts.csv) and optional
spurious modes written by `hpcontact infsup --mode` (mode_*.csv, columns x,mu,...).

Writes into DIR: alpha_vs_h.png (α against h per configuration, one panel per multiplier family
and h/H), stable_map.png (verdict over (p, p_C), one panel per family and h/H: the families side
by side), alpha_vs_pi.png, modes.png.
Usage: plot_stability.py DIR
"""
import csv
import sys
from collections import defaultdict
from fractions import Fraction
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.ticker import FixedFormatter, FixedLocator, NullLocator  # noqa: E402
from figure_file import save_figure  # noqa: E402

VERDICT_CODE = {"stable": 0, "decaying": 1, "singular": 2}
VERDICT_COLOURS = ["#4caf50", "#ff9800", "#d32f2f"]


def read(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def ratio_label(value):
    return str(Fraction(float(value)).limit_denominator(16))


FAMILY_ORDER = ["discontinuous", "standard", "standard-modified", "dual", "dual-modified"]


def panel_order(panel):
    """Panels by family (the paper's first), then by h/H from the largest."""
    family, ratio = panel
    return (FAMILY_ORDER.index(family) if family in FAMILY_ORDER else len(FAMILY_ORDER), family, -ratio)


def family_of(row):
    """The multiplier family of a row (files of sweeps without the column: the paper's)."""
    return row.get("family", "discontinuous")


def panel_title(family, ratio, families):
    """"h/H = 1/2", with the family in front when the sweep has several."""
    return (f"{family}\n" if len(families) > 1 else "") + f"h/H = {ratio_label(ratio)}"


def save(figure, path):
    save_figure(figure, path, dpi=110)


# One colour per p, one marker and line style per p_C: every curve is told apart on every panel.
P_COLOURS = plt.get_cmap("tab10").colors
PC_STYLES = [("o", "-"), ("s", "--"), ("^", "-."), ("D", ":"), ("v", "-"), ("P", "--"), ("X", "-."), ("*", ":")]


def curve_style(p, pc):
    marker, line = PC_STYLES[pc % len(PC_STYLES)]
    return {"color": P_COLOURS[(p - 1) % len(P_COLOURS)], "marker": marker, "linestyle": line}


def plot_alpha_vs_h(rows, folder):
    groups = defaultdict(list)
    for row in rows:
        key = (row["problem"], row["norm"], (family_of(row), float(row["ratio"])), int(row["p"]), int(row["pC"]))
        # h_min, the shortest edge on Γ_C: h on uniform meshes, the finest layer on graded ones.
        groups[key].append((float(row["h_min"]), float(row["alpha"])))
    families = sorted({key[2][0] for key in groups})
    panels = sorted({key[2] for key in groups}, key=panel_order)
    labels = {(key[0], key[3], key[4]) for key in groups}
    # As many legend columns as fit the figure's width (an entry takes about 1.5 inches).
    width = max(3.6 * len(panels), 6.0)
    columns = max(1, min(len(labels), int(width // 1.5)))
    legend_rows = -(-len(labels) // columns)
    height = 4.2 + 0.28 * legend_rows
    figure, axes = plt.subplots(1, len(panels), figsize=(width, height), squeeze=False, sharey=True)
    legend = {}
    for axis, panel in zip(axes[0], panels):
        for key, points in sorted(groups.items()):
            if key[2] != panel:
                continue
            points.sort()
            h, alpha = zip(*points)
            label = f"p = {key[3]}, $p_C$ = {key[4]}" + ("" if key[0] == "signorini" else f" ({key[0]})")
            (line,) = axis.loglog(h, [max(a, 1e-8) for a in alpha], markersize=4, linewidth=1,
                                  **curve_style(key[3], key[4]))
            legend.setdefault((key[3], key[4], key[0]), (label, line))
        axis.set_title(panel_title(panel[0], panel[1], families), fontsize=10)
        axis.set_xlabel(r"$h_{\min}$ (shortest edge on $\Gamma_C$)")
        axis.grid(True, which="both", alpha=0.3)
        # Ticks at the levels' h_min alone: log-scale minor labels (3×10⁻², 4×10⁻², …) overlap.
        levels = sorted({h for key, points in groups.items() if key[2] == panel for h, _ in points})
        axis.xaxis.set_major_locator(FixedLocator(levels))
        axis.xaxis.set_minor_locator(NullLocator())
        axis.xaxis.set_major_formatter(FixedFormatter([f"{h:.3g}" for h in levels]))
    axes[0][0].set_ylabel(r"inf-sup constant $\alpha$")
    # One legend for all panels, below them (the same p and p_C look the same everywhere).
    entries = [legend[key] for key in sorted(legend)]  # by p, then p_C
    figure.legend([line for _, line in entries], [label for label, _ in entries], loc="lower center",
                  ncol=columns, fontsize=8, bbox_to_anchor=(0.5, 0.0))
    figure.suptitle(r"inf-sup constant $\alpha$ against $h_{\min}$ (a positive slope: an unstable pairing)")
    figure.tight_layout(rect=(0, (0.28 * legend_rows + 0.1) / height, 1, 1))
    save(figure, folder / "alpha_vs_h.png")


def plot_stable_map(verdicts, folder):
    for (problem, norm) in sorted({(v["problem"], v["norm"]) for v in verdicts}):
        selected = [v for v in verdicts if v["problem"] == problem and v["norm"] == norm]
        families = sorted({family_of(v) for v in selected})
        panels = sorted({(family_of(v), float(v["ratio"])) for v in selected}, key=panel_order)
        p_min, p_max = min(int(v["p"]) for v in selected), max(int(v["p"]) for v in selected)
        pc_min, pc_max = min(int(v["pC"]) for v in selected), max(int(v["pC"]) for v in selected)
        width = 0.55 * (p_max - p_min + 1) + 1.0
        figure, axes = plt.subplots(1, len(panels), figsize=(max(width * len(panels) + 0.8, 4.5), 4.3),
                                    squeeze=False, sharey=True)
        shown = set()
        for axis, (family, ratio) in zip(axes[0], panels):
            grid = [[float("nan")] * (p_max + 1) for _ in range(pc_max + 1)]
            for v in selected:
                if family_of(v) == family and float(v["ratio"]) == ratio and v["verdict"] in VERDICT_CODE:
                    grid[int(v["pC"])][int(v["p"])] = VERDICT_CODE[v["verdict"]]
                    shown.add(v["verdict"])
            axis.imshow(grid, origin="lower", cmap=ListedColormap(VERDICT_COLOURS), vmin=0, vmax=2)
            axis.set_xlim(p_min - 0.5, p_max + 0.5)
            axis.set_ylim(pc_min - 0.5, pc_max + 0.5)
            axis.set_xticks(range(p_min, p_max + 1))
            axis.set_yticks(range(pc_min, pc_max + 1))
            axis.set_xlabel("p")
            axis.set_title(panel_title(family, ratio, families), fontsize=10)
        axes[0][0].set_ylabel(r"$p_C$ (degree of the multipliers)")
        # The verdicts that occur, below the panels (a legend inside would cover cells).
        entries = [(verdict, colour) for verdict, colour in zip(VERDICT_CODE, VERDICT_COLOURS) if verdict in shown]
        figure.legend([plt.Rectangle((0, 0), 1, 1, color=c) for _, c in entries], [v for v, _ in entries],
                      loc="lower center", ncol=len(entries), fontsize=9)
        figure.suptitle(f"stable pairings ({problem}, {norm} norm)")
        figure.tight_layout(rect=(0, 0.1, 1, 0.95))
        save(figure, folder / ("stable_map.png" if problem == "signorini" and norm == "interp"
                               else f"stable_map_{problem}_{norm}.png"))


def plot_alpha_vs_pi(rows, verdict_of, folder):
    figure, axis = plt.subplots(figsize=(6, 4.5))
    for verdict, colour in zip(VERDICT_CODE, VERDICT_COLOURS):
        points = [(float(r["Pi"]), max(float(r["alpha"]), 1e-8)) for r in rows
                  if verdict_of.get((r["problem"], r["norm"], r["p"], r["pC"], family_of(r),
                                     f'{float(r["ratio"]):.6g}')) == verdict]
        if points:
            axis.loglog(*zip(*points), "o", color=colour, markersize=3, alpha=0.7, label=verdict)
    axis.set_xlabel(r"$\Pi(h, H, p, p_C) = h H^{-1} \max(1,p_C)^2 p^{-1}$")
    axis.set_ylabel(r"$\alpha$")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend()
    axis.set_title(r"$\alpha$ against the indicator $\Pi$ of (20)")
    figure.tight_layout()
    save(figure, folder / "alpha_vs_pi.png")


def plot_modes(folder):
    files = sorted(folder.glob("mode_*.csv"))
    if not files:
        return
    figure, axes = plt.subplots(len(files), 1, figsize=(7, 1.9 * len(files)), squeeze=False)
    for axis, path in zip(axes[:, 0], files):
        rows = read(path)
        axis.plot([float(r["s"]) for r in rows], [float(r["mu"]) for r in rows], linewidth=1)
        axis.set_ylabel(r"mode $\mu$")
        # mode_p3_pC2_hH1-2.csv -> "p=3 pC=2 h/H=1/2"
        p, pc, ratio = path.stem.split("_")[1:4]
        axis.set_title(f"p={p[1:]}  pC={pc[2:]}  h/H={ratio[2:].replace('-', '/')}", fontsize=9)
        axis.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel(r"arc length $s$ along $\Gamma_C$")
    figure.suptitle("spurious multiplier modes (eigenvectors of the smallest eigenvalue)")
    figure.tight_layout()
    save(figure, folder / "modes.png")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    rows = read(folder / "alpha.csv")
    verdicts = read(folder / "verdicts.csv")
    verdict_of = {(v["problem"], v["norm"], v["p"], v["pC"], family_of(v), f'{float(v["ratio"]):.6g}'): v["verdict"]
                  for v in verdicts}
    plot_alpha_vs_h(rows, folder)
    plot_stable_map(verdicts, folder)
    plot_alpha_vs_pi(rows, verdict_of, folder)
    plot_modes(folder)


if __name__ == "__main__":
    main()
