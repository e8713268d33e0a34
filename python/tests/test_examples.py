"""The worked examples, run small: examples/matplotlib_ddaa.py (matplotlib drawing without
anti-aliasing, every method through ssfx.aa, scored two ways)."""
import os
import subprocess
import sys

import numpy as np
import pytest

import ssfx

SOURCE = os.environ.get("SSFX_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))


def test_matplotlib_example(tmp_path):
    pytest.importorskip("matplotlib", reason="python3-matplotlib not installed")
    r = subprocess.run([sys.executable, os.path.join(SOURCE, "examples", "matplotlib_ddaa.py"), "--out",
                        str(tmp_path), "--dpi", "30"], capture_output=True, text=True, env=os.environ)
    assert r.returncode == 0, r.stderr
    rows = {}
    for line in open(tmp_path / "table.md"):
        if line.startswith("| `"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            rows[cells[0].strip("`")] = [float(c) for c in cells[1:]]
    assert set(rows) == {m["id"] for m in ssfx.methods("aa")}
    # The resolves see 4x and 16x the samples: closer to the resolved truth than no AA.
    assert rows["ssaax4"][2] > rows["ssaax2"][2] > rows["noaa"][2]
    # Every row's numbers are what the written images give.
    truth = ssfx.io.read_png(str(tmp_path / "plot_truth.png"))
    ddaa2 = ssfx.io.read_png(str(tmp_path / "plot_ddaa2.png"))
    assert ssfx.metrics.psnr(ddaa2, truth) == pytest.approx(rows["ddaa2"][2], abs=0.005)
    x1 = ssfx.io.read_png(str(tmp_path / "plot.png"))
    assert x1.shape == (90, 120, 4)
    assert np.array_equal(ssfx.aa(x1, "ddaa2"), ddaa2)


def test_dask_example_matches_the_cli(tmp_path):
    pytest.importorskip("distributed", reason="python3-distributed not installed")
    sys.path.insert(0, os.path.join(SOURCE, "examples"))
    import dask_frames

    rng = np.random.default_rng(5)
    src = tmp_path / "in"
    src.mkdir()
    for i in range(8):  # eight different aliased frames
        img = np.full((48, 64, 4), 255, np.uint8)
        y, x = np.mgrid[0:48, 0:64]
        img[(x - 32 - 3 * i) ** 2 + (y - 24) ** 2 < 200, :3] = rng.integers(0, 256, 3)
        img[np.abs(y - 0.4 * x - i) < 0.6, :3] = 0
        ssfx.io.write_png(str(src / f"f.{i:04d}.png"), img)
    done, _ = dask_frames.run(str(src), str(tmp_path / "dask"), "ddaa2", workers=2)
    assert len(done) == 8
    cli = os.environ.get("SSFX_CLI", "ssfx")
    subprocess.run([cli, "aa", "-m", "ddaa2", str(src), "-o", str(tmp_path / "cli")], check=True)
    for i in range(8):
        name = f"f.{i:04d}.png"
        assert (tmp_path / "dask" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
