"""The Python module `freestand` against the command line (README "Python").

Every binding runs on the same input as the built CLI (FREESTAND_EXE) and must return what the
command prints with --json or writes as JSON: the same keys in the same order and the same
numbers (the module calls the same C++ code, so equal, not close). Errors must carry the
command's message and the class of its exit code. The module is the one the build put in
<build>/python (PYTHONPATH, set by ctest).
"""
import csv
import json
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

import freestand

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"
EL_CENTRO = DATA / "RSN175_IMPVALL.H_H-E12140.AT2"
EL_CENTRO_Y = DATA / "RSN175_IMPVALL.H_H-E12230.AT2"
COSMOS = DATA / "cosmos_small.V2"
EXE = os.environ.get("FREESTAND_EXE", "freestand")


def cli(*args, cwd=None):
    """Runs the CLI; returns (exit code, stdout, stderr)."""
    p = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=600)
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    code, out, err = cli(*args)
    assert code == 0, err
    return json.loads(out)


def plain(value):
    """A binding's result with NumPy arrays as lists, for comparing with parsed JSON."""
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return value.tolist()
    return value


def same(binding, document):
    """Equal values and the same key order at every level."""
    binding = plain(binding)
    assert binding == document
    assert json.dumps(binding) == json.dumps(document)


def without_wall_time(summary):
    return {k: v for k, v in summary.items() if k != "wall_s"}


# --- records and spectra ------------------------------------------------------------------------

def test_read_record_gives_the_file_samples_in_mps2():
    r = freestand.read_record(EL_CENTRO)
    assert r.dt_s == 0.005
    assert isinstance(r.accel_mps2, np.ndarray) and r.accel_mps2.dtype == np.float64
    # The AT2 file's first samples, in g, times g = 9.81 m/s^2 (core/units.hpp).
    lines = EL_CENTRO.read_text().splitlines()
    first = [float(x) for x in lines[4].split()][:3]
    assert r.accel_mps2[:3] == pytest.approx([9.81 * a for a in first], rel=1e-12)
    assert len(r.time_s) == len(r.accel_mps2) and r.time_s[1] == pytest.approx(0.005)
    assert np.max(np.abs(r.accel_g)) == pytest.approx(np.max(np.abs(r.accel_mps2)) / 9.81)


@pytest.mark.parametrize("record", [EL_CENTRO, COSMOS], ids=["at2", "cosmos"])
def test_response_spectrum_equals_spectrum_json(record):
    expected = cli_json("spectrum", record, "--damping", "0.05,0.1", "--json")
    got = freestand.response_spectrum(freestand.read_record(record), [0.05, 0.1])
    same(got, expected)
    assert isinstance(got["frequencies_hz"], np.ndarray)


def test_response_spectrum_of_a_numpy_array():
    t = np.arange(0, 10, 0.01)
    rec = freestand.Record(0.3 * 9.81 * np.sin(2 * np.pi * 2.0 * t), 0.01, "sine")
    s = freestand.response_spectrum(rec, 0.05, frequencies=[2.0, 50.0])
    # A rigid oscillator (50 Hz) follows the ground: its PSA is the PGA.
    assert s["psa_g"]["0.05"][1] == pytest.approx(0.3, rel=0.02)
    assert s["psa_g"]["0.05"][0] > 2.0  # resonance at 2 Hz after 20 cycles


def test_design_target_equals_target_json():
    expected = cli_json("target", "--design", "rg1.60", "--pga", "0.3", "--damping", "0.05", "--json")
    same(freestand.design_target("rg1.60", pga=0.3, damping=0.05), expected)


def test_generate_equals_the_command_s_match_json_and_records(tmp_path):
    code, _, err = cli("generate", "--target", "rg1.60", "--pga", "0.2", "--seed", "3",
                       "--components", "h1", "--no-timing", "--out", tmp_path)
    assert code == 0, err
    match, records = freestand.generate("rg1.60", pga=0.2, seed=3, components="h1", timing=False)
    same(match, json.loads((tmp_path / "match.json").read_text()))
    assert set(records) == {"h1"}
    files = sorted(tmp_path.glob("*.csv"))
    assert len(files) == 1
    written = freestand.read_record(files[0])
    assert records["h1"].dt_s == written.dt_s
    # The CSV holds the samples in g to its printed digits.
    np.testing.assert_allclose(records["h1"].accel_mps2, written.accel_mps2, rtol=1e-8, atol=1e-10)


# --- closed forms -------------------------------------------------------------------------------

def test_slide_equals_slide_json():
    expected = cli_json("slide", "--mu", "0.15", "--pga-g", "0.3", "--pgd-m", "0.1", "--fes-hz", "1.5",
                        "--json")
    same(freestand.slide(0.15, pga_g=0.3, pgd_m=0.1, fes_hz=1.5), expected)


