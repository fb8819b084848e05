"""The notebook-style example python/examples/spectrum_and_fragility.py runs and draws its figures."""
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "python" / "examples" / "spectrum_and_fragility.py"


def png_size(path):
    """Width and height from a PNG's IHDR chunk."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


def test_the_example_writes_a_spectrum_and_a_fragility_figure(tmp_path):
    p = subprocess.run([sys.executable, str(EXAMPLE), str(tmp_path), "4"], capture_output=True,
                       text=True, timeout=240, env=dict(os.environ, MPLBACKEND="Agg"))
    assert p.returncode == 0, p.stderr
    for name in ("spectrum.png", "fragility.png"):
        assert png_size(tmp_path / name) == (700, 450)
        assert (tmp_path / name).stat().st_size > 10_000, f"{name} looks empty"
    assert "wrote" in p.stdout
