"""The Python boundary (issue #35, items 4, 15 and 16): Python's split between a wrong type
(TypeError) and a bad value (ssfx.Error, a ValueError), each with a short message in ssfx's
words naming the argument; numpy scalars as numbers; paths with a NUL byte refused rather
than cut; out= arrays that overlap themselves or the input refused.
Run through ctest (python.pytest), which sets PYTHONPATH."""
import pathlib

import numpy as np
import pytest
from numpy.lib.stride_tricks import as_strided

import ssfx

IMG = np.arange(16 * 16 * 4, dtype=np.uint8).reshape(16, 16, 4)
DEPTH = np.full((12, 12), 0.5, np.float32)
CAMERA = {"fov_y_deg": 60, "z_near": -0.1, "z_far": None}


def short(message):
    """ssfx's words, not pybind11's: one line, no signature listing."""
    assert "\n" not in message and "incompatible function arguments" not in message, message
    assert "Unable to cast" not in message, message


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: ssfx.aa(IMG.tolist()), ["image", "numpy array", "list"]),
        (lambda: ssfx.aa(None), ["image", "NoneType"]),
        (lambda: ssfx.aa(IMG, 3), ["method", "str", "int"]),
        (lambda: ssfx.aa(IMG, "ddaa2", threads=2.5), ["threads", "int", "float"]),
        (lambda: ssfx.aa(IMG, "ddaa2", threads="2"), ["threads", "int", "str"]),
        (lambda: ssfx.aa(IMG, "ddaa2", threads=True), ["threads", "int", "bool"]),
        (lambda: ssfx.aa(IMG, "ddaa2", preset=1), ["preset", "str"]),
        (lambda: ssfx.aa(IMG, "ddaa2", filtering=None), ["filtering", "str"]),
        (lambda: ssfx.aa(IMG, "ddaa2", out=[1]), ["out", "numpy array"]),
        (lambda: ssfx.aa(IMG, "ddaa2", strength=[1]), ["strength", "number"]),
        (lambda: ssfx.aa(IMG, "ddaa2", strength=None), ["strength", "number"]),
        (lambda: ssfx.resample(IMG, 2.0), ["factor", "int"]),
        (lambda: ssfx.methods(1), ["family", "str"]),
        (lambda: ssfx.ao.sao(DEPTH, 60), ["camera", "dict"]),
        (lambda: ssfx.ao.sao(DEPTH, {**CAMERA, "z_near": [1]}), ["z_near", "number"]),
        (lambda: ssfx.ao.sao(DEPTH.tolist(), CAMERA), ["depth", "numpy array"]),
        (lambda: ssfx.io.read_png(3), ["path", "str"]),
        (lambda: ssfx.io.write_apng("x.png", IMG), ["frames", "list"]),
        (lambda: ssfx.io.write_apng("x.png", [IMG], fps="25"), ["fps", "number"]),
        (lambda: ssfx.metrics.psnr(IMG, None), ["b", "numpy array"]),
    ],
)
def test_a_wrong_type_is_a_type_error_naming_the_argument(call, words):
    with pytest.raises(TypeError) as e:
        call()
    assert not isinstance(e.value, ssfx.Error)
    short(str(e.value))
    for w in words:
        assert w in str(e.value), str(e.value)


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: ssfx.aa(IMG, "ddaa2", strength=10**400), ["strength", "too large"]),
        (lambda: ssfx.aa(IMG, "ddaa2", threads=2**40), ["threads", "1099511627776", "[0, 1024]"]),
        (lambda: ssfx.aa(IMG, "ddaa2", threads=2**80), ["threads", "[0, 1024]"]),
        (lambda: ssfx.aa(IMG, "ddaa2", strength=np.float32(1e9)), ["strength"]),
        (lambda: ssfx.ao.sao(DEPTH, {**CAMERA, "fov_y_deg": float("nan")}), ["fov_y_deg", "nan", "finite"]),
        (lambda: ssfx.ao.sao(DEPTH, {**CAMERA, "z_near": np.float32("inf")}), ["z_near", "finite"]),
        (lambda: ssfx.ao.sao(DEPTH, {**CAMERA, "fov_y_deg": 180}), ["fov_y_deg", "(0, 180) degrees"]),
    ],
)
def test_a_bad_value_is_an_ssfx_error_naming_the_argument(call, words):
    with pytest.raises(ssfx.Error) as e:
        call()
    short(str(e.value))
    for w in words:
        assert w in str(e.value), str(e.value)


