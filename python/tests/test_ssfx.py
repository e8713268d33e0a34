"""The Python module against the ssfx tool: the same bytes for every method and preset, the
array layouts it takes without a copy, and a clear ssfx.Error for every bad argument.
Run through ctest (python.pytest), which sets PYTHONPATH and SSFX_CLI."""
import json
import os
import subprocess

import numpy as np
import pytest

import ssfx

CLI = os.environ.get("SSFX_CLI", "ssfx")
PRESETS = ["low", "medium", "high", "ultra", "extreme"]


def drawing(w, h, seed=0):
    """An aliased drawing: discs, lines and a few flat colours, alpha varying."""
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:h, 0:w]
    img = np.full((h, w, 4), 255, np.uint8)
    for _ in range(6):
        cx, cy, r = rng.uniform(0, w), rng.uniform(0, h), rng.uniform(3, w / 3)
        img[(x - cx) ** 2 + (y - cy) ** 2 < r * r, :3] = rng.integers(0, 256, 3)
    for _ in range(6):
        a, b = rng.uniform(-2, 2), rng.uniform(0, h)
        img[np.abs(y - (a * x + b)) < rng.uniform(0.4, 2), :3] = rng.integers(0, 256, 3)
    img[..., 3] = rng.integers(128, 256, (h, w))
    return img


