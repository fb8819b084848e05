"""The Python module `freestand` (README "Python"): its numbers against closed forms, and the
front-ends against each other.

The closed forms (classify, rock, slide) and simulate are checked against values computed here
from docs/methods.md's formulas: a uniform box's geometry, ASCE 4's sliding displacement, a
block at rest, and a Coulomb block's slip under a constant-acceleration pulse. A few bindings are
also run on the same input as the built CLI (FREESTAND_EXE) and must return what the command
prints with --json or writes as JSON: the same keys in the same order and the same numbers (both
call the same C++ code, so equal, not close). Errors must carry the command's message and the
class of its exit code. The module is the one the build put in <build>/python (PYTHONPATH, set
by ctest).
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

G_MPS2 = 9.81  # docs/methods.md, Conventions
#: Tolerance of a closed form evaluated here against the library's: the same double arithmetic
#: in another order.
CLOSED_FORM_RTOL = 1e-12


def test_classify_of_a_uniform_box_follows_tan_alpha():
    # docs/methods.md s.2: tan(alpha) = b / h; A = a_g / (1 - av_g); at rest below tan(alpha),
    # rocking above it when mu_s > tan(alpha).
    b, h = 0.15, 0.6
    rest = freestand.classify({"b": b, "h": h}, mu=0.4, a_g=0.2)
    assert rest["tan_alpha"] == pytest.approx(b / h, rel=CLOSED_FORM_RTOL)
    assert rest["mode"] == "rest"
    rocks = freestand.classify({"b": b, "h": h}, mu=0.4, a_g=0.3, av_g=0.1)
    assert rocks["A"] == pytest.approx(0.3 / (1 - 0.1), rel=CLOSED_FORM_RTOL)
    assert rocks["mode"] == "rock"
    slides = freestand.classify({"b": b, "h": h}, mu=0.1, a_g=0.3)
    assert slides["mode"] == "slide"


def test_rock_of_a_uniform_box_gives_its_geometry_and_thresholds():
    # Uniform box (docs/methods.md s.1, s.5): I_O = 4/3 M R^2, so p = sqrt(3 g / (4 R)); uplift
    # at A = tan(alpha) = b / h; Housner's r = 1 - 3/2 sin^2(alpha); Ishiyama's bound
    # V = 0.4 sqrt(8 g R (1 - cos alpha) / (3 cos alpha)).
    b, h, m = 0.3, 0.9, 500.0
    r = freestand.rock({"b": b, "h": h, "m": m}, pga_g=0.4, pgv_mps=0.3, mu=0.5)
    radius_m = math.hypot(b, h)
    alpha = math.atan2(b, h)
    assert r["R_m"] == pytest.approx(radius_m, rel=CLOSED_FORM_RTOL)
    assert r["tan_alpha"] == pytest.approx(b / h, rel=CLOSED_FORM_RTOL)
    assert r["alpha_rad"] == pytest.approx(alpha, rel=CLOSED_FORM_RTOL)
    assert r["p_radps"] == pytest.approx(math.sqrt(3 * G_MPS2 / (4 * radius_m)),
                                         rel=CLOSED_FORM_RTOL)
    assert r["inertia_edge_kgm2"] == pytest.approx(4 / 3 * m * radius_m**2, rel=CLOSED_FORM_RTOL)
    assert r["uplift_a_g"] == pytest.approx(b / h, rel=CLOSED_FORM_RTOL)
    assert r["restitution"] == pytest.approx(1 - 1.5 * math.sin(alpha)**2, rel=CLOSED_FORM_RTOL)
    ishiyama = 0.4 * math.sqrt(8 * G_MPS2 * radius_m * (1 - math.cos(alpha))
                               / (3 * math.cos(alpha)))
    assert r["ishiyama_v_mps"] == pytest.approx(ishiyama, rel=CLOSED_FORM_RTOL)
    assert r["pgv_below_ishiyama"] is (0.3 < ishiyama)
    # mu_s 0.5 > tan(alpha) = 0.333 and 0.4 g above it: the block rocks.
    assert r["mode"] == "rock"


def test_slide_follows_the_asce_4_and_energy_formulas():
    # docs/methods.md s.4: mu_e = mu_s (1 - 0.4 A_v), C_s = 2 mu_e g, delta_s = C_s / (2 pi f_es)^2;
    # energy: g DD = 4 mu_e g delta + (2 pi f_es)^2 delta^2 / 2, the positive root.
    mu, av_g, pgd_m, fes_hz = 0.15, 0.2243, 0.040, 1.2
    s = freestand.slide(mu, av_g=av_g, pgd_m=pgd_m, fes_hz=fes_hz)
    mu_e = mu * (1 - 0.4 * av_g)
    c_s = 2 * mu_e * G_MPS2
    omega2 = (2 * math.pi * fes_hz) ** 2
    assert s["mu_e"] == pytest.approx(mu_e, rel=CLOSED_FORM_RTOL)
    assert s["c_s_mps2"] == pytest.approx(c_s, rel=CLOSED_FORM_RTOL)
    assert s["slide_asce_m"] == pytest.approx(c_s / omega2, rel=CLOSED_FORM_RTOL)
    a, bq, c = omega2 / 2, 4 * mu_e * G_MPS2, G_MPS2 * pgd_m
    assert s["slide_energy_m"] == pytest.approx((-bq + math.sqrt(bq * bq + 4 * a * c)) / (2 * a),
                                                rel=1e-9)
    # The thesis's worked example (Saraswat 2017 s.5.5): 47 mm by ASCE 4, 56 mm by energy.
    assert s["slide_asce_m"] == pytest.approx(0.047, abs=0.0005)
    assert s["slide_energy_m"] == pytest.approx(0.056, abs=0.0005)


def power_law_spectrum(path, damping):
    """PSA = 0.1 f (g, f in Hz) up to 4 Hz, 0.4 g above, at the damping, in the spectrum file
    format (docs/methods.md s.8): linear on log-log axes, so a crossing of a level L below 0.4 g
    is read exactly at f = 10 L."""
    rows = "".join(f"{f},{0.1 * min(f, 4.0)}\n" for f in (0.25, 1.0, 4.0, 16.0, 64.0))
    path.write_text(f"# damping: {damping}\nfrequency_hz,psa_g\n{rows}")
    return path


def test_slide_finds_f_es_on_spectrum_files(tmp_path):
    # f_es is where SA_VH = C_s = 2 mu_e g (docs/methods.md s.4): on PSA = 0.1 f, f = 20 mu_e;
    # two equal components give SA_VH = sqrt(1.16) PSA, so f = 20 mu_e / sqrt(1.16).
    h1 = power_law_spectrum(tmp_path / "h1.csv", 0.1)
    one = freestand.slide(0.15, spectrum10=h1)
    assert one["f_es_hz"] == pytest.approx(20 * 0.15, rel=1e-9)
    assert one["slide_asce_m"] == pytest.approx(2 * 0.15 * G_MPS2 / (2 * math.pi * 3.0) ** 2,
                                                rel=1e-9)
    two = freestand.slide(0.15, spectrum10=[h1, str(h1)])
    assert two["f_es_hz"] == pytest.approx(20 * 0.15 / math.sqrt(1.16), rel=1e-9)
    with pytest.raises(freestand.InputError, match="damping"):
        freestand.slide(0.15, spectrum10=power_law_spectrum(tmp_path / "h5.csv", 0.05))


def test_slide_classify_and_rock_equal_their_commands():
    # The front-ends agree: the same request from the command line and from Python.
    expected = cli_json("slide", "--mu", "0.15", "--pga-g", "0.3", "--pgd-m", "0.1", "--fes-hz", "1.5",
                        "--json")
    same(freestand.slide(0.15, pga_g=0.3, pgd_m=0.1, fes_hz=1.5), expected)
    expected = cli_json("classify", "--block", "b=0.15,h=0.6", "--mu", "0.4", "--a-g", "0.3", "--json")
    same(freestand.classify({"b": 0.15, "h": 0.6}, mu=0.4, a_g=0.3), expected)
    expected = cli_json("rock", "--block", "b=0.3,h=0.9,m=500", "--pga-g", "0.4", "--pgv-mps", "0.3",
                        "--mu", "0.5", "--json")
    same(freestand.rock({"b": 0.3, "h": 0.9, "m": 500}, pga_g=0.4, pgv_mps=0.3, mu=0.5), expected)


def test_rock_on_spectrum_files_equals_its_command(tmp_path):
    files = [power_law_spectrum(tmp_path / f"h{d}.csv", d) for d in (0.02, 0.05)]
    expected = cli_json("rock", "--block", "b=0.15,h=0.6,m=38", "--spectrum",
                        ",".join(map(str, files)), "--v-ratio", "0.5", "--fn-hz", "8",
                        "--rock-band-hz", "0.5,5", "--json")
    got = freestand.rock({"b": 0.15, "h": 0.6, "m": 38}, spectrum=files, v_ratio=0.5, fn_hz=8,
                         rock_band_hz=(0.5, 5))
    same(got, expected)
    # The files were read: the spectral checks and the flexible-body screen ran.
    assert got["housner_sv_mps"] is not None and got["flexible"] is not None


# --- simulate -----------------------------------------------------------------------------------

BLOCK = {"b": 0.2, "h": 0.5, "m": 100}


def test_simulate_a_block_under_a_sub_threshold_sine_stays_at_rest():
    # 0.1 g against mu_s g = 0.6 g and g tan(alpha) = 0.4 g (docs/methods.md s.2): neither
    # sliding nor rocking starts, so the block moves with the base.
    dt_s = 0.005
    t = np.arange(0.0, 4.0, dt_s)
    accel = 0.1 * G_MPS2 * np.sin(2 * np.pi * 2.0 * t)
    run = freestand.simulate(BLOCK, accel, dt_s, mu=0.6)
    assert run["slide_max_m"] == 0.0
    assert run["rock_max_rad"] == 0.0
    assert not run["overturned"]
    assert run["pga_g"] == pytest.approx(0.1, rel=1e-3)
    series = run["series"]
    assert np.all(series["slide_m"] == 0.0) and np.all(series["rotation_rad"] == 0.0)
    assert set(series["mode"].tolist()) == {freestand.mode_names.index("rest")}


def test_simulate_a_coulomb_block_under_a_pulse_slips_the_closed_form_distance():
    # A squat block (tan(alpha) = 2.5 > mu_s: it cannot rock) under a base acceleration a0 > mu g
    # for T seconds, then none. Relative to the base it slips at (a0 - mu g) during the pulse,
    # reaching v = (a0 - mu g) T, then friction stops it at mu g (mu_k = mu_s):
    # d = (a0 - mu g) T^2 / 2 + v^2 / (2 mu g) = (a0 - mu g) a0 T^2 / (2 mu g).
    mu, a0_mps2, pulse_s, dt_s = 0.2, 0.4 * G_MPS2, 0.5, 0.001
    n_pulse = int(round(pulse_s / dt_s))
    accel = np.zeros(2000)
    accel[1:n_pulse + 1] = a0_mps2
    run = freestand.simulate({"b": 0.5, "h": 0.2, "m": 100}, accel, dt_s, mu=mu)
    expected_m = (a0_mps2 - mu * G_MPS2) * a0_mps2 * pulse_s**2 / (2 * mu * G_MPS2)
    # The samples ramp the pulse on and off over one step each: an error of order dt / T.
    assert run["slide_max_m"] == pytest.approx(expected_m, rel=5 * dt_s / pulse_s)
    assert run["slide_residual_m"] == pytest.approx(run["slide_max_m"], rel=1e-9)
    assert run["rock_max_rad"] == 0.0
    # It stops (v / (mu g) after the pulse, about 1 s) and stays: at rest from then on.
    stopped = run["series"]["time_s"] > 1.1
    assert set(run["series"]["mode"][stopped].tolist()) == {freestand.mode_names.index("rest")}


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


def test_simulate_runs_each_call_on_its_own_arguments():
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


def test_assess_of_a_box_at_rest_is_acceptable_at_the_levels_given(tmp_path):
    # A squat steel box (b/h = 0.75) at 0.02 and 0.04 g: below steel's friction and far below
    # its tipping ratio, neither slide nor rock starts (docs/methods.md s.2), so the closed forms
    # decide without a history.
    case = tmp_path / "rest.toml"
    case.write_text('[component]\nname = "Rest"\nmass_kg = 500.0\nwidth_m = 1.2\ndepth_m = 1.0\n'
                    'height_m = 0.8\nbase_material = "steel"\nallowable_slide_m = 0.050\n\n'
                    '[site]\npga_g = [0.05]\n')
    got = freestand.assess(case, pga_g=np.array([0.02, 0.04]))
    assert got["verdict"] == "free-standing acceptable"
    assert sorted({level["pga_g"] for level in got["levels"]}) == [0.02, 0.04]
    assert got["histories_generated"] == 0
    assert got["stamp"]["case_file"] == str(case)
    assert isinstance(got["levels"], list) and isinstance(got["histories_generated"], int)


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


def test_fragility_with_the_case_models_equals_the_command_line_and_runs_the_3d_body():
    # TS2 at 0.4 g rocks: with models="case" its samples run the 3D body (docs/methods.md s.11).
    case = ROOT / "cases" / "block-ts2.toml"
    args = ["--pga", "0.4", "--samples", "2", "--pool", "1", "--seed", "5"]
    expected = cli_json("fragility", case, *args, "--models", "case", "--json")
    got = freestand.fragility(case, pga=[0.4], samples=2, pool=1, seed=5, models="case")
    assert got == expected
    assert "runs the 3D rigid body" in got["inputs"]["models"]
    planar = freestand.fragility(case, pga=[0.4], samples=2, pool=1, seed=5)
    assert planar["inputs"]["models"] == "the rigid planar block in x and in y (docs/methods.md s.3)"
    with pytest.raises(ValueError, match="models"):
        freestand.fragility(case, pga=[0.4], samples=1, pool=1, models="3d")
    code, _, err = cli("fragility", case, "--pga", "0.4", "--samples", "1", "--models", "3d")
    assert code == 2
    assert "--models: expected planar or case" in err


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
    with pytest.raises(TypeError, match="accel_mps2: expected a one-dimensional"):
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


def test_simulate_3d_slides_as_coulomb_under_a_pulse():
    # A squat box (tan alpha = 2.5 > mu = 0.2: it cannot uplift) under 0.5 g in x for 1 s,
    # falling linearly to 0 over the next 0.01 s sample: it slips at (a - 0.2 g) relative to the
    # base, then stops under mu g. At 1 s: u = 0.15 g, v = 0.3 g; over the ramp u gains 0.003 g
    # (to 1e-6 g) and v 0.0005 g; then (0.3005 g)^2 / (2 x 0.2 g). Peak slip 0.37875 g m.
    g = freestand.g_mps2
    accel = np.zeros(301)
    accel[:101] = 0.5 * g
    r = freestand.simulate_3d({"b": 0.5, "d": 0.4, "h": 0.2, "m": 50.0}, accel, 0.01, mu=0.2,
                              series=True)
    assert r["model"] == "3d"
    assert r["slide_max_m"] == pytest.approx(0.37875 * g, rel=1e-3)
    assert r["tilt_max_rad"] < 1e-9
    assert r["time_in_state_s"]["slide"] > 1.0
    s = r["series"]
    assert set(s) == {"time_s", "slide_x_m", "slide_y_m", "tilt_rad", "tilt_over_critical",
                      "twist_rad", "state"}
    assert freestand.state_names[int(s["state"][50])] == "slide"
    assert np.max(np.abs(s["slide_y_m"])) < 1e-9


def test_simulate_3d_carries_a_flexible_mode():
    # A held squat box under a small sine: its modes are the fixed-base oscillators; the body
    # with the mode reports it, the series carries q, and the rigid body has none.
    g = freestand.g_mps2
    t = np.arange(0.0, 3.0, 0.005)
    accel = 0.05 * g * np.sin(2.0 * np.pi * 3.0 * t)
    block = {"b": 0.5, "d": 0.5, "h": 0.3, "m": 200.0}
    r = freestand.simulate_3d(block, accel, 0.005, mu=1.0, motion_y=0.5 * accel,
                              flexible={"f": 5.0, "zeta": 0.05, "mass": 0.3, "height": 0.45})
    assert r["mode"]["frequency_x_hz"] == 5.0
    assert r["modal_max_m"] > 1e-4
    assert r["tilt_max_rad"] < 1e-9
    s = r["series"]
    assert np.max(np.abs(s["modal_x_m"])) > 1e-4
    assert np.max(np.abs(s["modal_y_m"])) > 0.4 * np.max(np.abs(s["modal_x_m"]))
    rigid = freestand.simulate_3d(block, accel, 0.005, mu=1.0)
    assert rigid["mode"] is None and "modal_x_m" not in rigid["series"]
    with pytest.raises(freestand.InputError, match="flexible.f"):
        freestand.simulate_3d(block, accel, 0.005, mu=1.0, flexible={"zeta": 0.05})
    with pytest.raises(TypeError, match="unknown key 'mode'"):
        freestand.simulate_3d(block, accel, 0.005, mu=1.0, flexible={"f": 5.0, "mode": 1})


def test_simulate_3d_names_its_arguments():
    with pytest.raises(freestand.InputError, match="block.d"):
        freestand.simulate_3d({"b": 0.5, "h": 0.2}, np.zeros(10), 0.01, mu=0.2)
    with pytest.raises(freestand.InputError, match="accel_y_mps2"):
        freestand.simulate_3d({"b": 0.5, "d": 0.4, "h": 0.2}, np.zeros(10), 0.01, mu=0.2,
                              motion_y=np.zeros(9))
    with pytest.raises(TypeError, match="mu"):
        freestand.simulate_3d({"b": 0.5, "d": 0.4, "h": 0.2}, np.zeros(10), 0.01, mu="0.2")
    with pytest.raises(TypeError, match="unknown key 'mass'"):
        freestand.simulate_3d({"b": 0.5, "d": 0.4, "h": 0.2, "mass": 9.0}, np.zeros(10), 0.01,
                              mu=0.2)


def test_simulate_3d_restitution_is_on_angular_velocity():
    # A sine along x rocks the box about its edges: restitution 0.6 on angular velocity gives
    # what the planar block gives with the same restitution, Housner's (0.90) another answer.
    g = freestand.g_mps2
    t = np.arange(0.0, 3.0 + 1e-9, 0.005)
    accel = 0.5 * g * np.sin(2.0 * math.pi * 2.0 * t)
    box = {"b": 0.2, "d": 0.35, "h": 0.6, "m": 150.0}
    r06 = freestand.simulate_3d(box, accel, 0.005, mu=1.0, restitution=0.6, series=False)
    planar = freestand.simulate({"b": 0.2, "h": 0.6, "m": 150.0}, accel, 0.005, mu=1.0,
                                restitution=0.6, series=False)
    housner = freestand.simulate_3d(box, accel, 0.005, mu=1.0, series=False)
    assert r06["tilt_max_rad"] == pytest.approx(planar["rock_max_rad"], rel=0.01)
    assert abs(r06["tilt_max_rad"] - housner["tilt_max_rad"]) > 0.005
    with pytest.raises(freestand.InputError, match="restitution"):
        freestand.simulate_3d(box, accel, 0.005, mu=1.0, restitution=1.5)


def test_simulate_3d_phases_false_takes_every_phase_by_steps():
    g = freestand.g_mps2
    t = np.arange(0.0, 3.0 + 1e-9, 0.005)
    accel = 0.5 * g * np.sin(2.0 * math.pi * 2.0 * t)
    box = {"b": 0.2, "d": 0.35, "h": 0.6, "m": 150.0}
    phased = freestand.simulate_3d(box, accel, 0.005, mu=1.0, dt=1e-3, series=False)
    stepped = freestand.simulate_3d(box, accel, 0.005, mu=1.0, dt=1e-3, series=False,
                                    phases=False)
    assert phased["phases"] is True and stepped["phases"] is False
    assert phased["phase_time_s"]["edge_sticking"] > 1.0
    assert all(v == 0.0 for v in stepped["phase_time_s"].values())
    assert stepped["steps"] > 1.5 * phased["steps"]
    assert phased["tilt_max_rad"] == pytest.approx(stepped["tilt_max_rad"], rel=0.01)


def test_simulate_3d_takes_the_cg_offset_and_inertia():
    g = freestand.g_mps2
    t = np.arange(0.0, 3.0 + 1e-9, 0.005)
    accel = 0.5 * g * np.sin(2.0 * math.pi * 2.0 * t)
    box = {"b": 0.2, "d": 0.35, "h": 0.6, "m": 150.0, "cgx": 0.05, "cgy": -0.1, "ixx": 30.0,
           "iyy": 25.0, "izz": 12.0}
    # mu 0.4: the edge it rocks on slips, and off its middle the two vertices' friction turns it
    # (on a sticking edge no body twists).
    got = freestand.simulate_3d(box, accel, 0.005, mu=0.4, series=False)
    centred = freestand.simulate_3d({"b": 0.2, "d": 0.35, "h": 0.6, "m": 150.0}, accel, 0.005,
                                    mu=0.4, series=False)
    assert got["tilt_max_rad"] != centred["tilt_max_rad"]
    assert got["twist_max_rad"] > 10.0 * centred["twist_max_rad"]
    with pytest.raises(freestand.InputError, match="block.ixx"):
        freestand.simulate_3d({"b": 0.2, "d": 0.35, "h": 0.6, "ixx": 3.0}, accel, 0.005, mu=1.0)
    with pytest.raises(freestand.InputError, match="cgx|cg_x_m"):
        freestand.simulate_3d({"b": 0.2, "d": 0.35, "h": 0.6, "cgx": 0.3}, accel, 0.005, mu=1.0)
