"""read_record, response_spectrum, design_target and generate against values known without
freestand: an oscillator's closed-form response to a sine, RG 1.60's tabulated factors
(docs/methods.md s.8, from the Guide's Tables I and II), and the level a generated set was asked
for. Errors name the keyword the caller typed.
"""
import math

import numpy as np
import pytest

import freestand

G_MPS2 = 9.81  # freestand's g (core/units.hpp)
# RG 1.60 Rev. 2 Table I, horizontal, factors A (33 Hz) / B (9 Hz) / C (2.5 Hz) / D (0.25 Hz) at
# 2% and 5% damping; D multiplies 36 in (0.9144 m) of ground displacement per 1 g.
RG160_HORIZONTAL = {0.02: (1.0, 3.54, 4.25, 2.50), 0.05: (1.0, 2.61, 3.13, 2.05)}
RG160_DISPLACEMENT_M_PER_G = 0.9144


def sine(frequency_hz, cycles, amplitude_g, dt_s=0.0025):
    t = np.arange(0.0, cycles / frequency_hz + dt_s / 2, dt_s)
    return freestand.Record(amplitude_g * G_MPS2 * np.sin(2 * np.pi * frequency_hz * t), dt_s,
                            "sine")


def resonant_growth(cycles, damping):
    """PSA / PGA of an oscillator at rest driven at its own frequency for `cycles` cycles: the
    envelope of u'' + 2 z w u' + w^2 u = -a sin(w t) grows as (a / (2 z w^2)) (1 - exp(-z w t)),
    which tends to pi x cycles as z -> 0 (u = a (sin wt - wt cos wt) / (2 w^2))."""
    x = damping * 2 * np.pi * cycles
    return math.pi * cycles * (1 - math.exp(-x)) / x


def test_a_sine_at_an_oscillator_s_own_frequency_grows_as_the_closed_form():
    damping = 1e-4  # next to none: the growth is the undamped one within 1%
    psa = {}
    for cycles in (10, 20):
        s = freestand.response_spectrum(sine(2.0, cycles, 0.1), damping, frequencies=[2.0])
        assert s["pga_g"] == pytest.approx(0.1, rel=1e-9)
        psa[cycles] = s["psa_g"][str(damping)][0]
        assert psa[cycles] / 0.1 == pytest.approx(resonant_growth(cycles, damping), rel=0.02)
    # Twice the cycles, twice the amplitude: the growth is linear in time without damping.
    assert psa[20] / psa[10] == pytest.approx(2.0, rel=0.02)


def test_a_stiff_oscillator_follows_the_ground_so_its_psa_is_the_pga():
    s = freestand.response_spectrum(sine(2.0, 10, 0.25), [0.02, 0.05], fmin=50.0, fmax=100.0,
                                    per_decade=10)
    for damping in ("0.02", "0.05"):
        assert s["psa_g"][damping][-1] == pytest.approx(0.25, rel=0.01)
    # SD and PSV are PSA over w^2 and w.
    w = 2 * np.pi * s["frequencies_hz"]
    np.testing.assert_allclose(s["sd_m"]["0.05"] * w**2 / G_MPS2, s["psa_g"]["0.05"], rtol=1e-9)
    np.testing.assert_allclose(s["psv_mps"]["0.05"] * w / G_MPS2, s["psa_g"]["0.05"], rtol=1e-9)


@pytest.mark.parametrize("damping", sorted(RG160_HORIZONTAL))
def test_rg160_control_points_are_the_guide_s_factors_times_the_pga(damping):
    pga = 0.3
    a, b, c, d = RG160_HORIZONTAL[damping]
    t = freestand.design_target("rg1.60", pga=pga, damping=damping,
                                frequencies=[0.25, 2.5, 9.0, 33.0, 50.0])
    psa = t["psa_g"][str(damping)]
    sd_m = d * RG160_DISPLACEMENT_M_PER_G * pga
    assert psa[0] == pytest.approx((2 * np.pi * 0.25) ** 2 * sd_m / G_MPS2, rel=1e-9)
    assert psa[1] == pytest.approx(c * pga, rel=1e-9)
    assert psa[2] == pytest.approx(b * pga, rel=1e-9)
    assert psa[3] == pytest.approx(a * pga, rel=1e-9)
    assert psa[4] == pytest.approx(pga, rel=1e-9)  # rigid above 33 Hz


def test_design_values_are_typed_keywords():
    ec8 = freestand.design_target("ec8", ag=0.2, type=1, ground="B", frequencies=[2.0])
    # EC8 type 1 ground B: S = 1.2, TC = 0.5 s, so 0.5 s lies on the plateau 2.5 a_g S eta.
    assert ec8["psa_g"]["0.05"][0] == pytest.approx(2.5 * 0.2 * 1.2, rel=1e-9)
    asce = freestand.design_target("asce7", sds=1.0, sd1=0.6, tl=8.0, frequencies=[1.0])
    assert asce["psa_g"]["0.05"][0] == pytest.approx(0.6, rel=1e-9)  # SD1 / T at T = 1 s
    is1893 = freestand.design_target("is1893", pga=0.2, soil="soft", frequencies=[0.5])
    assert is1893["psa_g"]["0.05"][0] == pytest.approx(0.2 * 1.67 / 2.0, rel=1e-9)


