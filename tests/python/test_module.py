"""The Python module against the command-line tool and the library's own checks: scenes from files
and dicts, solve -> arrays, infsup -> alpha with its mode, sweep -> rows, errors with the same
messages. Run by CTest (Python.Module) with the build tree's python/ folder on PYTHONPATH."""

import json
import math
import os
import subprocess

import numpy as np
import pytest

import hpcontact

SOURCE = os.environ["HPCONTACT_SOURCE_DIR"]
CLI = os.environ["HPCONTACT_CLI"]
FIGURE1 = os.path.join(SOURCE, "studies", "paper", "figure1_signorini.toml")


def cli_summary(tmp_path, *arguments):
    out = tmp_path / "cli"
    subprocess.run([CLI, "solve", *arguments, "--out", str(out)], check=True, capture_output=True)
    return json.loads((out / "summary.json").read_text()), out


def test_solve_gives_the_command_line_results_as_arrays(tmp_path):
    result = hpcontact.solve(FIGURE1, {"discretization.p": 3}, effects=["signorini"])
    summary, out = cli_summary(tmp_path, FIGURE1, "--p", "3", "--effects", "signorini")
    assert result.summary["signorini"]["energy"] == summary["signorini"]["energy"]
    assert result.summary["signorini"]["solver"]["kkt_residual"] < 1e-12
    # The typed result carries the same numbers as fields.
    typed = result.run.contact("signorini")
    assert typed.energy == summary["signorini"]["energy"] and typed.solver.kkt_residual < 1e-12
    assert [c.problem for c in result.run.contacts] == ["signorini"] and result.run.infsup is None
    samples = result.boundary["signorini"]
    assert isinstance(samples["lambda"], np.ndarray) and samples["lambda"].dtype == np.float64
    # The same samples as the CLI's boundary CSV, to the last digit.
    cli_rows = np.genfromtxt(out / "boundary_signorini.csv", delimiter=",", names=True)
    for column in ("x", "u", "obstacle", "lambda", "s_arc"):
        np.testing.assert_array_equal(samples[column], cli_rows[column])
    # Signorini: u >= g where λ < 0 is active, λ <= 0 (the sign condition of M_-).
    assert samples["lambda"].max() <= 1e-12
    assert np.all(np.diff(samples["s_arc"]) >= 0)


def test_scene_from_a_dict_equals_the_file(tmp_path):
    tables = {
        "domain": {"n_x": 16, "n_y": 16},
        "boundary": {"contact": "abs(y + 1) < 1e-9",
                     "dirichlet": "abs(y - 1) < 1e-9 || (abs(x - 1) < 1e-9 && y > 0)"},
        "contact_mesh": {"ratio": "1/2"},
        "discretization": {"p": 2, "pC": 1},
        "data": {"f": "-1", "g": "-x^2"},
        "run": {"effects": ["signorini"]},
    }
    from_dict = hpcontact.solve(tables)
    from_file = hpcontact.solve(FIGURE1, effects=["signorini"])
    assert from_dict.summary["signorini"]["energy"] == from_file.summary["signorini"]["energy"]
    # Files only when asked for.
    hpcontact.solve(tables, out=tmp_path / "written")
    assert (tmp_path / "written" / "summary.json").exists()


def test_infsup_gives_alpha_its_error_and_the_mode():
    result = hpcontact.infsup(FIGURE1)
    assert 0.5 < result.alpha < 1.0
    assert result.alpha_error < 1e-4 and result.converged and result.unique
    assert set(result.mode) >= {"s"}
    assert len(result.mode["s"]) > 10
    # A triangle mesh of the same scene, through an override of the dict-free path.
    triangles = hpcontact.infsup(FIGURE1, {"domain.cells": "triangles"})
    assert 0.5 < triangles.alpha < result.alpha


