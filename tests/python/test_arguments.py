"""The Python module's arguments: only real numbers where numbers are expected.

A cast to float would drop a complex array's imaginary part with only a NumPy warning and read
bool and text arrays as numbers; a string or a bool given for a number would reach the option
parser as option text, whose messages name a --flag the caller never typed. Each is an
InputError naming the Python argument, as a PGA level near zero is.
"""
import pathlib
import re
import warnings

import numpy as np
import pytest

import freestand

ROOT = pathlib.Path(__file__).resolve().parents[2]
CASE = ROOT / "cases" / "block-ts1.toml"
EL_CENTRO = ROOT / "tests" / "data" / "RSN175_IMPVALL.H_H-E12140.AT2"
BLOCK = {"b": 0.2, "h": 0.5, "m": 100}


@pytest.mark.parametrize("samples, kind", [
    (np.zeros(10, dtype=complex), "complex128"),
    (np.zeros(10, dtype=bool), "bool"),
    (np.array(["0.1"] * 10), "<U3"),
])
def test_samples_that_are_not_real_numbers_are_refused(samples, kind):
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no NumPy ComplexWarning on the way to the error
        with pytest.raises(TypeError,
                           match=f"accel_mps2: expected a one-dimensional array of real numbers, "
                                 f"got an array of {kind}"):
            freestand.simulate(BLOCK, samples, 0.01, mu=0.3)
        with pytest.raises(TypeError, match="vertical_mps2: expected"):
            freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, vertical_mps2=samples)
        record = freestand.Record(samples, 0.01)
        with pytest.raises(TypeError, match="accel_mps2: expected"):
            freestand.response_spectrum(record)


def test_the_extension_itself_refuses_complex_samples():
    # The module's own boundary, below the package: no silent cast to float.
    from freestand import _freestand
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(freestand.InputError,
                           match="accel_mps2: expected a one-dimensional array of real numbers, "
                                 "got an array of complex128"):
            _freestand.spectrum(np.ones(10, dtype=complex), 0.01, "n", "python", "h", [0.05],
                                None, None, None, None)


def test_integer_samples_are_numbers():
    run = freestand.simulate(BLOCK, np.zeros(10, dtype=np.int32), 0.01, mu=0.3, series=False)
    assert run["slide_max_m"] == 0.0


@pytest.mark.parametrize("value, shown", [("0.1", "str '0.1'"), (True, "bool True"),
                                          (0.1 + 0j, "complex (0.1+0j)")])
def test_a_number_argument_refuses_what_is_not_a_real_number(value, shown):
    rec = freestand.read_record(EL_CENTRO)
    shown = re.escape(shown)
    with pytest.raises(TypeError, match=f"^mu: expected a real number, got {shown}"):
        freestand.simulate(BLOCK, rec, mu=value)
    with pytest.raises(TypeError, match=f"^mu: expected a real number, got {shown}"):
        freestand.classify(BLOCK, mu=value, a_g=0.3)
    with pytest.raises(TypeError, match=f"^a_g: expected a real number, got {shown}"):
        freestand.classify(BLOCK, mu=0.3, a_g=value)
    with pytest.raises(TypeError, match="^scale: expected a real number"):
        freestand.simulate(BLOCK, rec, mu=0.3, scale=value)
    with pytest.raises(TypeError, match="^mu_k: expected a real number"):
        freestand.simulate(BLOCK, rec, mu=0.3, mu_k=value)
    with pytest.raises(TypeError, match="^dt: expected a real number"):
        freestand.simulate(BLOCK, rec, mu=0.3, dt=value)
    with pytest.raises(TypeError, match="^pga_g: expected a real number"):
        freestand.rock(BLOCK, pga_g=value)
    with pytest.raises(TypeError, match="^fes_hz: expected a real number"):
        freestand.slide(0.3, fes_hz=value)
    with pytest.raises(TypeError, match=r"^block\['b'\]: expected a real number"):
        freestand.classify({"b": value, "h": 0.6}, mu=0.3, a_g=0.3)
    with pytest.raises(TypeError, match=f"^samples: expected a whole number, got {shown}"):
        freestand.fragility(CASE, pga=[0.2], samples=value)
    with pytest.raises(TypeError, match=f"^pga: expected a real number, got {shown}"):
        freestand.fragility(CASE, pga=[0.2, value])


