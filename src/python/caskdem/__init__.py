"""caskdem from Python: the seismic response of a free-standing cask, one run or thousands.

The same library as the ``caskdem`` command line, reached without files or processes:

* ``load_case(file)`` / ``case(**tables)``: a case, from its TOML file or from keyword arguments
  named as the file's tables (``cask={...}, motion={...}``); the same keys, units and checks.
* ``run(case)``: one analysis; its summary (a dict, as summary.json) and histories (arrays).
* ``load_ensemble(file)`` / ``ensemble(**tables)``: an ensemble (cask, motions, intensity
  measure); ``ensemble(file, **tables)`` replaces some of a file's tables.
* ``realisations(ensemble)``: the realisations the ensemble file draws, as columns.
* ``rollout(ensemble, parameters)``: any realisations you choose, run together on the ensemble
  engine (SIMD lanes and threads, or a GPU), outcomes as arrays in your order.
* ``fit_fragility(level, exceeded, motion)``: the ensemble's lognormal fit, band and fit test.
* ``annual_frequency(median, beta_r, hazard=...)``: the risk command's convolution.
* ``read_result(file)``: a result file of ``caskdem ensemble`` as nested dicts of arrays.

Units: SI throughout (m, s, kg, rad, m/s^2), both ways. A number given where a file takes a
quantity may also be a string with its unit, as in the files ("0.6 g", "40 cm/s"). Arrays come
back in ``Columns``, a dict whose ``units`` attribute names each array's unit ("1": none).

Bad input raises ValueError with the message the command line would print.
"""

from __future__ import annotations

import pathlib
import tomllib
from typing import Callable, Mapping, Optional

from . import _caskdem as _native

__version__ = _native.__version__
__all__ = [
    "Case", "Ensemble", "Columns", "Run", "STATUS", "G",
    "load_case", "case", "run", "load_ensemble", "ensemble", "realisations", "rollout",
    "rollout_parameters", "fit_fragility", "annual_frequency", "read_result",
]

Case = _native.Case
Ensemble = _native.Ensemble

#: Outcome codes of the ``status`` column: 0 completed (ran to the end standing), 1 tipped
#: over, 2 left the floor, 3 slid off its pad, 4 non-finite (reported, never counted).
STATUS = dict(_native.STATUS)

#: Standard gravity, m/s^2: ``0.6 * caskdem.G`` is 0.6 g in SI.
G = 9.80665


class Columns(dict):
    """Arrays by name, one entry per realisation or sample; ``units[name]`` is each one's SI unit.

    A plain dict otherwise: ``pandas.DataFrame(columns)`` makes a table of it.
    """

    def __init__(self, arrays=(), units: Optional[Mapping[str, str]] = None):
        super().__init__(arrays)
        self.units = dict(units or {})

    def __repr__(self):
        rows = len(next(iter(self.values()))) if self else 0
        return f"<caskdem.Columns: {len(self)} columns of {rows} rows: {', '.join(self)}>"


class Run:
    """One analysis: ``summary`` (a dict, as summary.json) and ``history`` (Columns, as history.csv)."""

    def __init__(self, summary: dict, history: Columns):
        self.summary = summary
        self.history = history

    def __repr__(self):
        s = self.summary
        return f"<caskdem.Run: {s.get('status')}, {len(self.history.get('time_s', []))} samples>"


def _numpy():
    """numpy, which every array here is; imported when first needed, so that `import caskdem` and
    help() work in an interpreter without it."""
    try:
        import numpy
    except ImportError:
        raise ImportError("caskdem's arrays need numpy: run /usr/bin/python3 (Debian's python3-numpy), or "
                          "install numpy into this interpreter") from None
    return numpy


def _columns(triples) -> Columns:
    out = Columns()
    for name, unit, values in triples:
        out[name] = values
        out.units[name] = unit
    return out


def _merged(base: dict, tables: Mapping) -> dict:
    for key, value in tables.items():
        if isinstance(value, Mapping) and isinstance(base.get(key), dict):
            _merged(base[key], value)
        else:
            base[key] = value
    return base


def _from_tables(file, tables, load, from_tables):
    if file is None:
        return from_tables(dict(tables), "keyword arguments")
    if not tables:
        return load(str(file))
    path = pathlib.Path(file)
    try:
        with open(path, "rb") as f:
            document = tomllib.load(f)
    except OSError as error:
        raise ValueError(f"{path}: cannot read it ({error.strerror})") from None
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{path}: {error}") from None
    # Relative paths in the file still start at its folder.
    return from_tables(_merged(document, tables), str(path.parent / f"{path.name} (with keyword arguments)"))


