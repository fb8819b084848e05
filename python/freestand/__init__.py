"""freestand from Python: must free-standing equipment be anchored to survive the design earthquake?

Every function here runs the same C++ code as the `freestand` command of the same name and
returns what that command prints with --json (or writes as result.json / fragility.json) as a
dict; series of numbers come as float64 NumPy arrays. Units are SI and in the names
(accel_mps2, dt_s, pga_g). Keywords are the command's options with '-' written '_' (`a_g` is
`--a-g`). classify, slide, rock and simulate pass typed values to the library: a keyword of the
wrong type (a string, a bool, a complex number for a number) is a TypeError naming it, and a
value out of its range an InputError naming it (`mu: value -0.4 is out of range; expected
[0, 2]`). The other functions still pass their options as command-line text: a keyword that
takes numbers refuses anything else with an InputError naming it, and a range error names the
option as the command line does (`--pga`). Methods: docs/methods.md.

Errors are exceptions carrying the command's message, one class per exit-code class:
UsageError (2), InputError (3, also a ValueError), NumericalError (4), IoError (5), all
subclasses of Error, each with its `exit_code`.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, Iterable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _freestand as _fs

Error = _fs.Error
UsageError = _fs.UsageError
InputError = _fs.InputError
NumericalError = _fs.NumericalError
IoError = _fs.IoError

__version__: str = _fs.version
commit: str = _fs.commit
#: Default gravity and size of the unit g, m/s^2: the thesis's 9.81 (docs/methods.md, Conventions);
#: a case may set its own (site.g_mps2).
g_mps2: float = _fs.g_mps2
#: Names of the simulation's contact modes, indexed by the codes in simulate()'s series["mode"].
mode_names: tuple = tuple(_fs.mode_names)
#: Names of the 3D body's contact states, indexed by the codes in simulate_3d()'s series["state"].
state_names: tuple = tuple(_fs.state_names)

__all__ = [
    "Error", "UsageError", "InputError", "NumericalError", "IoError", "Record", "read_record",
    "response_spectrum", "design_target", "generate", "slide", "classify", "rock", "simulate",
    "simulate_3d", "assess", "fragility", "mode_names", "state_names",
]

PathLike = Union[str, os.PathLike]


@dataclass
class Record:
    """A uniformly sampled acceleration history: sample i at i * dt_s seconds, in m/s^2."""

    accel_mps2: np.ndarray
    dt_s: float
    name: str = ""
    source: str = "python"
    component: str = ""

    @property
    def time_s(self) -> np.ndarray:
        return self.dt_s * np.arange(len(self.accel_mps2))

    @property
    def accel_g(self) -> np.ndarray:
        """The samples in g of g_mps2 m/s^2 (freestand's default unit g; a case may set its own)."""
        return self.accel_mps2 / g_mps2


# NumPy kinds of real numbers: signed and unsigned integers, floats. Not b (bool), c (complex,
# whose imaginary part a cast to float drops with only a warning), U/S (text) or O (objects).
_REAL_KINDS = "iuf"


def _samples(values: Any, what: str) -> np.ndarray:
    """values as float64 samples; TypeError naming `what` when they are not real numbers (the
    module checks the shape, and refuses the same things itself with an InputError)."""
    try:
        array = np.asarray(values)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what}: expected a one-dimensional array of numbers ({e})") from None
    if array.dtype.kind not in _REAL_KINDS:
        raise TypeError(f"{what}: expected a one-dimensional array of real numbers, got an "
                        f"array of {array.dtype}")
    return array.astype(float)


