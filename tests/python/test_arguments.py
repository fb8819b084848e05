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
        with pytest.raises(freestand.InputError,
                           match=f"accel_mps2: expected a one-dimensional array of real numbers, "
                                 f"got an array of {kind}"):
            freestand.simulate(BLOCK, samples, 0.01, mu=0.3)
        with pytest.raises(freestand.InputError, match="vertical_mps2: expected"):
            freestand.simulate(BLOCK, np.zeros(10), 0.01, mu=0.3, vertical_mps2=samples)
        record = freestand.Record(samples, 0.01)
        with pytest.raises(freestand.InputError, match="accel_mps2: expected"):
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
    with pytest.raises(freestand.InputError, match=f"^mu: expected a real number, got {shown}"):
        freestand.simulate(BLOCK, rec, mu=value)
    with pytest.raises(TypeError, match=f"^mu: expected a real number, got {shown}"):
        freestand.classify(BLOCK, mu=value, a_g=0.3)
    with pytest.raises(TypeError, match=f"^a_g: expected a real number, got {shown}"):
        freestand.classify(BLOCK, mu=0.3, a_g=value)
    with pytest.raises(freestand.InputError, match="^scale: expected a real number"):
        freestand.simulate(BLOCK, rec, mu=0.3, scale=value)
    with pytest.raises(TypeError, match=r"^block\['b'\]: expected a real number"):
        freestand.classify({"b": value, "h": 0.6}, mu=0.3, a_g=0.3)
    with pytest.raises(freestand.InputError, match="^samples: expected a real number"):
        freestand.fragility(CASE, pga=[0.2], samples=value)


def test_a_list_argument_refuses_a_string():
    # A string is not a sequence of levels, even though Python iterates it.
    with pytest.raises(freestand.InputError,
                       match="^pga_g: expected a sequence of real numbers, got str '0.1,0.2'"):
        freestand.assess(CASE, pga_g="0.1,0.2")
    with pytest.raises(freestand.InputError, match="^pga_g: expected a real number, got str"):
        freestand.assess(CASE, pga_g=["0.1"])
    with pytest.raises(TypeError, match="^damping: expected a real number, got bool"):
        freestand.response_spectrum(freestand.read_record(EL_CENTRO), damping=[0.05, True])
    with pytest.raises(freestand.InputError, match="^pga_g: expected a one-dimensional array of "
                                                   "real numbers, got a 1-dimensional array of "
                                                   "complex128"):
        freestand.assess(CASE, pga_g=np.array([0.1 + 1j]))


def test_fragility_takes_its_level_range_as_text():
    with pytest.raises(freestand.InputError, match="pga: value 1e-310 is out of range"):
        freestand.fragility(CASE, pga="1e-310,0.1", samples=2)


def test_a_level_near_zero_is_an_input_error():
    # The library's InputError, not an IndexError from an exception of the C++ runtime.
    with pytest.raises(freestand.InputError,
                       match=r"--pga: value 1e-310 is out of range; expected \[0.001, 3\]"):
        freestand.assess(CASE, pga_g=[1e-310, 0.1])