def load_case(file) -> Case:
    """The case in a case file (TOML; docs/case-file.md)."""
    return _native.load_case(str(file))


def case(file=None, /, **tables) -> Case:
    """A case from keyword arguments named as a case file's tables, each a dict of its keys.

    ``case(cask={"shape": "cylinder", ...}, motion={"kind": "sine", ...})`` reads as the file
    would; ``case("cases/x.toml", motion={...})`` is that file with some tables replaced (a dict
    replaces the keys it names and keeps the others). Relative paths start at the working
    directory (or at the file's folder). A bad key raises ValueError naming it.
    """
    return _from_tables(file, tables, _native.load_case, _native.case_from_tables)


def run(case: Case, output_interval: Optional[float] = None) -> Run:
    """Runs one case: its summary (dict) and histories (Columns, one array per history column).

    ``output_interval`` (s) overrides the case's [output] interval; 0 keeps no history. A 3D
    case without a settle time runs until the cask is at rest, as ``caskdem run`` does.
    """
    _numpy()
    summary, history = _native.run(case, output_interval)
    import json
    return Run(json.loads(summary), _columns(history))


def load_ensemble(file) -> Ensemble:
    """The ensemble in an ensemble file (TOML; docs/ensemble-file.md), its motions read."""
    return _native.load_ensemble(str(file))


def ensemble(file=None, /, **tables) -> Ensemble:
    """An ensemble from keyword arguments named as an ensemble file's tables.

    ``ensemble("ensembles/x.toml", uncertain={...})`` is that file with tables replaced; without
    a file every table the file needs must be given (cask, motions, intensity, ...). The same
    checks as the file; a bad key raises ValueError naming it.
    """
    return _from_tables(file, tables, _native.load_ensemble, _native.ensemble_from_tables)


def realisations(ensemble: Ensemble) -> Columns:
    """The realisations the ensemble file draws, as rollout's columns, in the file's order.

    ``rollout(ensemble, realisations(ensemble))`` gives, bit for bit, the outcomes that
    ``caskdem ensemble`` stores for the same file.
    """
    _numpy()
    units = {name: unit for name, unit, _ in _native.rollout_parameters()}
    columns = ensemble.realisations()
    return Columns(columns, {name: units[name] for name in columns})


def rollout_parameters() -> list:
    """The columns rollout takes: (name, SI unit, meaning) for each."""
    return list(_native.rollout_parameters())


def rollout(ensemble: Ensemble, parameters: Optional[Mapping] = None, *, device: str = "auto", threads: int = 0,
            isa: str = "automatic", progress: Optional[Callable[[int, int], None]] = None, **columns) -> Columns:
    """Runs the realisations you give on the ensemble engine; their outcomes, in your order.

    The ensemble gives the cask, its nominal parameters, the motions, the intensity measure and
    the time step; each realisation is one row of the columns, given as a dict ``parameters`` or
    as keyword arguments, each a 1-D array (one value per realisation) or one number for all:

    ======================  ======  ===================================================
    motion                  index   the ensemble's motion, 0 to M - 1 (needed when M > 1)
    scale_factor            1       factor on the motion's accelerations, or instead:
    level                   SI      the motion's intensity in the ensemble's measure
    friction_static         1       static friction coefficient
    friction_kinetic        1       kinetic coefficient (static_kinetic, exponential laws)
    friction_decay_speed    m/s     the exponential law's v0
    restitution             1       rocking restitution (via the cask's calibration curve)
    damping_ratio           1       the contacts' damping ratio, instead of restitution
    mass                    kg      no lighter than ``ensemble.lightest_mass``
    centre_height           m       centre of mass above the base
    eccentricity            m       centre of mass off the axis
    base_camber             m       rise of the base's edges above its middle
    incidence               rad     direction of the first horizontal (3D casks)
    ======================  ======  ===================================================

    A parameter not given keeps the ensemble's nominal value (``ensemble.nominal``).

    Returns Columns with the result file's per-realisation names: the inputs as run (level,
    scale_factor, friction_static, ..., damping_ratio, mass, centre_height) and the outcomes:
    status (see STATUS), tipped_over (bool), max_abs_rotation (rad; 3D: the axis' tilt),
    max_rotation_ratio (of the nominal stability angle), max_abs_slide, residual_slide,
    max_uplift (m), impacts, end_time, tip_over_time, instability_time (s; -1: none); in 3D
    also spin (rad), max_slip and residual_slip (m). Each row's result depends only on its own
    parameters: not on the other rows, the threads, the instruction set or the device.

    device: "auto" (a CUDA GPU when one is usable, else the CPU), "cpu" or "cuda".
    threads: OpenMP threads on the CPU (0: OpenMP's default). isa: "automatic", "avx512f", "avx2",
    "sse2" or "scalar", the same results on each. progress: called as progress(done, total) at
    most ten times a second. The GIL is released while the realisations run; Ctrl-C stops
    the run at the next finished realisation and raises KeyboardInterrupt.
    """
    np = _numpy()
    given = dict(parameters or {})
    for name, values in columns.items():
        if name in given:
            raise ValueError(f"rollout parameter {name}: given both in parameters and as a keyword")
        given[name] = values
    out = _columns(_native.rollout(ensemble, given, device, threads, isa, progress))
    out["tipped_over"] = out["status"] == 1
    out.units["tipped_over"] = "1"
    rows = len(out["status"])
    for name in ("eccentricity", "base_camber"):  # inputs the result file has no column for
        if name in given:
            out[name] = np.broadcast_to(np.asarray(given[name], dtype=float), (rows,)).copy()
            out.units[name] = "m"
    return out


