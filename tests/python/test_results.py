"""Result files read from Python: every dataset with its unit, a table for pandas, and a
damaged file refused before HDF5 reads it."""

import shutil

import numpy as np
import pandas
import pytest

import caskdem
from conftest import SOURCE


@pytest.fixture(scope="module")
def result(command_line, tmp_path_factory):
    out = tmp_path_factory.mktemp("result") / "mixed.h5"
    command_line("ensemble", SOURCE / "tests/ensemble/data/mixed-outcomes.toml", "--out", out, "--no-plot", "--quiet")
    return out


def every_dataset(group, path=""):
    for name, item in group.items():
        if isinstance(item, caskdem.Group):
            yield from every_dataset(item, f"{path}{name}/")
        else:
            yield f"{path}{name}", group, name


def test_every_numeric_dataset_has_its_unit(result):
    r = caskdem.read_result(result)
    numeric = [(path, group, name) for path, group, name in every_dataset(r)
               if isinstance(group[name], np.ndarray) and group[name].dtype.kind in "fiub"]
    assert len(numeric) > 40
    assert [path for path, group, name in numeric if name not in group.units] == []
    assert r["realisations"].units["max_abs_rotation"] == "rad"
    assert r["limit_states"]["tip_over"].attrs["intensity_unit"] == "m/s^2"


def test_the_realisations_make_a_table(result):
    r = caskdem.read_result(result)
    table = pandas.DataFrame(r["realisations"])
    assert len(table) == r.attrs["realisations"] == 256
    assert table.groupby("motion")["status"].count().tolist() == [128, 128]


def test_a_damaged_file_is_refused(result, tmp_path):
    damaged = tmp_path / "damaged.h5"
    shutil.copy(result, damaged)
    with open(damaged, "r+b") as f:
        f.seek(damaged.stat().st_size // 2)
        byte = f.read(1)
        f.seek(-1, 1)
        f.write(bytes([byte[0] ^ 0xFF]))
    with pytest.raises(ValueError, match="damaged.h5"):
        caskdem.read_result(damaged)
    with pytest.raises(ValueError, match="nothing-here.h5"):
        caskdem.read_result(tmp_path / "nothing-here.h5")
