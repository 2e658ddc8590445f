"""plots/plot_run.py, the one entry to a run's pictures, on the runs of every kind of scene: a
scalar run with the effect infsup, an elastic one and a contact pair of two bodies; each picture it
names is written, and plot_paper.py leaves an elastic problem to it with a message."""

import os
import subprocess
import sys

import hpcontact

SOURCE = os.environ["HPCONTACT_SOURCE_DIR"]
PLOTS = os.path.join(SOURCE, "plots")


def plot_run(folder):
    return subprocess.run([sys.executable, os.path.join(PLOTS, "plot_run.py"), str(folder)], capture_output=True,
                          text=True)


def run_into(tmp_path, name, scene, overrides, effects):
    out = tmp_path / name
    hpcontact.solve(os.path.join(SOURCE, scene), overrides, effects=effects, out=out)
    return out


def test_plot_run_draws_scalar_elastic_and_two_body_runs(tmp_path):
    scalar = run_into(tmp_path, "scalar", "studies/tutorial/block.toml", {"discretization.p": 2},
                      ["signorini", "infsup"])
    elastic = run_into(tmp_path, "elastic", "studies/elasticity/hertz.toml",
                       {"discretization.p": 2, "discretization.pC": 0, "domain.n_x": 16, "domain.n_y": 8,
                        "domain.grading_layers": 0},
                       ["frictionless"])
    pair = run_into(tmp_path, "pair", "studies/two_bodies/hertz.toml", {"discretization.p": 2, "discretization.pC": 0}, None)
    for folder, pictures in ((scalar, ["figure_signorini.png", "mode.png"]),
                             (elastic, ["figure_frictionless.png"]), (pair, ["figure_punch_frictionless.png"])):
        run = plot_run(folder)
        assert run.returncode == 0, run.stderr
        written = [line.split("/")[-1] for line in run.stdout.splitlines() if line.startswith("wrote ")]
        assert written == pictures, run.stdout
        for name in written:
            assert (folder / name).stat().st_size > 10_000
    paper = subprocess.run([sys.executable, os.path.join(PLOTS, "plot_paper.py"), str(elastic)], capture_output=True,
                           text=True)
    assert paper.returncode == 0 and "plot_run.py draws it" in paper.stdout


def test_plot_run_names_a_folder_that_is_no_run(tmp_path):
    run = plot_run(tmp_path)
    assert run.returncode != 0 and "no summary.json" in run.stderr
