"""caskdem.rollout: the caller's realisations on the ensemble engine.

What it is checked against: the command line's result file (the same realisations, bit for
bit), rocking theory (no uplift below g tan alpha), its own rows reordered (a row's result
depends on nothing else), and the errors a caller can make."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import caskdem
from conftest import SOURCE, bits


def result_file(command_line, ensemble_file, tmp_path, *options):
    out = tmp_path / "result.h5"
    command_line("ensemble", ensemble_file, "--out", out, "--no-plot", "--quiet", *options)
    return caskdem.read_result(out)["realisations"]


@pytest.mark.parametrize("name", ["mixed-outcomes", "mixed-outcomes-3d"])
def test_the_files_realisations_give_the_command_lines_bits(name, command_line, tmp_path):
    ensemble_file = SOURCE / f"tests/ensemble/data/{name}.toml"
    stored = result_file(command_line, ensemble_file, tmp_path, "--threads", "1")
    ensemble = caskdem.load_ensemble(ensemble_file)
    # Another thread count and instruction set than the command line's: the same bits.
    ran = caskdem.rollout(ensemble, caskdem.realisations(ensemble), threads=2, isa="sse2")
    compared = [k for k in ran if k in stored and k != "level"]
    assert len(compared) >= 18
    for key in compared:
        assert np.array_equal(bits(ran[key]), bits(stored[key])), key
        assert ran.units[key] == stored.units[key], key
    # level is the intensity of the motion as scaled: the stripe's level to rounding.
    np.testing.assert_allclose(ran["level"], stored["level"], rtol=1e-14)
    assert set(np.unique(ran["status"])) >= {0, 1}, "the ensemble should both stand and tip over"


def test_a_stripes_level_gives_the_files_scale(mixed_outcomes, command_line, tmp_path):
    stored = result_file(command_line, SOURCE / "tests/ensemble/data/mixed-outcomes.toml", tmp_path)
    columns = caskdem.realisations(mixed_outcomes)
    del columns["scale_factor"]
    columns["level"] = stored["level"]
    ran = caskdem.rollout(mixed_outcomes, columns)
    assert np.array_equal(bits(ran["scale_factor"]), bits(stored["scale_factor"]))
    assert np.array_equal(bits(ran["max_abs_rotation"]), bits(stored["max_abs_rotation"]))


def test_each_row_depends_on_its_own_parameters_only(mixed_outcomes):
    columns = caskdem.realisations(mixed_outcomes)
    ran = caskdem.rollout(mixed_outcomes, columns)
    order = np.random.default_rng(7).permutation(len(columns["motion"]))[:50]
    subset = {k: np.asarray(v)[order] for k, v in columns.items()}
    again = caskdem.rollout(mixed_outcomes, subset, threads=1, isa="scalar")
    for key in ("status", "max_abs_rotation", "max_abs_slide", "end_time"):
        assert np.array_equal(bits(again[key]), bits(np.asarray(ran[key])[order])), key


def test_no_rocking_below_g_tan_alpha(mixed_outcomes):
    """Rocking theory (Housner 1963): a rigid block with enough friction does not uplift while the
    table's acceleration stays below g tan(alpha). The spring contacts only rotate elastically."""
    e = mixed_outcomes
    assert e.nominal["friction_static"] > np.tan(e.stability_angle)
    g_tan_alpha = caskdem.G * np.tan(e.stability_angle)
    pga = e.motion_intensities["pga"]
    motion = np.repeat(np.arange(len(pga)), 20)
    fraction = np.tile(np.linspace(0.1, 0.8, 20), len(pga))
    ran = caskdem.rollout(e, motion=motion, scale_factor=fraction * g_tan_alpha / pga[motion])
    assert np.all(ran["status"] == 0)
    assert np.max(ran["max_rotation_ratio"]) < 0.02
    assert np.max(ran["max_abs_slide"]) < 1e-3
    # Well above it the same cask rocks.
    strong = caskdem.rollout(e, motion=np.arange(len(pga)), scale_factor=3.0 * g_tan_alpha / pga)
    assert np.all(strong["max_rotation_ratio"] > 0.05)


