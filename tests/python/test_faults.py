"""Faults met from Python: Ctrl-C during a long call raises KeyboardInterrupt within a second and
writes nothing; a geometry Gmsh cannot mesh, an integer too large, an output path that is a file
and a folder of another study are InputError; numpy's scalars and arrays are accepted as values."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import hpcontact

SOURCE = os.environ["HPCONTACT_SOURCE_DIR"]
FIGURE1 = os.path.join(SOURCE, "studies", "paper", "figure1_signorini.toml")
SQUARE = os.path.join(SOURCE, "studies", "stability", "square.toml")


def test_ctrl_c_interrupts_a_long_solve_within_a_second_and_writes_nothing(tmp_path):
    out = tmp_path / "out"
    script = textwrap.dedent("""
        import sys, time
        import hpcontact
        print("started", flush=True)
        try:
            hpcontact.solve(sys.argv[1], {"domain.n_x": 192, "domain.n_y": 192, "discretization.p": 4},
                            effects=["signorini", "infsup"], out=sys.argv[2])
            print("finished", flush=True)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic(), flush=True)
        """)
    child = subprocess.Popen([sys.executable, "-c", script, FIGURE1, str(out)], stdout=subprocess.PIPE, text=True,
                             env=os.environ)
    assert child.stdout.readline().strip() == "started"
    time.sleep(2.0)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    line = child.stdout.readline().split()
    child.wait(timeout=300)
    assert line and line[0] == "interrupted", "the solve ended before the interrupt: make it longer"
    assert float(line[1]) - sent < 1.0
    assert not out.exists()
    assert not any(p.name.startswith("out.tmp-") for p in tmp_path.iterdir())


def write_geo(tmp_path, loop):
    geo = tmp_path / "block.geo"
    geo.write_text("Point(1) = {0, 0, 0, 0.2};\nPoint(2) = {2, 0, 0, 0.2};\nPoint(3) = {0, 1, 0, 0.2};\n"
                   "Point(4) = {2, 1.5, 0, 0.2};\nLine(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\n"
                   "Line(4) = {4, 1};\nCurve Loop(1) = " + loop + ";\nPlane Surface(1) = {1};\n"
                   "Physical Curve(\"contact\") = {1};\nPhysical Curve(\"clamped\") = {3};\n"
                   "Physical Surface(\"block\") = {1};\n")
    return geo


def test_a_geometry_gmsh_cannot_mesh_is_an_input_error(tmp_path):
    scene = {"domain": {"mesh": str(write_geo(tmp_path, "{1, 2, 3, 4}"))},
             "boundary": {"contact_groups": ["contact"], "dirichlet_groups": ["clamped"]},
             "contact_mesh": {"ratio": 1}, "discretization": {"p": 2, "pC": 1},
             "data": {"f": "-1", "g": "-0.2"}, "run": {"effects": ["signorini"]}}
    with pytest.raises(hpcontact.InputError, match="Gmsh cannot mesh the geometry"):
        hpcontact.solve(scene)


def test_numpy_values_and_integers_out_of_range(tmp_path):
    plain = hpcontact.solve(FIGURE1, {"discretization.p": 2}, effects=["signorini"])
    for value in (np.int64(2), np.int32(2), np.uint8(2)):
        result = hpcontact.solve(FIGURE1, {"discretization.p": value}, effects=["signorini"])
        assert result.summary["signorini"]["energy"] == plain.summary["signorini"]["energy"]
    result = hpcontact.solve(FIGURE1, {"discretization.p": 2, "domain.x_max": np.float64(1.0)}, effects=["signorini"])
    assert result.summary["signorini"]["energy"] == plain.summary["signorini"]["energy"]
    with pytest.raises(hpcontact.InputError, match="an integer between"):
        hpcontact.solve(FIGURE1, {"discretization.p": 2**70})
    with pytest.raises(hpcontact.InputError, match=r"'domain.x_max' = nan"):
        hpcontact.solve(FIGURE1, {"domain.x_max": float("nan")})


def test_sweep_into_a_file_or_a_folder_of_another_study_is_an_input_error(tmp_path):
    def study(levels):
        path = tmp_path / ("study_%d.toml" % levels[0])
        path.write_text('[sweep]\nscene = "{}"\nlevels = {{ "domain.n_x" = {}, "domain.n_y" = {} }}\n'
                        'p = [2]\npC = [1]\nnorm = ["interp"]\nproblem = ["signorini"]\nfit_levels = 2\n'
                        .format(SQUARE, levels, levels))
        return path
    a_file = tmp_path / "a_file"
    a_file.write_text("x")
    with pytest.raises(hpcontact.InputError, match="--out"):
        hpcontact.sweep(study([8, 16]), out=a_file)
    hpcontact.sweep(study([8, 16]), out=tmp_path / "sweep")
    with pytest.raises(hpcontact.InputError, match="holds the rows of another study"):
        hpcontact.sweep(study([16, 32]), out=tmp_path / "sweep")
    alpha, _ = hpcontact.sweep(study([16, 32]), out=tmp_path / "sweep", restart=True)
    assert sorted(set(alpha["n"])) == [16, 32]