def cli(*args):
    r = subprocess.run([CLI, *args], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def aa_methods():
    return ssfx.methods("aa")


def test_error_is_a_value_error():
    assert issubclass(ssfx.Error, ValueError)


def test_methods_match_the_cli():
    ours = {m["id"]: m for m in ssfx.methods()}
    theirs = json.loads(cli("methods", "--json"))
    theirs = theirs["methods"] if isinstance(theirs, dict) and "methods" in theirs else theirs
    theirs = [t for t in theirs if t["family"] in ("aa", "ao")]  # (the deferred family has no Python API yet)
    assert [m["id"] for m in ssfx.methods()] == [t["id"] for t in theirs]
    for t in theirs:
        o = ours[t["id"]]
        assert o["summary"] == t["summary"]
        assert [p["name"] for p in o["params"]] == [p["name"] for p in t["params"]]
    ddaa2 = ours["ddaa2"]
    strength = next(p for p in ddaa2["params"] if p["name"] == "strength")
    assert strength["default"] == 3.0 and strength["min"] == 0 and strength["max"] == 100
    texture = next(p for p in ddaa2["params"] if p["name"] == "texture")
    assert texture["choices"] == ["unorm", "srgb"] and texture["default"] == "unorm"
    assert ddaa2["presets"][0] == "medium"
    assert {m["family"] for m in ssfx.methods("ao")} == {"ao"}


@pytest.mark.parametrize("method", [m["id"] for m in aa_methods()])
def test_bytes_equal_the_cli_for_every_preset(tmp_path, method):
    m = next(x for x in aa_methods() if x["id"] == method)
    s = m["input_scale"]
    img = drawing(40 * s, 30 * s, seed=s)
    path = str(tmp_path / "in.png")
    ssfx.io.write_png(path, img)
    for preset in [None] + (PRESETS if m["presets"] else []):
        out = str(tmp_path / "out.png")
        cli("aa", "-m", method, path, "-o", out, *(["--preset", preset] if preset else []))
        want = ssfx.io.read_png(out)
        got = ssfx.aa(img, method, preset=preset)
        assert got.shape == want.shape and got.dtype == np.uint8
        assert np.array_equal(got, want), f"{method} preset {preset}"


def test_parameters_and_srgb_equal_the_cli(tmp_path):
    img = drawing(48, 40)
    path, out = str(tmp_path / "in.png"), str(tmp_path / "out.png")
    ssfx.io.write_png(path, img)
    cli("aa", "-m", "ddaa2", "-p", "strength=2", "-p", "searchRounds=3", "-p", "texture=srgb", path, "-o", out)
    got = ssfx.aa(img, "ddaa2", strength=2, searchRounds=3, texture="srgb")
    assert np.array_equal(got, ssfx.io.read_png(out))
    cli("aa", "-m", "fxaa3d", "--filtering", "exact", "-p", "paperSearchQuirk=false", path, "-o", out)
    got = ssfx.aa(img, "fxaa3d", filtering="exact", paperSearchQuirk=False)
    assert np.array_equal(got, ssfx.io.read_png(out))


def test_three_channels_in_three_out():
    img = drawing(50, 40)
    rgb = np.ascontiguousarray(img[..., :3])
    opaque = img.copy()
    opaque[..., 3] = 255
    out = ssfx.aa(rgb, "ddaa2")
    assert out.shape == (40, 50, 3)
    assert np.array_equal(out, ssfx.aa(opaque, "ddaa2")[..., :3])


def test_strided_views_give_the_same_bytes():
    big = drawing(90, 70, seed=3)
    for view in (big[5:60, 7:80], big[::2], big[:, ::-1], big[..., [2, 1, 0, 3]], np.asfortranarray(big)):
        assert np.array_equal(ssfx.aa(view, "ddaa2"), ssfx.aa(np.ascontiguousarray(view), "ddaa2"))


def test_out_writes_into_the_callers_array():
    img = drawing(40, 30)
    out = np.zeros((30, 40, 4), np.uint8)
    ret = ssfx.aa(img, "fxaa3c", out=out)
    assert ret is out
    assert np.array_equal(out, ssfx.aa(img, "fxaa3c"))
    half = np.zeros((15, 20, 4), np.uint8)
    ssfx.aa(drawing(40, 30), "ssaax2", out=half)
    assert np.array_equal(half, ssfx.aa(drawing(40, 30), "ssaax2"))
    # A strided destination: written through its strides.
    canvas = np.zeros((30, 80, 4), np.uint8)
    ssfx.aa(img, "ddaa2", out=canvas[:, ::2])
    assert np.array_equal(canvas[:, ::2], ssfx.aa(img, "ddaa2"))
    assert not canvas[:, 1::2].any()


def test_threads_do_not_change_the_bytes():
    img = drawing(120, 90)
    for m in ("ddaa2", "fxaa3d", "blur"):
        assert np.array_equal(ssfx.aa(img, m, threads=1), ssfx.aa(img, m, threads=3))


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.float32)), ["image", "uint8"]),
        (lambda: ssfx.aa(np.zeros((8, 8), np.uint8)), ["image", "shape"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 2), np.uint8)), ["image", "shape"]),
        (lambda: ssfx.aa(np.zeros((0, 8, 4), np.uint8)), ["image"]),
        # 4e8 pixels (a zero-stride view: no memory), above the 2^28 limit: refused before any copy.
        (lambda: ssfx.aa(np.broadcast_to(np.zeros((1, 1, 4), np.uint8), (20000, 20000, 4))), ["image"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "nope"), ["nope"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", strength=1000), ["strength", "100"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", searchRounds=2.5), ["searchRounds"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", texture="linear"), ["texture", "linear"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", bogus=1), ["bogus"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", preset="max"), ["preset", "max"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "blur", preset="high"), ["presets"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", filtering="fast"), ["filtering"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", threads=-1), ["threads"]),
        (lambda: ssfx.aa(np.zeros((9, 8, 4), np.uint8), "ssaax2"), ["divisible"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), out=np.zeros((8, 7, 4), np.uint8)), ["out", "shape"]),
        (lambda: ssfx.aa(np.zeros((8, 8, 4), np.uint8), out=np.zeros((8, 8, 3), np.uint8)), ["out"]),
        (lambda: ssfx.methods("deferred"), ["family"]),
    ],
)
def test_bad_arguments_raise_ssfx_error(call, words):
    with pytest.raises(ssfx.Error) as e:
        call()
    for w in words:
        assert w in str(e.value)


def test_out_read_only_or_overlapping_is_refused():
    img = drawing(16, 16)
    ro = np.zeros_like(img)
    ro.flags.writeable = False
    with pytest.raises(ssfx.Error, match="read-only"):
        ssfx.aa(img, out=ro)
    with pytest.raises(ssfx.Error, match="overlap"):
        ssfx.aa(img, out=img)


def test_io_round_trips(tmp_path):
    img = drawing(33, 21)
    p = str(tmp_path / "a.png")
    ssfx.io.write_png(p, img)
    assert np.array_equal(ssfx.io.read_png(p), img)
    frames = [drawing(20, 10, seed=i) for i in range(3)]
    ssfx.io.write_apng(str(tmp_path / "a.apng"), frames, fps=20)
    back = ssfx.io.read_apng(str(tmp_path / "a.apng"))
    assert len(back) == 3 and all(np.array_equal(f, g) for (f, _), g in zip(back, frames))
    assert back[0][1] == pytest.approx(0.05)
    z = np.linspace(0, 1, 6 * 4, dtype=np.float32).reshape(4, 6)
    ssfx.io.write_exr(str(tmp_path / "z.exr"), z, "Z")
    assert np.array_equal(ssfx.io.read_exr(str(tmp_path / "z.exr")), z)
    with pytest.raises(ssfx.Error, match="missing.png"):
        ssfx.io.read_png(str(tmp_path / "missing.png"))
    with pytest.raises(ssfx.Error, match="first frame"):
        ssfx.io.write_apng(str(tmp_path / "b.apng"), [frames[0], drawing(10, 10)])
    assert not (tmp_path / "b.apng").exists()