def fit_fragility(level, exceeded, motion=None, *, confidence: float = 0.95, bootstrap: int = 200,
                  seed: int = 1) -> dict:
    """A lognormal fragility fitted to realisations, as an ensemble fits each limit state.

    level: each realisation's intensity (SI; a stripe is a level several realisations share);
    exceeded: whether it exceeded the limit state (bool or 0/1); motion: its motion's index,
    the unit the bootstrap resamples and the fit test clusters (one motion when not given).

    Returns a dict: fitted, reason (why not), median (SI) and beta, the stripes (level, trials,
    count, probability and its Clopper-Pearson interval), band (a bootstrap band over motions
    at ``confidence`` on a grid of intensities) and test (the fit test with the motions
    clustered: p_value, record_to_record, design_effect, rejected, text); ``rejected`` says
    whether the curve failed it. A rejected curve is still returned: say so where you use it.
    """
    _numpy()
    return _native.fit_fragility(level, exceeded, motion, confidence, bootstrap, seed)


def annual_frequency(median: float, beta_r: float, *, beta_u: float = 0.0, measure: str = "PGA", hazard=None,
                     intensity=None, frequency=None) -> dict:
    """The annual frequency of exceeding a lognormal fragility at a site, as ``caskdem risk``.

    median (SI: m/s^2, or m/s for PGV), beta_r and beta_u: the fragility; measure: its
    intensity measure ("PGA", "PGV", "SA(1.0)"). The hazard: a file (OpenQuake, nshmp-haz or a
    table, docs/risk.md) of the same measure (another is refused), or the arrays intensity
    (SI, increasing) and frequency (1/year). The median must be the curve of the cask the
    hazard is for: a model's curve goes to full size first (docs/risk.md, similarity).

    Returns mean, median (1/year), fractile_05 and fractile_95 (None unless beta_u > 0: not
    sampled), the HCLPF capacities (conservative, composite and the lower of the two; SI), and
    how the integral splits (below_curve, above_curve, segment_frequency).
    """
    _numpy()
    return _native.annual_frequency(median, beta_r, beta_u, measure, None if hazard is None else str(hazard),
                                    intensity, frequency)


class Group(dict):
    """An HDF5 group as a dict: datasets as numpy arrays, subgroups as Groups; ``attrs`` holds
    the group's attributes and ``units[name]`` each dataset's unit."""

    def __init__(self):
        super().__init__()
        self.attrs = {}
        self.units = {}


def _text(value):
    np = _numpy()
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, np.ndarray) and value.dtype.kind in "OS":
        return np.array([v.decode() if isinstance(v, bytes) else v for v in value.ravel()], dtype=object)
    return value


def _group(h5group) -> Group:
    import h5py
    out = Group()
    out.attrs = {k: _text(v) for k, v in h5group.attrs.items()}
    for name, item in h5group.items():
        if isinstance(item, h5py.Group):
            out[name] = _group(item)
        else:
            out[name] = _text(item[()])
            if "units" in item.attrs:
                out.units[name] = _text(item.attrs["units"])
    return out


def read_result(file) -> Group:
    """A result file of ``caskdem ensemble`` (docs/output.md), its seal checked, as nested dicts.

    ``read_result(f)["realisations"]`` holds one array per field (``.units`` names each unit);
    ``["limit_states"][name]`` the stripes, fit and band of each limit state; ``.attrs`` the
    run's attributes. ``pandas.DataFrame(read_result(f)["realisations"])`` is a table of it.
    """
    _native.verify_result(str(file))
    import h5py
    with h5py.File(file, "r") as f:
        return _group(f)