def test_design_target_errors_name_the_keyword():
    with pytest.raises(TypeError, match=r"design_target\(\) got unexpected keyword argument\(s\) "
                                        r"colour"):
        freestand.design_target("rg1.60", pga=0.3, colour="red")
    with pytest.raises(TypeError, match="^pga: expected a real number, got str '0.3'"):
        freestand.design_target("rg1.60", pga="0.3")
    with pytest.raises(freestand.InputError, match="^pga: required by design rg1.60$"):
        freestand.design_target("rg1.60")
    with pytest.raises(freestand.InputError, match="^pga: does not apply to design asce7$"):
        freestand.design_target("asce7", sds=1.0, sd1=0.6, tl=8.0, pga=0.3)
    with pytest.raises(freestand.InputError, match="^tl: 0.3 s; expected more than TS"):
        freestand.design_target("asce7", sds=1.0, sd1=0.6, tl=0.3)
    with pytest.raises(freestand.InputError, match='^design: unknown design "rg1.70"'):
        freestand.design_target("rg1.70", pga=0.3)
    with pytest.raises(freestand.InputError, match="^damping: value 0.2 is out of range"):
        freestand.design_target("rg1.60", pga=0.3, damping=0.2)
    with pytest.raises(freestand.InputError, match='^ground: "F"; expected A, B, C, D or E'):
        freestand.design_target("ec8", ag=0.2, type=1, ground="F")


def test_response_spectrum_errors_name_the_keyword():
    rec = sine(2.0, 4, 0.1)
    with pytest.raises(freestand.InputError, match="^fmax: 1 Hz; expected more than the lowest "
                                                   "frequency 10 Hz"):
        freestand.response_spectrum(rec, fmin=10.0, fmax=1.0)
    with pytest.raises(freestand.InputError, match="^frequencies: 1 Hz follows 2 Hz"):
        freestand.response_spectrum(rec, frequencies=[2.0, 1.0])
    with pytest.raises(freestand.InputError, match="^damping: 0.05 given twice"):
        freestand.response_spectrum(rec, [0.05, 0.05])
    with pytest.raises(freestand.InputError, match=r"^per_decade: 2.5; expected an integer"):
        freestand.response_spectrum(rec, per_decade=2.5)
    with pytest.raises(TypeError, match="^frequencies and fmin exclude each other"):
        freestand.response_spectrum(rec, frequencies=[1.0, 2.0], fmin=0.5)
    with pytest.raises(TypeError, match="^damping: expected a real number, got str"):
        freestand.response_spectrum(rec, "0.05")


def test_a_generated_set_has_the_requested_pga_and_sampling():
    pga = 0.25
    match, records = freestand.generate("rg1.60", pga=pga, seed=5, components=["h1"], dt=0.01,
                                        duration=20.0, timing=False)
    h1 = records["h1"]
    assert h1.dt_s == 0.01
    assert len(h1.accel_mps2) * h1.dt_s == pytest.approx(20.0, abs=0.02)
    pga_got = np.max(np.abs(h1.accel_mps2)) / G_MPS2
    # RG 1.60's zero-period acceleration is its PGA; the realism check keeps PGA/ZPA in [1, 1.1].
    assert pga <= pga_got <= 1.1 * pga
    assert match["components"][0]["pga_g"] == pytest.approx(pga_got, rel=1e-12)
    assert match["components"][0]["wall_s"] is None


def test_generate_errors_name_the_keyword(tmp_path):
    with pytest.raises(TypeError, match=r"generate\(\) got unexpected keyword argument\(s\) "
                                        r"colour"):
        freestand.generate("rg1.60", pga=0.2, colour="red")
    with pytest.raises(freestand.InputError, match="^sds: does not apply to design rg1.60"):
        freestand.generate("rg1.60", pga=0.2, sds=1.0)
    with pytest.raises(freestand.InputError, match="^target: no target"):
        freestand.generate(pga=0.2)
    with pytest.raises(freestand.InputError, match="^dt: dt 0.02 s is too coarse"):
        freestand.generate("rg1.60", pga=0.2, dt=0.02)
    with pytest.raises(TypeError, match=r"^va_range: expected \(min, max\), got 1 number"):
        freestand.generate("rg1.60", pga=0.2, va_range=[0.8])
    with pytest.raises(TypeError, match="^seed: expected a whole number"):
        freestand.generate("rg1.60", pga=0.2, seed=1.5)
    with pytest.raises(freestand.IoError, match="nowhere.csv"):
        freestand.generate(target_file=tmp_path / "nowhere.csv")
