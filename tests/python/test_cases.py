"""Cases from Python: load_case, case(**tables) and run, against the command line's own output
for the same file and against rocking theory."""

import json

import numpy as np
import pandas
import pytest
import tomllib

import caskdem
from conftest import SOURCE

PULSE = SOURCE / "cases/default-pulse.toml"


def test_a_run_gives_the_command_lines_summary_and_histories(command_line, tmp_path):
    command_line("run", PULSE, "--out", tmp_path, "--no-plot")
    stored = json.loads((tmp_path / "summary.json").read_text())
    run = caskdem.run(caskdem.load_case(PULSE))
    assert run.summary.keys() == stored.keys()
    for key, value in stored.items():
        if key != "wall_time_s":
            assert run.summary[key] == value, key
    history = pandas.read_csv(tmp_path / "history.csv")
    assert list(run.history) == list(history.columns)
    for name in history.columns:
        np.testing.assert_allclose(run.history[name], history[name], rtol=1e-9, atol=1e-12 * np.max(np.abs(history[name])))
    assert run.history.units["rotation_rad"] == "rad" and run.history.units["table_acceleration_m_s2"] == "m/s^2"


def test_keyword_tables_read_as_the_file_does():
    with open(PULSE, "rb") as f:
        tables = tomllib.load(f)
    from_file = caskdem.run(caskdem.load_case(PULSE), output_interval=0)
    from_tables = caskdem.run(caskdem.case(**tables), output_interval=0)
    for key, value in from_file.summary.items():
        if key not in ("wall_time_s", "case_file"):
            assert from_tables.summary[key] == value, key
    assert from_tables.summary["case_file"] == "keyword arguments"
    assert from_file.history.get("time_s") is None or len(from_file.history["time_s"]) <= 1


def test_a_pulse_below_g_tan_alpha_does_not_rock_the_cask_and_one_above_does():
    """Housner (1963): uplift needs a table acceleration of g tan(alpha); the built-in case's
    0.35 g pulse is above the 1/3 model's 0.23 g."""
    above = caskdem.run(caskdem.load_case(PULSE), output_interval=0).summary
    tan_alpha = np.tan(above["stability_angle_rad"])
    assert 0.35 > tan_alpha and above["max_uplift_m"] > 1e-3 and not above["tipped_over"]
    below = caskdem.run(caskdem.case(PULSE, motion={"amplitude": f"{0.8 * tan_alpha} g"}), output_interval=0).summary
    assert below["max_rotation_ratio"] < 0.02 and below["max_uplift_m"] < 1e-4


def test_a_misspelt_key_is_named_with_what_was_meant():
    with open(PULSE, "rb") as f:
        tables = tomllib.load(f)
    tables["cask"]["diamter"] = tables["cask"].pop("diameter")
    with pytest.raises(ValueError) as raised:
        caskdem.case(**tables)
    message = str(raised.value)
    assert message.startswith("keyword arguments: ") and "cask.diameter" in message and "is diamter" in message
    assert "line" not in message  # keyword arguments have no lines


@pytest.mark.parametrize("cask, words", [
    ({"diameter": object()}, ["cask.diameter", "object"]),
    ({"diameter": None}, ["cask.diameter", "leave the key out"]),
    ({"diameter": "95 kg"}, ["cask.diameter", "length"]),
    ({"diameter": -1.0}, ["cask.diameter"]),
])
def test_a_bad_value_is_named(cask, words):
    with pytest.raises(ValueError) as raised:
        caskdem.case(PULSE, cask=cask)
    for word in words:
        assert word in str(raised.value), str(raised.value)


def test_a_missing_file_says_so():
    with pytest.raises(ValueError, match="no-such-case.toml"):
        caskdem.load_case(SOURCE / "no-such-case.toml")
    with pytest.raises(ValueError, match="no-such-case.toml"):
        caskdem.case(SOURCE / "no-such-case.toml", motion={"amplitude": "0.1 g"})


def test_a_3d_case_runs_to_rest_as_the_command_line_does(command_line, tmp_path):
    case_file = SOURCE / "cases/full-scale-3d.toml"
    command_line("run", case_file, "--out", tmp_path, "--no-plot")
    stored = json.loads((tmp_path / "summary.json").read_text())
    run = caskdem.run(caskdem.load_case(case_file))
    for key, value in stored.items():
        if key != "wall_time_s":
            assert run.summary[key] == value, key
    assert "slip_m" in run.history and run.history.units["slip_m"] == "m"
