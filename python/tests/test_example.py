"""examples/python/sweep_and_plot.py runs and writes a PNG."""
import os
import subprocess
import sys

from conftest import SOURCE_DIR


def test_sweep_and_plot_writes_a_png(tmp_path):
    png = tmp_path / "plots" / "sweep.png"
    p = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "python" / "sweep_and_plot.py"), str(png)],
                       capture_output=True, text=True, env=os.environ)
    assert p.returncode == 0, p.stderr
    assert png.exists() and png.stat().st_size > 1000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "wrote" in p.stdout