@pytest.mark.parametrize("call, message", [
    (lambda: freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=2.5),
     "mu: value 2.5 is out of range; expected [0, 2]"),
    (lambda: freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, mu_k=0.4),
     "mu_k: kinetic friction must be in [0, mu_s = 0.3]; got 0.4"),
    (lambda: freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, restitution=1.5),
     "restitution: value 1.5 is out of range; expected [0, 1]"),
    (lambda: freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, top=0.1),
     "top: "),
    (lambda: freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, integrator="cd", dt=-1.0),
     "dt: value -1 must be a finite number > 0"),
    (lambda: freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, integrator="rk4"),
     'integrator: expected "event" or "cd"; got "rk4"'),
    (lambda: freestand.simulate({"b": -0.2, "h": 0.5}, np.zeros(10), 0.01, mu=0.3),
     "block['b']: value -0.2 must be a finite number > 0"),
    (lambda: freestand.simulate({"b": 0.2, "h": 0.5, "m": 1e-6}, np.zeros(10), 0.01, mu=0.3),
     "block['m']: mass (kg): 1e-06 is below the limit"),
    (lambda: freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, cg={"x": 0.3, "h": 0.4},
                                inertia=1.0),
     "cg['x']: value 0.3 is out of range"),
    (lambda: freestand.rock(BLOCK, pga_g=-1.0), "pga_g: value -1 is out of range"),
    (lambda: freestand.rock(BLOCK, av_g=1.0), "av_g: value 1 is out of range; expected [0, 1)"),
    (lambda: freestand.rock(BLOCK, fn_hz=0.0), "fn_hz: value 0 is out of range"),
    (lambda: freestand.rock(BLOCK, fs_required=0.5), "fs_required: value 0.5 is out of range"),
    (lambda: freestand.rock(BLOCK, rock_band_hz=(5.0, 1.0)),
     "rock_band_hz: 5,1 Hz; expected 0 < LO < HI"),
    (lambda: freestand.rock(BLOCK, mu=-1.0), "mu: value -1 is out of range"),
    (lambda: freestand.slide(0.3, fes_hz=0.0), "fes_hz: value 0 must be a finite number > 0"),
    (lambda: freestand.slide(0.3, fes_hz=1.0, pgd_m=-1.0), "pgd_m: value -1 is out of range"),
    (lambda: freestand.slide(0.3, fes_hz=1.0, pga_g=-1.0), "pga_g: value -1 is out of range"),
    (lambda: freestand.slide(3.0, fes_hz=1.0), "mu: value 3 is out of range; expected [0, 2]"),
], ids=["mu", "mu_k", "restitution", "top", "dt", "integrator", "block-b", "block-m", "cg-x",
        "rock-pga_g", "rock-av_g", "rock-fn_hz", "rock-fs_required", "rock-band", "rock-mu",
        "slide-fes_hz", "slide-pgd_m", "slide-pga_g", "slide-mu"])
def test_a_value_out_of_range_is_an_input_error_naming_the_keyword(call, message):
    with pytest.raises(freestand.InputError) as e:
        call()
    assert str(e.value).startswith(message)
    assert "--" not in str(e.value)


def test_slide_takes_exactly_one_source_of_f_es():
    with pytest.raises(freestand.UsageError, match="exactly one of fes_hz and spectrum10"):
        freestand.slide(0.3)
    with pytest.raises(TypeError, match="^spectrum10: expected a path"):
        freestand.slide(0.3, spectrum10=[1.5])


def test_a_list_argument_refuses_a_string():
    # A string is not a sequence of levels, even though Python iterates it.
    with pytest.raises(TypeError,
                       match="^pga_g: expected a sequence of real numbers, got str '0.1,0.2'"):
        freestand.assess(CASE, pga_g="0.1,0.2")
    with pytest.raises(TypeError, match="^pga_g: expected a real number, got str"):
        freestand.assess(CASE, pga_g=["0.1"])
    with pytest.raises(TypeError, match="^damping: expected a real number, got bool"):
        freestand.response_spectrum(freestand.read_record(EL_CENTRO), damping=[0.05, True])
    with pytest.raises(TypeError, match="^pga_g: expected a real number, got complex"):
        freestand.assess(CASE, pga_g=np.array([0.1 + 1j]))


def test_fragility_takes_its_levels_as_a_range_text_or_numbers():
    # The library's range check names the keyword, not the command line's --pga.
    with pytest.raises(freestand.InputError, match="^pga: value 1e-310 is out of range"):
        freestand.fragility(CASE, pga=[1e-310, 0.1], samples=2)
    with pytest.raises(freestand.InputError, match="^pga: .*needs STEP > 0"):
        freestand.fragility(CASE, pga="0.3:0.1:0.1", samples=2)
    # A comma list is the command line's text; Python gives a list.
    with pytest.raises(freestand.InputError, match="^pga: expected \"START:STOP:STEP\""):
        freestand.fragility(CASE, pga="0.1,0.2", samples=2)
    with pytest.raises(TypeError, match="^samples: expected a whole number, got float 2.5"):
        freestand.fragility(CASE, pga=[0.2], samples=2.5)
    with pytest.raises(TypeError, match="unexpected keyword argument 'sample'"):
        freestand.fragility(CASE, pga=[0.2], sample=2)
    # Values out of their range are the request's to refuse, named as the keyword.
    with pytest.raises(freestand.InputError, match="^threads: value -1 is out of range"):
        freestand.fragility(CASE, pga=[0.2], samples=1, threads=-1)
    with pytest.raises(freestand.InputError, match="^seed: value -1 is out of range"):
        freestand.fragility(CASE, pga=[0.2], samples=1, seed=-1)
    with pytest.raises(freestand.InputError, match="^samples: 0; expected 1"):
        freestand.fragility(CASE, pga=[0.2], samples=0)


def test_a_level_near_zero_is_an_input_error():
    # The library's InputError, not an IndexError from an exception of the C++ runtime.
    with pytest.raises(freestand.InputError,
                       match=r"^pga_g: value 1e-310 is out of range; expected \[0.001, 3\]"):
        freestand.assess(CASE, pga_g=[1e-310, 0.1])
