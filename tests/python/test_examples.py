"""The examples of docs/python.md run as written (smaller), and the module documents itself."""

import os
import subprocess
import sys

import pandas

from conftest import SOURCE


def run_example(name, *arguments, cwd):
    return subprocess.run([sys.executable, str(SOURCE / "examples" / name), *map(str, arguments)], cwd=cwd,
                          capture_output=True, text=True, env=dict(os.environ), timeout=600)


def test_help_shows_rollouts_parameters():
    shown = subprocess.run([sys.executable, "-c", "import caskdem; help(caskdem.rollout)"], capture_output=True,
                           text=True, env=dict(os.environ, PAGER="cat"), check=True).stdout
    for word in ("friction_static", "restitution", "eccentricity", "KeyboardInterrupt", "SI"):
        assert word in shown


def test_the_custom_latin_hypercube_fits_and_plots(tmp_path):
    done = run_example("custom_lhs.py", "--per-stripe", 16, "--out", tmp_path, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "tip-over fragility: median" in done.stdout and "model-scale" in done.stdout
    assert (tmp_path / "fragility.png").stat().st_size > 10_000


def test_the_sobol_study_runs_and_its_indices_bracket_as_they_must(tmp_path):
    done = run_example("sobol_openturns.py", "--base-size", 48, "--levels", 6, "--out", tmp_path, cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    table = pandas.read_csv(tmp_path / "sobol-indices.csv")
    assert len(table) == 8 and set(table["input"]) == {"friction", "restitution", "eccentricity", "record"}
    assert (table["first_lower"] <= table["first_order"]).all() and (table["total"] <= table["total_upper"]).all()


def test_a_result_file_reads_into_pandas(command_line, tmp_path):
    out = tmp_path / "mixed.h5"
    command_line("ensemble", SOURCE / "tests/ensemble/data/mixed-outcomes.toml", "--out", out, "--no-plot", "--quiet")
    done = run_example("read_result.py", out, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "256 realisations" in done.stdout and "tip_over: median" in done.stdout
    missing = run_example("read_result.py", tmp_path / "none.h5", cwd=tmp_path)
    assert missing.returncode == 2 and "none.h5" in missing.stderr


def test_the_docs_list_every_rollout_parameter_with_its_unit():
    import caskdem

    page = (SOURCE / "docs/python.md").read_text()
    for name, unit, meaning in caskdem.rollout_parameters():
        row = next((line for line in page.splitlines() if line.startswith(f"| `{name}` |")), None)
        assert row is not None, name
        shown = row.split("|")[2].strip()
        assert shown == unit or (unit == "1" and name == "motion" and shown == "index"), (name, unit, shown)


def readme_blocks(section):
    """The code blocks of a README section, by language."""
    blocks, language, lines, inside = [], None, [], False
    for line in (SOURCE / "README.md").read_text().splitlines():
        if line.startswith("## "):
            inside = line == f"## {section}"
            continue
        if not inside:
            continue
        if line.startswith("```"):
            if language is None:
                language, lines = line[3:].strip(), []
            else:
                blocks.append((language, "\n".join(lines)))
                language = None
        elif language is not None:
            lines.append(line)
    return blocks


def test_the_readmes_python_lines_run_as_written():
    blocks = readme_blocks("From Python")
    assert [language for language, _ in blocks] == ["sh", "python"]
    command = blocks[0][1].strip()
    assert command.startswith("python3 -c ")
    shown = subprocess.run([sys.executable, "-c", command.split('"')[1]], cwd=SOURCE, capture_output=True, text=True,
                           env=dict(os.environ, PAGER="cat"))
    assert shown.returncode == 0 and "rollout" in shown.stdout, shown.stderr
    ran = subprocess.run([sys.executable, "-c", blocks[1][1]], cwd=SOURCE, capture_output=True, text=True,
                         env=dict(os.environ), timeout=300)
    assert ran.returncode == 0, ran.stderr
    probability, unit = ran.stdout.split()
    assert 0.0 < float(probability) < 1.0 and unit == "m"