def _number(value: Any, keyword: str) -> float:
    """value as a float when it is a real number; TypeError naming keyword otherwise."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(
            value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{keyword}: expected a real number, got {type(value).__name__} "
                        f"{value!r}")
    return float(value)


_BOX_KEYS = {"b": "half_width_m", "h": "half_height_m", "m": "mass_kg"}
_CG_KEYS = {"x": "cg_offset_m", "h": "cg_height_m"}
#: simulate_3d's block keys, passed on under the same names.
_BODY3D_KEYS = {key: key for key in ("b", "d", "h", "m", "height", "cgx", "cgy", "ixx", "iyy", "izz")}
#: simulate_3d's flexible keys (`--flexible f=,zeta=,mass=,height=`).
_MODE_KEYS = {key: key for key in ("f", "zeta", "mass", "height")}


def _keyed_numbers(values: Mapping[str, Any], keys: Mapping[str, str], keyword: str) -> dict:
    """{keys[k]: float} of a mapping; TypeError naming keyword[k] for an unknown key or a value
    that is not a real number."""
    if not isinstance(values, Mapping):
        raise TypeError(f"{keyword}: expected a mapping of {', '.join(keys)} to numbers, got "
                        f"{type(values).__name__} {values!r}")
    out = {}
    for key, value in values.items():
        if key not in keys:
            raise TypeError(f"{keyword}: unknown key {key!r}; expected one of "
                            f"{', '.join(keys)}")
        out[keys[key]] = _number(value, f"{keyword}[{key!r}]")
    return out


def _sequence(values: Any, keyword: str) -> list:
    """A sequence of numbers as a list (each still to check); TypeError naming keyword for a
    string, a multi-dimensional array or anything that is not a sequence."""
    if isinstance(values, np.ndarray):
        if values.ndim != 1:
            raise TypeError(f"{keyword}: expected a one-dimensional array of real numbers, got "
                            f"a {values.ndim}-dimensional array")
        return values.tolist()
    if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        raise TypeError(f"{keyword}: expected a sequence of real numbers, got "
                        f"{type(values).__name__} {values!r}")
    return list(values)


def _pair(value: Any, keyword: str, shape: str) -> list:
    """Two real numbers as a list; TypeError naming keyword and the expected shape otherwise."""
    if isinstance(value, (str, bytes)) or not isinstance(value, Iterable):
        raise TypeError(f"{keyword}: expected {shape}, got {type(value).__name__} {value!r}")
    pair = [_number(v, keyword) for v in value]
    if len(pair) != 2:
        raise TypeError(f"{keyword}: expected {shape}, got {len(pair)} numbers")
    return pair


def _box(block: Mapping[str, float], cg: Any, inertia: Optional[float]) -> dict:
    """The block, CG and inertia as the module's box fields (sliding::BoxSpec): block {"b", "h"
    [, "m"]}; cg {"x", "h"} (x right of the box centre) or (x, y) (x from the left edge, y up)."""
    box = _keyed_numbers(block, _BOX_KEYS, "block")
    for key in ("b", "h"):
        if _BOX_KEYS[key] not in box:
            raise TypeError(f"block: missing {key!r}")
    if cg is not None:
        if isinstance(cg, Mapping):
            box.update(_keyed_numbers(cg, _CG_KEYS, "cg"))
        else:
            xy = _pair(cg, "cg", "{'x': .., 'h': ..} or (x, y)")
            box["cg_offset_m"] = xy[0] - box["half_width_m"]
            box["cg_height_m"] = xy[1]
    if inertia is not None:
        box["inertia_cg_kgm2"] = _number(inertia, "inertia")
    return box


def _optional_number(value: Any, keyword: str) -> Optional[float]:
    """None, or value as a float when it is a real number; TypeError naming keyword otherwise."""
    return None if value is None else _number(value, keyword)


def _one_path(value: Any, keyword: str) -> str:
    if not isinstance(value, (str, os.PathLike)):
        raise TypeError(f"{keyword}: expected a path, got {type(value).__name__} {value!r}")
    return os.fspath(value)


def _paths(value: Any, keyword: str) -> list:
    """A path or a sequence of paths as a list of str ([] for None); TypeError naming keyword
    for anything else."""
    if value is None:
        return []
    if isinstance(value, (str, os.PathLike)):
        return [os.fspath(value)]
    if not isinstance(value, Iterable) or isinstance(value, bytes):
        raise TypeError(f"{keyword}: expected a path or a sequence of paths, got "
                        f"{type(value).__name__} {value!r}")
    return [_one_path(item, keyword) for item in value]


def _numbers(values: Any, keyword: str) -> list:
    """A real number or a sequence of them as a list of floats; TypeError naming keyword
    otherwise (a string is not a sequence of numbers here)."""
    if isinstance(values, np.ndarray):
        if values.ndim != 1 or values.dtype.kind not in _REAL_KINDS:
            raise TypeError(f"{keyword}: expected a one-dimensional array of real numbers, got "
                            f"a {values.ndim}-dimensional array of {values.dtype}")
        return [float(v) for v in values]
    if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        return [_number(values, keyword)]
    return [_number(v, keyword) for v in values]


def _grid(frequencies: Any, fmin: Any, fmax: Any, per_decade: Any) -> tuple:
    """The frequency grid's arguments to the module: an explicit list or fmin/fmax/per_decade."""
    if frequencies is not None:
        for keyword, value in (("fmin", fmin), ("fmax", fmax), ("per_decade", per_decade)):
            if value is not None:
                raise TypeError(f"frequencies and {keyword} exclude each other; give one")
        return _numbers(frequencies, "frequencies"), None, None, None
    return (None, _optional_number(fmin, "fmin"), _optional_number(fmax, "fmax"),
            _optional_number(per_decade, "per_decade"))