def test_metrics_match_their_definitions():
    a, b = drawing(64, 48, 1), drawing(64, 48, 2)
    assert ssfx.metrics.psnr(a, a) == float("inf")
    mse = np.mean(((a[..., :3].astype(np.float64) - b[..., :3]) / 255.0) ** 2)
    assert ssfx.metrics.psnr(a, b) == pytest.approx(10 * np.log10(1 / mse), rel=1e-9)
    assert ssfx.metrics.ssim(a, a) == pytest.approx(1.0)
    assert 0 < ssfx.metrics.ssim(a, b) < 1
    with pytest.raises(ssfx.Error, match="same size"):
        ssfx.metrics.psnr(a, a[:10])


def test_ao_equals_the_cli(tmp_path):
    d, c = str(tmp_path / "d.exr"), str(tmp_path / "c.json")
    cli("ao", "--scene", "room", "--size", "96x54", "-p", "guardBand=8", "--save-depth", d, "--save-camera", c,
        "-o", str(tmp_path / "sao.exr"))
    cli("ao", "-m", "alchemy", "--depth", d, "--camera", c, "-p", "guardBand=8", "-o", str(tmp_path / "alch.exr"))
    depth = ssfx.io.read_exr(d)
    camera = json.load(open(c))
    got = ssfx.ao.sao(depth, camera, guardBand=8)
    assert got.dtype == np.float32 and got.shape == (54, 96)
    assert np.array_equal(got, ssfx.io.read_exr(str(tmp_path / "sao.exr")))
    assert np.array_equal(ssfx.ao.alchemy(depth, c, guardBand=8), ssfx.io.read_exr(str(tmp_path / "alch.exr")))
    with pytest.raises(ssfx.Error, match="float32"):
        ssfx.ao.sao(depth.astype(np.float64), camera)
    with pytest.raises(ssfx.Error, match="fov_y_deg|z_near"):
        ssfx.ao.sao(depth, {"fov": 60})
    bad = depth.copy()
    bad[3, 3] = np.nan
    with pytest.raises(ssfx.Error):
        ssfx.ao.sao(bad, camera, guardBand=8)


def test_gtao_comes_from_the_registry_and_equals_the_cli(tmp_path):
    d, c, g = str(tmp_path / "d.exr"), str(tmp_path / "c.json"), str(tmp_path / "g.exr")
    cli("ao", "--scene", "room", "--size", "64x36", "-p", "guardBand=8", "--save-depth", d, "--save-camera", c,
        "-o", str(tmp_path / "sao.png"))
    cli("ao", "-m", "gtao", "--preset", "ultra", "--depth", d, "--camera", c, "-p", "guardBand=8", "-p", "radius=1",
        "-o", g)
    depth = ssfx.io.read_exr(d)
    got = ssfx.ao.gtao(depth, c, preset="ultra", guardBand=8, radius=1.0)
    assert got.dtype == np.float32 and got.shape == (36, 64)
    assert np.array_equal(got, ssfx.io.read_exr(g))
    assert "gtao" in ssfx.ao.__all__ and "Ground-Truth" in ssfx.ao.gtao.__doc__
    with pytest.raises(ssfx.Error, match="unknown preset"):
        ssfx.ao.gtao(depth, c, preset="extreme")
    with pytest.raises(ssfx.Error, match="radius"):
        ssfx.ao.gtao(depth, c, radius=0.0)
    with pytest.raises(ssfx.Error, match="not cpu or vulkan"):
        ssfx.ao.gtao(depth, c, backend="opengl")


def test_docstrings_and_stubs_come_from_the_registries():
    for m in aa_methods():
        assert m["id"] in ssfx.aa.__doc__
    stub = open(os.path.join(os.path.dirname(ssfx.__file__), "__init__.pyi")).read()
    for m in aa_methods():
        assert f"Literal[{m['id']!r}]" in stub
        for p in m["params"]:
            assert f"{p['name']}:" in stub