def test_parameters_not_given_keep_the_nominal_values(mixed_outcomes):
    nominal = mixed_outcomes.nominal
    plain = caskdem.rollout(mixed_outcomes, motion=[0, 1], scale_factor=[2.0, 2.0])
    explicit = caskdem.rollout(mixed_outcomes, motion=[0, 1], scale_factor=2.0,
                               friction_static=nominal["friction_static"], friction_kinetic=nominal["friction_kinetic"],
                               damping_ratio=nominal["damping_ratio"], mass=nominal["mass"],
                               centre_height=nominal["centre_height"], eccentricity=0.0)
    for key in ("status", "max_abs_rotation", "max_abs_slide", "max_uplift"):
        assert np.array_equal(bits(plain[key]), bits(explicit[key])), key
    assert np.all(explicit["eccentricity"] == 0.0) and explicit.units["eccentricity"] == "m"


def test_an_eccentric_centre_of_mass_tips_more_easily(mixed_outcomes):
    """Moving the centre of mass towards one edge lowers that side's stability angle: over many
    realisations at one intensity it cannot tip fewer casks (it does tip more)."""
    e = mixed_outcomes
    rows = 200
    motion = np.arange(rows) % len(e.motion_names)
    level = np.full(rows, 1.2 * caskdem.G)
    friction = np.linspace(0.3, 0.7, rows)
    centred = caskdem.rollout(e, motion=motion, level=level, friction_static=friction)
    half_width = e.nominal["centre_height"] * np.tan(e.stability_angle)
    shifted = caskdem.rollout(e, motion=motion, level=level, friction_static=friction, eccentricity=0.3 * half_width)
    assert shifted["tipped_over"].sum() > centred["tipped_over"].sum()


@pytest.mark.parametrize("parameters, words", [
    ({"frction_static": 0.5, "scale_factor": 1.0, "motion": 0}, ["frction_static", "did you mean friction_static"]),
    ({"motion": 0}, ["scale_factor or level"]),
    ({"motion": 0, "scale_factor": 1.0, "level": 3.0}, ["scale_factor or level"]),
    ({"scale_factor": 1.0}, ["motion", "2 motions"]),
    ({"motion": [0, 1, 2], "scale_factor": 1.0}, ["motion, row 2", "0 to 1"]),
    ({"motion": [0, 1], "scale_factor": [1.0, 2.0, 3.0]}, ["scale_factor", "one per realisation"]),
    ({"motion": 0, "scale_factor": float("nan")}, ["scale_factor", "finite"]),
    ({"motion": 0, "scale_factor": -1.0}, ["scale_factor, row 0", "positive"]),
    ({"motion": 0, "scale_factor": 1.0, "mass": 1.0}, ["mass, row 0", "lightest"]),
    ({"motion": 0, "scale_factor": 1.0, "restitution": 0.999}, ["restitution, row 0", "calibrated range"]),
    ({"motion": 0, "scale_factor": 1.0, "restitution": 0.9, "damping_ratio": 0.05}, ["restitution or damping_ratio"]),
    ({"motion": 0, "scale_factor": 1.0, "damping_ratio": 50.0}, ["damping_ratio, row 0", "stable"]),
    ({"motion": 0, "scale_factor": 1.0, "incidence": 0.5}, ["incidence", "3D"]),
    ({"motion": 0, "scale_factor": 1.0, "eccentricity": 5.0}, ["eccentricity, row 0", "over the base"]),
    ({"motion": 0, "scale_factor": 1.0, "centre_height": 0.0}, ["centre_height, row 0", "inside the cask"]),
    ({"motion": 0, "scale_factor": "large"}, ["scale_factor", "numbers"]),
    ({"motion": 0, "scale_factor": [[1.0]]}, ["scale_factor", "one-dimensional"]),
])
def test_bad_parameters_raise_a_value_error_naming_them(mixed_outcomes, parameters, words):
    with pytest.raises(ValueError) as raised:
        caskdem.rollout(mixed_outcomes, parameters)
    for word in words:
        assert word in str(raised.value), str(raised.value)


