"""Fragility fits and site risk from Python: the ensemble's own numbers for its own data, a
known curve recovered from outcomes drawn from it, and the closed form of a power-law hazard."""

import numpy as np
import pytest
from scipy_free_normal import normal_cdf, normal_quantile

import caskdem
from conftest import SOURCE, bits


@pytest.fixture(scope="module")
def stored(command_line, tmp_path_factory):
    out = tmp_path_factory.mktemp("fit") / "mixed.h5"
    command_line("ensemble", SOURCE / "tests/ensemble/data/mixed-outcomes.toml", "--out", out, "--no-plot", "--quiet")
    return caskdem.read_result(out)


def test_the_ensembles_data_give_the_ensembles_curve_band_and_test(stored):
    r = stored["realisations"]
    state = stored["limit_states"]["tip_over"]
    # A cask on its side, off the floor or off its pad exceeds every limit state; non-finite runs count in none.
    counted = r["status"] != 4
    exceeded = np.isin(r["status"], [1, 2, 3])
    fit = caskdem.fit_fragility(r["level"][counted], exceeded[counted], r["motion"][counted],
                                bootstrap=int(stored.attrs.get("bootstrap_replicates", 50)), seed=7)
    assert fit["fitted"]
    assert fit["median"] == state.attrs["median"] and fit["beta"] == state.attrs["log_std"]
    assert np.array_equal(fit["stripes"]["count"], state["count"])
    assert np.array_equal(bits(fit["stripes"]["upper"]), bits(state["probability_upper"]))
    assert np.array_equal(bits(fit["band"]["lower"]), bits(state["band_lower"]))
    assert fit["test"]["p_value"] == state.attrs["fit_test_p_value"]
    assert fit["test"]["record_to_record"] == state.attrs["record_to_record"]
    assert fit["rejected"] == bool(state.attrs["fit_rejected"])


def test_a_known_curve_is_recovered_from_outcomes_drawn_from_it():
    rng = np.random.default_rng(2024)
    median, beta = 0.5 * caskdem.G, 0.4
    levels = np.repeat(median * np.exp(np.linspace(-2.0, 2.0, 10) * beta), 400)
    exceeded = rng.random(levels.size) < normal_cdf(np.log(levels / median) / beta)
    fit = caskdem.fit_fragility(levels, exceeded, bootstrap=50)
    # Standard errors here are about 0.01 in ln(median) and in beta.
    assert abs(np.log(fit["median"] / median)) < 0.05 and abs(fit["beta"] - beta) < 0.05
    assert not fit["rejected"] and fit["band"]["resampled"] == "realisations"
    # The band covers the true curve at the median.
    k = np.argmin(np.abs(fit["band"]["intensity"] - median))
    assert fit["band"]["lower"][k] <= 0.5 <= fit["band"]["upper"][k]


def test_outcomes_that_cannot_identify_a_curve_say_why():
    fit = caskdem.fit_fragility([1.0, 1.0, 2.0, 2.0], [0, 0, 0, 0])
    assert not fit["fitted"] and fit["median"] is None and fit["reason"]


@pytest.mark.parametrize("arguments, words", [
    (([1.0, 2.0], [0, 1, 1]), ["one value each per realisation"]),
    (([1.0, -2.0], [0, 1]), ["level", "positive"]),
    (([1.0, 2.0], [0, 2]), ["exceeded", "0 or 1"]),
    (([1.0, 2.0], [0, 1], [0, -1]), ["motion", "non-negative"]),
])
def test_bad_outcomes_raise_a_value_error(arguments, words):
    with pytest.raises(ValueError) as raised:
        caskdem.fit_fragility(*arguments)
    for word in words:
        assert word in str(raised.value)


def power_law(k0, k):
    intensity = np.geomspace(1e-3, 1e3, 400)
    return intensity, k0 * intensity ** -k


def test_a_power_law_hazard_gives_its_closed_form():
    """For H(a) = k0 a^-k the annual frequency of a lognormal curve is H(A_m) exp(k^2 beta^2 / 2)
    (Kennedy and Ravindra 1984); the member curves' fractiles likewise, at A_m exp(beta_U z)."""
    k0, k = 1e-4, 2.2
    median, beta_r, beta_u = 6.0, 0.35, 0.25
    intensity, frequency = power_law(k0, k)
    r = caskdem.annual_frequency(median, beta_r, beta_u=beta_u, intensity=intensity, frequency=frequency)
    beta_c = np.hypot(beta_r, beta_u)
    assert r["mean"] == pytest.approx(k0 * median ** -k * np.exp(0.5 * (k * beta_c) ** 2), rel=1e-9)
    assert r["median"] == pytest.approx(k0 * median ** -k * np.exp(0.5 * (k * beta_r) ** 2), rel=1e-9)
    for q, name in ((0.05, "fractile_05"), (0.95, "fractile_95")):
        member = median * np.exp(beta_u * normal_quantile(1.0 - q))
        assert r[name] == pytest.approx(k0 * member ** -k * np.exp(0.5 * (k * beta_r) ** 2), rel=1e-6)
    # EPRI TR-103959: 95 % confidence of at most 5 % failure, and the composite curve's 1 % point.
    z95, z99 = normal_quantile(0.95), normal_quantile(0.99)
    assert r["hclpf_conservative"] == pytest.approx(median * np.exp(-z95 * (beta_r + beta_u)), rel=1e-12)
    assert r["hclpf_composite"] == pytest.approx(median * np.exp(-z99 * beta_c), rel=1e-12)
    assert r["hclpf_lower"] == min(r["hclpf_conservative"], r["hclpf_composite"])


def test_without_an_epistemic_spread_the_fractiles_are_not_sampled():
    intensity, frequency = power_law(1e-4, 2.0)
    r = caskdem.annual_frequency(6.0, 0.4, intensity=intensity, frequency=frequency)
    assert r["fractile_05"] is None and r["fractile_95"] is None


def test_a_hazard_file_of_another_measure_is_refused():
    with pytest.raises(ValueError, match="PGV"):
        caskdem.annual_frequency(6.0, 0.4, measure="PGA", hazard=SOURCE / "hazard/example-site-pgv.csv")
    r = caskdem.annual_frequency(0.5, 0.4, measure="PGV", hazard=SOURCE / "hazard/example-site-pgv.csv")
    assert r["measure"] == "PGV" and r["unit"] == "m/s" and r["mean"] > 0.0