# Design values by keyword: the request's field and whether it takes a number (else a name).
_DESIGN_VALUES = {"pga": ("pga_g", True), "sds": ("sds_g", True), "sd1": ("sd1_g", True),
                  "tl": ("tl_s", True), "ag": ("ag_g", True), "type": ("type", False),
                  "ground": ("ground", False), "soil": ("soil", False)}


def _design_values(values: Mapping[str, Any], function: str) -> dict:
    """{field: value} of the design values; TypeError naming an unknown keyword or a value of
    the wrong type (EC8's type may be given as the number 1 or 2)."""
    unknown = sorted(set(values) - set(_DESIGN_VALUES))
    if unknown:
        raise TypeError(f"{function}() got unexpected keyword argument(s) {', '.join(unknown)}")
    out = {}
    for keyword, value in values.items():
        if value is None:
            continue
        field, numeric = _DESIGN_VALUES[keyword]
        if numeric:
            out[field] = _number(value, keyword)
        elif keyword == "type" and isinstance(value, (int, np.integer)) and not isinstance(
                value, (bool, np.bool_)):
            out[field] = str(int(value))
        elif isinstance(value, str):
            out[field] = value
        else:
            raise TypeError(f"{keyword}: expected a str, got {type(value).__name__} {value!r}")
    return out


def _range(value: Any, keyword: str) -> Optional[tuple]:
    """(min, max) of a realism range; TypeError naming keyword unless two real numbers."""
    return None if value is None else tuple(_pair(value, keyword, "(min, max)"))


def _names(value: Any, keyword: str) -> list:
    """A comma list ("h1,h2") or a sequence of names as a list of str."""
    if value is None:
        return []
    if isinstance(value, str):
        return value.split(",")
    if not isinstance(value, Iterable) or not all(isinstance(v, str) for v in value):
        raise TypeError(f"{keyword}: expected a str or a sequence of str, got "
                        f"{type(value).__name__} {value!r}")
    return list(value)


def _path(value: Any, keyword: str) -> str:
    """A path as str ("" for None); TypeError naming keyword for anything else."""
    return "" if value is None else _one_path(value, keyword)


def read_record(path: PathLike) -> Record:
    """Reads a PEER .AT2, COSMOS .V2 or CSV record (docs/methods.md s.8 for the CSV headers)."""
    r = _fs.read_record(os.fspath(path))
    return Record(r["accel_mps2"], r["dt_s"], r["name"], r["source"], r["component"])