def test_classify_equals_classify_json():
    expected = cli_json("classify", "--block", "b=0.15,h=0.6", "--mu", "0.4", "--a-g", "0.3", "--json")
    same(freestand.classify({"b": 0.15, "h": 0.6}, mu=0.4, a_g=0.3), expected)


def test_rock_equals_rock_json():
    expected = cli_json("rock", "--block", "b=0.3,h=0.9,m=500", "--pga-g", "0.4", "--pgv-mps", "0.3",
                        "--mu", "0.5", "--json")
    same(freestand.rock({"b": 0.3, "h": 0.9, "m": 500}, pga_g=0.4, pgv_mps=0.3, mu=0.5), expected)


# --- simulate -----------------------------------------------------------------------------------

BLOCK = {"b": 0.2, "h": 0.5, "m": 100}


@pytest.mark.parametrize("scale,mu", [(2.0, 0.1), (4.0, 0.6)], ids=["slides", "rocks"])
def test_simulate_equals_simulate_json_and_its_series(tmp_path, scale, mu):
    series_csv = tmp_path / "series.csv"
    expected = cli_json("simulate", "--block", "b=0.2,h=0.5,m=100", "--mu", mu, "--motion", EL_CENTRO,
                        "--scale", scale, "--json", "--out", series_csv)
    got = freestand.simulate(BLOCK, freestand.read_record(EL_CENTRO), mu=mu, scale=scale)
    series = got.pop("series")
    same(without_wall_time(got), without_wall_time(expected))
    with open(series_csv, encoding="utf-8") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    assert len(rows) == len(series["time_s"])
    for column in ("time_s", "slide_m", "rotation_rad", "normal_force_N", "top_accel_mps2"):
        # The CSV prints 9 significant digits (time to 1 us).
        np.testing.assert_allclose(series[column], [float(r[column]) for r in rows], rtol=2e-8, atol=1e-6)
    modes = [freestand.mode_names[m] for m in series["mode"]]
    assert modes == [r["mode"] for r in rows]


def test_simulate_an_array_equals_the_record_run():
    rec = freestand.read_record(EL_CENTRO)
    from_record = freestand.simulate(BLOCK, rec, mu=0.1, scale=2.0, series=False)
    from_array = freestand.simulate(BLOCK, 2.0 * rec.accel_mps2, rec.dt_s, mu=0.1, series=False)
    assert "series" not in from_array
    assert from_array["slide_max_m"] == pytest.approx(from_record["slide_max_m"], rel=1e-12)
    assert from_array["slide_max_m"] > 0.001


def test_simulate_remembers_no_stale_block():
    rec = freestand.read_record(EL_CENTRO)
    runs = [freestand.simulate(BLOCK, rec, mu=mu, scale=2.0, series=False)["slide_max_m"]
            for mu in (0.1, 0.25, 0.1)]
    assert runs[0] == runs[2] and runs[0] > 2 * runs[1]
    for _ in range(2):  # a refused block is refused every time
        with pytest.raises(freestand.InputError):
            freestand.simulate({"b": -0.2, "h": 0.5, "m": 100}, rec, mu=0.1)


# --- assess and fragility -----------------------------------------------------------------------

def test_assess_equals_result_json(tmp_path):
    case = ROOT / "cases" / "block-ts1.toml"
    code, _, err = cli("assess", case, "--pga", "0.3", "--out", tmp_path / "out")
    assert code == 0, err
    expected = json.loads((tmp_path / "out" / "result.json").read_text())
    got = freestand.assess(case, pga_g=[0.3])
    assert got == expected
    assert json.dumps(got) == json.dumps(expected)


def test_fragility_equals_fragility_json():
    case = ROOT / "cases" / "block-ts1.toml"
    args = ["--pga", "0.2,0.6", "--samples", "3", "--seed", "5"]
    expected = cli_json("fragility", case, *args, "--json")
    got = freestand.fragility(case, pga=[0.2, 0.6], samples=3, seed=5, threads=2)
    assert got == expected
    assert [lvl["n"] for lvl in got["levels"]] == [3, 3]


def test_fragility_of_a_slender_block_against_its_uplift_threshold():
    # TS1 is 0.3 m wide and 1.2 m tall: tan(alpha) = 0.15 / 0.6 = 0.25, so it cannot uplift
    # while a_h < 0.25 g (1 - a_v) (docs/methods.md s.2), about 0.24 g at 0.05 g with the case's
    # vertical ratio 2/3: nothing rocks or overturns there; at 2 g every sample overturns.
    case = ROOT / "cases" / "block-ts1.toml"
    levels = [0.05, 0.23, 0.26, 0.29, 2.0]
    got = freestand.fragility(case, pga=levels, samples=6, pool=2, seed=3, threads=2)
    assert [lvl["pga_g"] for lvl in got["levels"]] == levels
    p_overturn = [lvl["events"]["overturn"]["p"] for lvl in got["levels"]]
    assert got["levels"][0]["events"]["rock"]["k"] == 0
    assert p_overturn[0] == 0.0
    assert p_overturn[-1] == 1.0
    # Counts that rise with the level: the fitted median lies above the last level where no
    # sample overturns and below the first where every sample does (P = 0.5 falls between).
    none = max(a for a, p in zip(levels, p_overturn) if p == 0.0)
    every = min(a for a, p in zip(levels, p_overturn) if p == 1.0)
    assert none < every
    fit = got["fit"]["overturn"]
    assert fit is not None, got["fit_notes"]
    assert none < fit["theta_m_g"] < every


