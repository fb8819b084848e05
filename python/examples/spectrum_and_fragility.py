# %% [markdown]
# # freestand from Python: a spectrum and a fragility curve
#
# A notebook in the "percent" format: each `# %%` is a cell (Jupyter with jupytext, VS Code and
# Spyder run them one by one); `python3 spectrum_and_fragility.py [OUT_DIR] [SAMPLES]` runs it
# whole and writes the two figures as PNG files. Needs the module on PYTHONPATH
# (README "Python") and Debian's python3-matplotlib.

# %%
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files, no window: the same in a notebook, a terminal or CI
import matplotlib.pyplot as plt
import numpy as np

import freestand

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
OUT = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path("out/python-example")
SAMPLES = int(sys.argv[2]) if len(sys.argv) > 2 else 20
OUT.mkdir(parents=True, exist_ok=True)
print(f"freestand {freestand.__version__} ({freestand.commit})")

# %% [markdown]
# ## A record and its response spectrum against the design target
# El Centro 1940 (PEER NGA-West2 RSN 175, component 140) against RG 1.60 anchored at 0.3 g,
# both at 5% damping.

# %%
record = freestand.read_record(ROOT / "tests/data/RSN175_IMPVALL.H_H-E12140.AT2")
print(f"{record.name}: {len(record.accel_mps2)} samples at {record.dt_s} s, "
      f"PGA {np.max(np.abs(record.accel_g)):.3f} g")
spectrum = freestand.response_spectrum(record, 0.05)
target = freestand.design_target("rg1.60", pga=0.3, damping=0.05)

fig, ax = plt.subplots(figsize=(7, 4.5))
ax.loglog(spectrum["frequencies_hz"], spectrum["psa_g"]["0.05"], label=f"{record.name} (5%)")
ax.loglog(target["frequencies_hz"], target["psa_g"]["0.05"], "k--", label="RG 1.60 at 0.3 g (5%)")
ax.set_xlabel("frequency (Hz)")
ax.set_ylabel("pseudo-spectral acceleration (g)")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(OUT / "spectrum.png", dpi=100)
print(f"wrote {OUT / 'spectrum.png'}")

# %% [markdown]
# ## Fragility of test block TS1 on steel
# P(overturn), P(slide > allowable) and P(theta/alpha > 1/FS) against PGA, with the 95%
# intervals and the lognormal fits (docs/methods.md s.9). More samples narrow the intervals.

# %%
levels = [0.2, 0.4, 0.6, 0.8, 1.0]
frag = freestand.fragility(ROOT / "cases/block-ts1.toml", pga=levels, samples=SAMPLES, seed=1)
pga = np.array([lvl["pga_g"] for lvl in frag["levels"]])
fig, ax = plt.subplots(figsize=(7, 4.5))
grid = np.linspace(0.05, 1.1, 200)
for event, colour in (("overturn", "C3"), ("slide", "C0"), ("rock", "C1")):
    p = np.array([lvl["events"][event]["p"] for lvl in frag["levels"]])
    ci = np.array([lvl["events"][event]["ci"] for lvl in frag["levels"]])
    ax.errorbar(pga, p, yerr=[p - ci[:, 0], ci[:, 1] - p], fmt="o", color=colour, capsize=3,
                label=f"{event}: {frag['inputs']['events'][event]}")
    fit = frag["fit"][event]
    if fit is not None:
        # Lognormal fragility P = Phi(ln(a / theta) / beta), Phi by the error function.
        z = np.log(grid / fit["theta_m_g"]) / fit["beta"]
        ax.plot(grid, 0.5 * (1 + np.vectorize(math.erf)(z / np.sqrt(2))), color=colour)
ax.set_xlabel("PGA (g)")
ax.set_ylabel("probability")
ax.set_ylim(-0.02, 1.02)
ax.grid(True, alpha=0.3)
ax.legend(fontsize=7)
ax.set_title(f"{frag['inputs']['case']}: {SAMPLES} samples per level")
fig.tight_layout()
fig.savefig(OUT / "fragility.png", dpi=100)
print(f"wrote {OUT / 'fragility.png'}")