def response_spectrum(record: Record, damping: Union[float, Sequence[float]] = 0.05, *,
                      frequencies: Optional[Sequence[float]] = None, fmin: Optional[float] = None,
                      fmax: Optional[float] = None, per_decade: Optional[int] = None) -> dict:
    """The record's measures and its PSA (g), SD (m) and PSV (m/s) per damping
    (`freestand spectrum --json`): psa_g["0.05"] is an array over frequencies_hz."""
    return _fs.spectrum(_samples(record.accel_mps2, "accel_mps2"), record.dt_s, record.name,
                        record.source, record.component, _numbers(damping, "damping"),
                        *_grid(frequencies, fmin, fmax, per_decade))


def design_target(design: str, *, damping: Union[float, Sequence[float]] = 0.05,
                  vertical: bool = False, frequencies: Optional[Sequence[float]] = None,
                  fmin: Optional[float] = None, fmax: Optional[float] = None,
                  per_decade: Optional[int] = None, **design_values: Any) -> dict:
    """A design spectrum as a matching target (`freestand target --json`): design is rg1.60
    (pga=), asce7 (sds=, sd1=, tl=), ec8 (ag=, type=, ground=) or is1893 (pga=, soil=)."""
    if not isinstance(design, str):
        raise TypeError(f"design: expected a str, got {type(design).__name__} {design!r}")
    if not isinstance(vertical, (bool, np.bool_)):
        raise TypeError(f"vertical: expected True or False, got {type(vertical).__name__}")
    return _fs.target(design, _design_values(design_values, "design_target"),
                      _numbers(damping, "damping"), bool(vertical),
                      *_grid(frequencies, fmin, fmax, per_decade))


# generate's keyword options besides the design values: the request's field and its reader.
_GENERATE_OPTIONS = {
    "target_file": _path, "target_file_10": _path, "vertical_ratio": _optional_number,
    "components": _names, "duration": _optional_number, "dt": _optional_number,
    "va_range": _range, "adv2_range": _range, "da_max": _optional_number,
}


def generate(target: Optional[str] = None, *, seed: int = 1, timing: bool = True,
             seed_record: Optional[Sequence[PathLike]] = None,
             **options: Any) -> tuple:
    """Spectrum-compatible histories (`freestand generate`): returns (match, records), match
    being match.json as a dict and records a dict of Record by component (h1, h2, v). Options
    as the command's: pga=, target_file=, vertical_ratio=, components=, duration=, dt=,
    va_range=, adv2_range=, da_max=, ... timing=False writes wall_s as None (--no-timing)."""
    if target is not None and not isinstance(target, str):
        raise TypeError(f"target: expected a str, got {type(target).__name__} {target!r}")
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)):
        raise TypeError(f"seed: expected a whole number, got {type(seed).__name__} {seed!r}")
    if not 0 <= int(seed) < 2**64:
        raise InputError(f"seed: {seed}; expected a whole number in [0, 2^64)")
    design = {k: v for k, v in options.items() if k not in _GENERATE_OPTIONS}
    given = {k: _GENERATE_OPTIONS[k](v, k) for k, v in options.items() if k in _GENERATE_OPTIONS}
    seeds = [] if seed_record is None else [_path(p, "seed_record") for p in seed_record]
    match, records = _fs.generate(
        target or "", _design_values(design, "generate"), given.get("target_file", ""),
        given.get("target_file_10", ""), given.get("vertical_ratio"), seeds,
        given.get("components", []), given.get("duration"), given.get("dt"), int(seed),
        given.get("va_range"), given.get("adv2_range"), given.get("da_max"), bool(timing))
    return match, {r["component"]: Record(r["accel_mps2"], r["dt_s"], r["component"], "generated",
                                          r["component"]) for r in records}