def test_sweep_returns_alpha_rows_and_verdicts(tmp_path):
    study = tmp_path / "study.toml"
    study.write_text(
        '[sweep]\nscene = "{}"\nlevels = {{ "domain.n_x" = [8, 16], "domain.n_y" = [8, 16] }}\n'
        'p = [2]\npC = [1]\nratio = ["1/2", 1]\nnorm = ["interp"]\nproblem = ["signorini"]\nfit_levels = 2\n'
        .format(os.path.join(SOURCE, "studies", "stability", "square.toml")))
    alpha, verdicts = hpcontact.sweep(study)
    assert len(alpha["alpha"]) == 4
    assert np.all((alpha["alpha"] > 0) & (alpha["alpha"] <= 1))
    assert sorted(verdicts["verdict"]) == ["decaying", "stable"]


def test_bad_input_raises_input_error_with_the_cli_message(tmp_path):
    with pytest.raises(hpcontact.InputError) as error:
        hpcontact.solve(FIGURE1, {"discretization.p": 0})
    assert "discretization.p" in str(error.value)
    cli = subprocess.run([CLI, "solve", FIGURE1, "--p", "0", "--out", str(tmp_path / "x")], capture_output=True,
                         text=True)
    assert cli.returncode != 0
    assert str(error.value).split(": key")[1].split("\n")[0] in cli.stderr
    with pytest.raises(hpcontact.InputError, match="no_such_scene.toml"):
        hpcontact.solve("no_such_scene.toml")
    with pytest.raises(hpcontact.InputError, match="allowed are dicts"):
        hpcontact.solve({"domain": {"n_x": object()}})
    assert issubclass(hpcontact.InputError, ValueError)


def test_scene_keys_are_the_documented_ones():
    keys = {key["key"] for key in hpcontact.scene_keys()}
    assert {"domain.cells", "contact_mesh.ratio", "solve.constraint_points"} <= keys
    documented = open(os.path.join(SOURCE, "docs", "scene_keys.md")).read()
    for key in keys:
        assert "`" + key.split(".")[1] + "`" in documented


def test_list_overrides_reach_the_scene_per_zone():
    # Text and numbers mixed, as in a scene file: one ratio per contact zone of two_zones.toml.
    two_zones = os.path.join(SOURCE, "studies", "zones", "two_zones.toml")
    result = hpcontact.solve(two_zones, {"contact_mesh.ratio": ["1/2", 1], "solve.constraint_points": [2, 2]},
                             effects=["signorini"])
    assert result.summary["signorini"]["nmult"] == (4 + 8) * 2
    with pytest.raises(hpcontact.InputError, match="one per zone"):
        hpcontact.solve(two_zones, {"contact_mesh.ratio": [1, 1, 1]}, effects=["signorini"])


def test_a_list_of_pairs_override_grades_the_mesh_as_the_file_does(tmp_path):
    # domain.grading_points as a list of lists and as a 2-D numpy array, against the same key in the file.
    scene = os.path.join(SOURCE, "studies", "paper", "figure1_signorini.toml")
    text = open(scene).read().replace("[domain]\n", "[domain]\ngrading_points = [[0.5, -1.0]]\ngrading_layers = 3\n", 1)
    graded = tmp_path / "graded.toml"
    graded.write_text(text)
    in_file = hpcontact.solve(str(graded), effects=["signorini"]).summary["signorini"]["energy"]
    for points in ([[0.5, -1.0]], np.array([[0.5, -1.0]])):
        result = hpcontact.solve(scene, {"domain.grading_points": points, "domain.grading_layers": 3},
                                 effects=["signorini"])
        assert result.summary["signorini"]["energy"] == in_file
    ungraded = hpcontact.solve(scene, effects=["signorini"]).summary["signorini"]["energy"]
    assert ungraded != in_file
    # One-dimensional arrays and numpy scalars in a list stay lists of numbers.
    two_zones = os.path.join(SOURCE, "studies", "zones", "two_zones.toml")
    for points in (np.array([2, 2]), [np.int64(2), 2]):
        result = hpcontact.solve(two_zones, {"solve.constraint_points": points}, effects=["signorini"])
        assert result.summary["signorini"]["nmult"] > 0
    result = hpcontact.solve(scene, {"domain.grading_points": [np.array([0.5, -1.0])], "domain.grading_layers": 3},
                             effects=["signorini"])
    assert result.summary["signorini"]["energy"] == in_file