def test_numpy_scalars_are_numbers():
    want = ssfx.aa(IMG, "ddaa2", strength=2.0, searchRounds=3, threads=1)
    assert np.array_equal(ssfx.aa(IMG, "ddaa2", strength=np.float32(2), searchRounds=np.int64(3), threads=np.int64(1)), want)
    assert np.array_equal(ssfx.aa(IMG, "ddaa2", strength=np.float64(2), searchRounds=np.int32(3)), want)
    cam = {"fov_y_deg": np.float32(60), "z_near": np.float64(-0.1), "z_far": None}
    assert np.array_equal(ssfx.ao.sao(DEPTH, cam), ssfx.ao.sao(DEPTH, CAMERA))
    assert np.array_equal(ssfx.ao.sao(DEPTH, CAMERA, guardBand=np.int64(2)), ssfx.ao.sao(DEPTH, CAMERA, guardBand=2))


def test_a_nul_byte_in_a_path_is_refused_for_every_path_argument(tmp_path):
    victim = tmp_path / "victim"
    victim.write_text("keep")
    good = tmp_path / "a.png"
    ssfx.io.write_png(str(good), IMG)
    calls = [
        lambda: ssfx.io.write_png(str(victim) + "\0.png", IMG),
        lambda: ssfx.io.read_png(str(good) + "\0junk"),
        lambda: ssfx.io.write_apng(str(victim) + "\0.png", [IMG]),
        lambda: ssfx.io.read_apng(str(good) + "\0junk"),
        lambda: ssfx.io.write_exr(str(victim) + "\0.exr", DEPTH),
        lambda: ssfx.io.read_exr(str(victim) + "\0.exr"),
        lambda: ssfx.ao.sao(DEPTH, str(victim) + "\0.json"),
    ]
    for call in calls:
        with pytest.raises(ssfx.Error, match="NUL byte") as e:
            call()
        assert "victim\\0" in str(e.value) or "a.png\\0junk" in str(e.value), str(e.value)
    assert victim.read_text() == "keep"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png", "victim"]


def test_paths_may_be_path_like(tmp_path):
    ssfx.io.write_png(tmp_path / "p.png", IMG)
    assert np.array_equal(ssfx.io.read_png(tmp_path / "p.png"), IMG)
    ssfx.io.write_exr(pathlib.Path(tmp_path / "d.exr"), DEPTH)
    assert np.array_equal(ssfx.io.read_exr(tmp_path / "d.exr"), DEPTH)


def test_an_out_that_overlaps_itself_or_the_input_is_refused():
    buf = np.zeros((16, 16, 4), np.uint8)
    for strides in [(4, 4, 1), (0, 0, 1), (64, 4, 0), (1, 4, 1)]:
        with pytest.raises(ssfx.Error, match="overlap one another"):
            ssfx.aa(IMG, "ddaa2", out=as_strided(buf, shape=(16, 16, 4), strides=strides))
    img = IMG.copy()
    with pytest.raises(ssfx.Error, match="must not overlap the image"):
        ssfx.aa(img, "ddaa2", out=img)
    with pytest.raises(ssfx.Error, match="must not overlap the image"):
        ssfx.aa(img[:, :8], "ddaa2", out=img[:, 4:12])
    assert np.array_equal(img, IMG)  # refused before anything was written
    # Layouts whose elements are distinct are taken, however they are strided.
    big = np.zeros((16, 32, 4), np.uint8)
    want = ssfx.aa(IMG, "ddaa2")
    ssfx.aa(IMG, "ddaa2", out=big[:, ::2])
    assert np.array_equal(big[:, ::2], want)
    fortran = np.asfortranarray(np.zeros((16, 16, 4), np.uint8))
    ssfx.aa(IMG, "ddaa2", out=fortran)
    assert np.array_equal(fortran, want)