def slide(mu: float, *, av_g: float = 0.0, pgd_m: Optional[float] = None,
          pga_g: Optional[float] = None, fes_hz: Optional[float] = None,
          spectrum10: Union[None, PathLike, Sequence[PathLike]] = None) -> dict:
    """ASCE 4 and energy-conservation sliding estimates (`freestand slide --json`): mu the
    static friction coefficient, av_g the peak vertical acceleration (g), pgd_m the peak ground
    displacement (m, energy method), pga_g the peak horizontal acceleration (g), and f_es as
    fes_hz (Hz) or found on spectrum10, the 10%-damped horizontal spectrum file(s) [H1.csv,
    H2.csv]: exactly one of the two."""
    if (fes_hz is None) == (spectrum10 is None):
        raise UsageError("slide: give exactly one of fes_hz and spectrum10")
    return _fs.slide(_number(mu, "mu"), _number(av_g, "av_g"), _optional_number(pgd_m, "pgd_m"),
                     _optional_number(pga_g, "pga_g"), _optional_number(fes_hz, "fes_hz"),
                     _paths(spectrum10, "spectrum10"))


def classify(block: Mapping[str, float], mu: float, a_g: float, *, cg=None, av_g: float = 0.0,
             inertia: Optional[float] = None) -> dict:
    """Initiating mode of a block at rest (`freestand classify --json`): block {"b": half-width,
    "h": half-height[, "m": kg]} in m; cg {"x": offset right of the centre, "h": height} or
    (x from the left edge, y up), which needs inertia (I_c about the CG, kg m^2) and m; av_g
    the peak vertical acceleration (g), taken downward."""
    return _fs.classify(_box(block, cg, inertia), _number(mu, "mu"), _number(a_g, "a_g"),
                        _number(av_g, "av_g"))


def rock(block: Mapping[str, float], *, cg=None, inertia: Optional[float] = None,
         spectrum: Union[None, PathLike, Sequence[PathLike]] = None,
         spectrum_v: Union[None, PathLike, Sequence[PathLike]] = None,
         v_ratio: Optional[float] = None, pga_g: Optional[float] = None,
         av_g: Optional[float] = None, pgv_mps: Optional[float] = None,
         mu: Optional[float] = None, restitution: Optional[float] = None,
         fs_required: Optional[float] = None, fn_hz: Optional[float] = None,
         rock_band_hz: Optional[Sequence[float]] = None) -> dict:
    """Closed-form rocking and overturning checks (`freestand rock --json`): block, cg and
    inertia as classify's; spectrum=[files] the horizontal spectra, one per damping, and
    spectrum_v the vertical ones (or v_ratio = SA_V / SA_H); pga_g, av_g (g), pgv_mps (m/s),
    mu, restitution, fs_required (default 1.5), fn_hz and rock_band_hz=(lo, hi) (Hz, the
    flexible-body screen)."""
    demand = {
        "v_ratio": _optional_number(v_ratio, "v_ratio"),
        "pga_h_g": _optional_number(pga_g, "pga_g"),
        "av_g": _optional_number(av_g, "av_g"),
        "pgv_mps": _optional_number(pgv_mps, "pgv_mps"),
        "mu_s": _optional_number(mu, "mu"),
        "restitution": _optional_number(restitution, "restitution"),
        "fs_required": _optional_number(fs_required, "fs_required"),
        "fixed_base_hz": _optional_number(fn_hz, "fn_hz"),
    }
    band = (None if rock_band_hz is None
            else _pair(rock_band_hz, "rock_band_hz", "(lo, hi) in Hz"))
    return _fs.rock(_box(block, cg, inertia), demand, _paths(spectrum, "spectrum"),
                    _paths(spectrum_v, "spectrum_v"), band)