def test_an_unstable_pairing_warns_and_advise_recommends_what_infsup_confirms(tmp_path):
    # p = 4, p_C = 3 on T_h's edges: predicted unstable, a StabilityWarning naming the alternative.
    with pytest.warns(hpcontact.StabilityWarning, match=r"Stable alternative: \[discretization\] pC = 2"):
        result = hpcontact.solve(FIGURE1, {"discretization.p": 4, "discretization.pC": 3, "contact_mesh.ratio": 1},
                                 effects=["signorini"])
    assert not result.run.stability.stable and result.summary["stability"]["warned"]
    assert result.run.stability.alternative.edit == "[discretization] pC = 2"
    # advise: advice.csv written, its recommended row's α is hpcontact infsup's of that row.
    advice = hpcontact.advise(FIGURE1, out=tmp_path / "advice")
    assert (tmp_path / "advice" / "advice.csv").exists()
    best = advice.recommended
    assert best["alpha_predicted"] >= advice.alpha_min and advice.edits
    cli = subprocess.run([CLI, "infsup", "--scene", FIGURE1, "--pc", str(int(best["pC"])), "--ratio", best["ratio"],
                          "--family", best["family"]], check=True, capture_output=True, text=True).stdout
    assert float(cli.split("alpha = ")[1].split()[0]) == best["alpha"]


def test_numbers_in_expression_keys_typos_and_a_clean_namespace():
    # An expression key takes a number as well as its text, and gives the same run.
    as_number = hpcontact.solve(FIGURE1, {"data.f": -1.0}, effects=["signorini"])
    as_text = hpcontact.solve(FIGURE1, {"data.f": "-1"}, effects=["signorini"])
    assert as_number.summary["signorini"]["energy"] == as_text.summary["signorini"]["energy"]
    # One effect given as a name, not a list, is that effect (not its letters).
    assert hpcontact.solve(FIGURE1, {"data.f": -1.0}, effects="signorini").summary["effects"] == ["signorini"]
    # A misspelt override names the key meant.
    with pytest.raises(hpcontact.InputError, match=r"did you mean 'discretization.pC'"):
        hpcontact.scene(FIGURE1, {"discretization.pc": 2})
    # The module exports its API, not the modules it uses.
    for name in ("np", "os", "csv", "tempfile", "warnings", "dataclass", "field"):
        assert not hasattr(hpcontact, name), name
    assert set(hpcontact.__all__) <= set(dir(hpcontact))


def test_a_three_dimensional_scene_gives_its_samples_and_hexahedra(tmp_path):
    scene = os.path.join(SOURCE, "studies", "three_d", "extruded_signorini.toml")
    result = hpcontact.solve(scene, effects=["signorini"])
    summary, _ = cli_summary(tmp_path, scene, "--effects", "signorini")
    assert result.run.dimension == 3 and result.run.faces_on_contact == 16
    assert result.summary["signorini"]["energy"] == summary["signorini"]["energy"]
    samples = result.boundary["signorini"]
    # The weights integrate over Γ_C = [-1, 1] x [0, 0.5]; λ ≤ 0 everywhere (p_C = 1, nodal bounds).
    assert abs(samples["w"].sum() - 1.0) < 1e-13
    assert samples["lambda"].max() <= 1e-12
    fields = result.fields["signorini"]
    assert set(np.unique(fields["types"])) == {12}  # linear hexahedra, p³ per cell
    assert len(fields["types"]) == 8 * 2 * 8 * 2**3
    assert fields["points"].shape == (len(fields["u"]), 3)