@pytest.mark.parametrize("option, words", [
    ({"device": "gpu"}, ["device", "gpu"]),
    ({"isa": "neon"}, ["isa", "neon"]),
    ({"threads": -1}, ["threads"]),
])
def test_bad_options_raise_a_value_error_naming_them(mixed_outcomes, option, words):
    with pytest.raises(ValueError) as raised:
        caskdem.rollout(mixed_outcomes, motion=0, scale_factor=1.0, **option)
    for word in words:
        assert word in str(raised.value), str(raised.value)


def test_progress_reports_every_realisation_and_may_stop_the_run(mixed_outcomes):
    calls = []
    caskdem.rollout(mixed_outcomes, caskdem.realisations(mixed_outcomes), progress=lambda d, n: calls.append((d, n)))
    assert calls and calls[-1] == (mixed_outcomes.size, mixed_outcomes.size)
    assert all(a[0] <= b[0] for a, b in zip(calls, calls[1:]))

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop

    with pytest.raises(Stop):
        caskdem.rollout(mixed_outcomes, caskdem.realisations(mixed_outcomes), progress=stop)
    assert caskdem.rollout(mixed_outcomes, motion=0, scale_factor=1.0)["status"][0] == 0  # still usable


def long_rows(ensemble, rows=4000):
    """Enough realisations (a few seconds' work) that a run is still going when it is interrupted."""
    return {"motion": np.arange(rows) % 2, "scale_factor": np.full(rows, 0.05)}


def test_the_gil_is_released_while_it_runs(mixed_outcomes):
    ticks = []
    running = threading.Event()

    def count():
        running.set()
        while len(ticks) < 10_000_000 and not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    stop = threading.Event()
    worker = threading.Thread(target=count)
    worker.start()
    running.wait()
    before = len(ticks)
    caskdem.rollout(mixed_outcomes, long_rows(mixed_outcomes, 1500), threads=1)
    during = len(ticks) - before
    stop.set()
    worker.join()
    assert during > 20, "another Python thread should run while rollout computes"


def test_ctrl_c_stops_the_run_with_keyboard_interrupt(mixed_outcomes):
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        caskdem.rollout(mixed_outcomes, long_rows(mixed_outcomes, 40_000))
    assert time.monotonic() - started < 10.0
    timer.join()
    assert caskdem.rollout(mixed_outcomes, motion=1, scale_factor=1.0)["status"][0] == 0


def resident_kib():
    with open("/proc/self/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith("VmRSS:"))


def test_a_long_loop_of_calls_does_not_grow(mixed_outcomes):
    rows = {"motion": [0, 1] * 4, "scale_factor": np.linspace(0.5, 4.0, 8), "restitution": 0.95}
    for _ in range(30):  # warm: tables, calibration, allocator pools
        caskdem.rollout(mixed_outcomes, rows)
    before = resident_kib()
    for _ in range(300):
        caskdem.rollout(mixed_outcomes, rows)
        caskdem.realisations(mixed_outcomes)
    grown = resident_kib() - before
    assert grown < 4 * 1024, f"resident memory grew by {grown} KiB over 300 calls"


def test_calls_from_two_threads_on_one_ensemble_take_turns_and_agree(mixed_outcomes):
    rows = caskdem.realisations(mixed_outcomes)
    alone = caskdem.rollout(mixed_outcomes, rows)
    results = [None, None]

    def call(k):
        results[k] = caskdem.rollout(mixed_outcomes, rows, threads=1, isa="sse2" if k else "automatic")

    threads = [threading.Thread(target=call, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for ran in results:
        assert np.array_equal(bits(ran["max_abs_rotation"]), bits(alone["max_abs_rotation"]))