def test_fragility_takes_a_level_range_as_the_command_line_does():
    case = ROOT / "cases" / "block-ts1.toml"
    expected = cli_json("fragility", case, "--pga", "0.05:0.11:0.03", "--samples", "1",
                        "--pool", "1", "--json")
    got = freestand.fragility(case, pga="0.05:0.11:0.03", samples=1, pool=1)
    assert [lvl["pga_g"] for lvl in got["levels"]] == [0.05, 0.08, 0.11]
    assert got == expected


# --- errors -------------------------------------------------------------------------------------

def test_error_classes_carry_exit_codes():
    assert issubclass(freestand.InputError, freestand.Error)
    assert issubclass(freestand.UsageError, freestand.Error)
    assert (freestand.UsageError.exit_code, freestand.InputError.exit_code,
            freestand.NumericalError.exit_code, freestand.IoError.exit_code) == (2, 3, 4, 5)


def test_a_bad_value_is_an_input_error_naming_the_keyword():
    # The command line names its option, Python its keyword; the message and the class agree.
    code, _, err = cli("classify", "--block", "b=0.15,h=0.6", "--mu", "-0.4", "--a-g", "0.3", "--json")
    with pytest.raises(freestand.InputError) as e:
        freestand.classify({"b": 0.15, "h": 0.6}, mu=-0.4, a_g=0.3)
    assert code == freestand.InputError.exit_code
    assert str(e.value) == "mu: value -0.4 is out of range; expected [0, 2]"
    assert "--mu: value -0.4 is out of range; expected [0, 2]" in err
    assert isinstance(e.value, ValueError)


def test_an_unknown_keyword_is_python_s_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
        freestand.classify({"b": 0.15, "h": 0.6}, mu=0.4, a_g=0.3, colour="red")
    with pytest.raises(TypeError, match=r"^block: unknown key 'q'; expected one of b, h, m"):
        freestand.classify({"b": 0.15, "h": 0.6, "q": 1}, mu=0.4, a_g=0.3)
    with pytest.raises(TypeError, match=r"^block: missing 'h'"):
        freestand.classify({"b": 0.15}, mu=0.4, a_g=0.3)


def test_a_missing_file_is_an_io_error(tmp_path):
    missing = tmp_path / "nowhere.AT2"
    code, _, err = cli("spectrum", missing, "--json")
    with pytest.raises(freestand.IoError) as e:
        freestand.read_record(missing)
    assert code == freestand.IoError.exit_code
    assert str(missing) in str(e.value)


def test_a_bad_case_line_is_named(tmp_path):
    case = tmp_path / "bad.toml"
    text = (ROOT / "cases" / "block-ts1.toml").read_text().replace("mass_kg = 38.0", "mass_kg = -38.0", 1)
    case.write_text(text)
    code, _, err = cli("assess", case, "--out", tmp_path / "out")
    with pytest.raises(freestand.InputError) as e:
        freestand.assess(case)
    assert code == freestand.InputError.exit_code
    assert str(e.value) in err and "bad.toml:9: component.mass_kg" in str(e.value)


def test_an_array_that_is_not_one_dimensional_is_refused():
    with pytest.raises(freestand.InputError, match="one-dimensional"):
        freestand.simulate(BLOCK, np.zeros((10, 2)), 0.01, mu=0.3)


def test_samples_that_are_not_numbers_are_refused_naming_the_array():
    with pytest.raises(freestand.InputError, match="accel_mps2: expected a one-dimensional"):
        freestand.simulate(BLOCK, np.array(["a", "b"]), 0.01, mu=0.3)


def test_a_vertical_of_another_length_is_refused():
    with pytest.raises(freestand.InputError, match="vertical_mps2: 5 samples; expected the 10"):
        freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, vertical_mps2=np.zeros(5))
    run = freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, vertical_mps2=np.zeros(10))
    assert run["slide_max_m"] == 0.0


def test_non_finite_samples_are_refused():
    samples = np.zeros(100)
    samples[50] = math.nan
    with pytest.raises(freestand.InputError):
        freestand.simulate(BLOCK, samples, 0.01, mu=0.3)


def test_version_and_commit():
    code, out, _ = cli("--version")
    assert code == 0
    assert out.splitlines()[0].endswith(freestand.__version__)
    assert freestand.commit in out