def _motion(motion, dt_s, function: str):
    """A record's samples, step and name, or an array's with its dt_s."""
    if isinstance(motion, Record):
        if dt_s is not None and dt_s != motion.dt_s:
            raise UsageError(f"dt_s {dt_s} s given for a record sampled at {motion.dt_s} s")
        return motion.accel_mps2, motion.dt_s, motion.name
    if dt_s is None:
        raise UsageError(f"{function}: an array of samples needs dt_s (s)")
    return motion, dt_s, "python array"


def simulate(block: Mapping[str, float], motion: Union[Record, np.ndarray],
             dt_s: Optional[float] = None, *, mu: float, vertical_mps2: Optional[np.ndarray] = None,
             scale: float = 1.0, series: bool = True, cg=None, inertia: Optional[float] = None,
             mu_k: Optional[float] = None, restitution: Optional[float] = None,
             top: Optional[float] = None, integrator: str = "event", dt: float = 1e-4) -> dict:
    """Time history of the planar rigid block (`freestand simulate --json`) under a record (or
    an array of m/s^2 samples at dt_s), times scale; vertical_mps2 on the same samples. block,
    cg and inertia as classify's; mu and mu_k the static and kinetic friction, restitution on
    angular velocity (default Housner's), top the height of the top corners (m), integrator
    "event" or "cd" with its step dt (s). Returns the summary, and with series=True also
    "series": NumPy arrays time_s, slide_m, slide_velocity_mps, rotation_rad,
    angular_velocity_radps, mode (codes into mode_names), normal_force_N, friction_force_N,
    top_accel_mps2."""
    accel, dt_s, label = _motion(motion, dt_s, "simulate")
    if not isinstance(integrator, str):
        raise TypeError(f"integrator: expected \"event\" or \"cd\", got "
                        f"{type(integrator).__name__} {integrator!r}")
    vertical = None if vertical_mps2 is None else _samples(vertical_mps2, "vertical_mps2")
    return _fs.simulate(_box(block, cg, inertia), _number(mu, "mu"),
                        _optional_number(mu_k, "mu_k"), _optional_number(restitution, "restitution"),
                        _optional_number(top, "top"), integrator, _number(dt, "dt"),
                        _samples(accel, "accel_mps2"), _number(dt_s, "dt_s"), vertical,
                        _number(scale, "scale"), label, bool(series))


def simulate_3d(block: Mapping[str, float], motion: Union[Record, np.ndarray],
                dt_s: Optional[float] = None, *, mu: float, motion_y=None,
                vertical_mps2: Optional[np.ndarray] = None, scale: float = 1.0,
                series: bool = True, mu_k: Optional[float] = None,
                restitution: Optional[float] = None, dt: float = 1e-4,
                flexible: Optional[Mapping[str, float]] = None, phases: bool = True) -> dict:
    """Time history of the rigid body in three dimensions (`freestand simulate --model 3d
    --json`, docs/methods.md s.11) under x (a record, or an array of m/s^2 samples at dt_s),
    optionally y (motion_y, on the same samples) and the vertical, all times scale. block has
    b and d (half-widths along x and y, m), h (CG height, m), and optionally m (mass, kg),
    height (total height, m), cgx and cgy (the CG's offset from the footprint's centre, m) and
    ixx, iyy, izz (all three: the inertia about the CG, kg m^2); mu and mu_k the friction; restitution on angular velocity
    (default: the plastic impact, Housner's rule generalised); dt the time step (s); flexible
    (`--flexible`) the elastic mode carried along x and y: f (Hz), and optionally zeta, mass (a
    fraction of m) and height (m; defaults a uniform cantilever's 0.613 m at 0.726 of the
    height); phases=False takes every phase by steps (`--steps-only`: the scheme alone, to
    check it). Returns the summary, and with series=True also "series": NumPy arrays time_s,
    slide_x_m, slide_y_m, tilt_rad, tilt_over_critical, twist_rad, state (codes into
    state_names), and with a mode modal_x_m and modal_y_m."""
    accel, dt_s, label = _motion(motion, dt_s, "simulate_3d")
    if isinstance(motion_y, Record):
        motion_y = motion_y.accel_mps2
    y = None if motion_y is None else _samples(motion_y, "motion_y")
    vertical = None if vertical_mps2 is None else _samples(vertical_mps2, "vertical_mps2")
    return _fs.simulate_3d(_keyed_numbers(block, _BODY3D_KEYS, "block"), _number(mu, "mu"), _optional_number(mu_k, "mu_k"),
                           _optional_number(restitution, "restitution"), _number(dt, "dt"), _samples(accel, "accel_mps2"), _number(dt_s, "dt_s"),
                           y, vertical, _number(scale, "scale"), label, bool(series),
                           None if flexible is None else _keyed_numbers(flexible, _MODE_KEYS, "flexible"),
                           bool(phases))


def assess(case_file: PathLike, pga_g: Optional[Iterable[float]] = None) -> dict:
    """Assesses a case file (`freestand assess`): result.json as a dict; pga_g replaces the
    case's levels. The reports (HTML, Markdown, figures) are the command line's to write."""
    levels = None if pga_g is None else [_number(p, "pga_g") for p in _sequence(pga_g, "pga_g")]
    return _fs.assess(os.fspath(case_file), levels)


_FRAGILITY_OPTIONS = ("samples", "pool", "seed", "threads", "cache", "no_cache", "models")


def _whole(value: Any, keyword: str) -> int:
    """value as an int when it is a whole number (int or NumPy integer, not a bool); TypeError
    naming keyword otherwise."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{keyword}: expected a whole number, got {type(value).__name__} "
                        f"{value!r}")
    return int(value)


def _level_range(text: str) -> tuple:
    """(start, stop, step) of "START:STOP:STEP"; InputError naming pga otherwise."""
    parts = text.split(":")
    try:
        if len(parts) != 3:
            raise ValueError
        return tuple(float(p) for p in parts)
    except ValueError:
        raise InputError(f"pga: expected \"START:STOP:STEP\" or a list of numbers, got "
                         f"{text!r}") from None


def fragility(case_file: PathLike, *, pga: Union[str, Sequence[float]] = "0.1:1.0:0.1",
              records: Optional[Sequence[PathLike]] = None, **options: Any) -> dict:
    """P(overturn), P(slide), P(rock) against PGA (`freestand fragility`): fragility.json as a
    dict. pga as "START:STOP:STEP" or a list; samples=, pool=, seed= (default: the case's),
    threads= (0: all cores; the result does not depend on it), whole numbers; cache= a folder or
    no_cache=True; records=[files] a user suite; models="planar" (the rigid block in x and y) or
    "case" (as the case's levels decide: flexible body, 3D body, biaxial sliding)."""
    for name in options:
        if name not in _FRAGILITY_OPTIONS:
            raise TypeError(f"fragility() got an unexpected keyword argument {name!r}")
    pga_range = _level_range(pga) if isinstance(pga, str) else None
    levels = [] if pga_range else [_number(v, "pga") for v in _sequence(pga, "pga")]
    seed = options.get("seed")
    cache = options.get("cache")
    no_cache = options.get("no_cache", False)
    if not isinstance(no_cache, (bool, np.bool_)):
        raise TypeError(f"no_cache: expected True or False, got {type(no_cache).__name__}")
    models = options.get("models", "planar")
    if models not in ("planar", "case"):
        raise ValueError(f"models: expected \"planar\" or \"case\", got {models!r}")
    return _fs.fragility(
        os.fspath(case_file), levels, pga_range, _whole(options.get("samples", 100), "samples"),
        _whole(options.get("pool", 20), "pool"), None if seed is None else _whole(seed, "seed"),
        [os.fspath(r) for r in records or []], _whole(options.get("threads", 0), "threads"),
        None if cache is None else os.fspath(cache), bool(no_cache), models == "case")
