"""ssfx.aa(..., backend='vulkan') (issue #36, item 5, for the anti-aliasing methods): the GPU
passes from Python on one Vulkan context per process, the CPU's bytes in the model (the
default sampling), the same bytes as the CLI's --backend vulkan, and ssfx's errors for a
missing device and for the vulkan-only choices. These run on lavapipe where no GPU exists, and
skip, saying why, only where there is no Vulkan device at all.
Run through ctest (python.pytest), which sets PYTHONPATH and SSFX_CLI."""
import os
import subprocess

import numpy as np
import pytest

import ssfx


def _vulkan():
    try:
        ssfx.aa(np.zeros((4, 4, 4), np.uint8), "blur", backend="vulkan")
        return None
    except ssfx.Error as e:
        return str(e)


NO_DEVICE = _vulkan()
needs_device = pytest.mark.skipif(NO_DEVICE is not None, reason=f"no Vulkan device: {NO_DEVICE}")


def random_image(h, w, seed):
    rng = np.random.default_rng(seed)
    img = (rng.random((h, w, 4)) < 0.5).astype(np.uint8) * 200 + 20  # hard edges
    img[..., 3] = 255
    return img


@needs_device
@pytest.mark.parametrize("method", [m["id"] for m in ssfx.methods("aa")])
def test_model_gives_the_cpu_bytes(method):
    scale = {"ssaax2": 2, "ddaa2p": 2, "ssaax4": 4}.get(method, 1)
    img = random_image(24 * scale, 40 * scale, 3)
    cpu = ssfx.aa(img, method)
    for edges in ("auto", "list", "one-pass"):
        assert np.array_equal(ssfx.aa(img, method, backend="vulkan", edges=edges), cpu), (method, edges)


@needs_device
@pytest.mark.parametrize("method", ["blur", "fxaa3c", "ddaa2", "ssaax2"])
def test_srgb_textures_give_the_cpu_bytes(method):
    # texture="srgb" (issue #34 item 4): an R8G8B8A8_SRGB view, decoded and encoded exactly.
    scale = 2 if method == "ssaax2" else 1
    img = random_image(24 * scale, 40 * scale, 11)
    cpu = ssfx.aa(img, method, texture="srgb")
    assert not np.array_equal(cpu, ssfx.aa(img, method)), method  # the texture must matter
    assert np.array_equal(ssfx.aa(img, method, texture="srgb", backend="vulkan"), cpu), method


@needs_device
def test_the_same_bytes_as_the_cli(tmp_path):
    img = random_image(30, 50, 5)
    src, dst = tmp_path / "in.png", tmp_path / "out.png"
    ssfx.io.write_png(src, img)
    cli = os.environ.get("SSFX_CLI", "ssfx")
    subprocess.run([cli, "aa", "-m", "fxaa3d", "--backend", "vulkan", "--preset", "high", str(src), "-o", str(dst)],
                   check=True)
    assert np.array_equal(ssfx.io.read_png(dst), ssfx.aa(img, "fxaa3d", preset="high", backend="vulkan"))


@needs_device
def test_out_three_channels_and_hardware_sampling():
    img = random_image(20, 32, 7)
    out = np.zeros((20, 32, 3), np.uint8)
    ssfx.aa(img[..., :3], "ddaa2", backend="vulkan", out=out)
    assert np.array_equal(out, ssfx.aa(img[..., :3], "ddaa2"))
    hw = ssfx.aa(img, "ddaa2", backend="vulkan", sampling="hardware").astype(int)
    diff = np.abs(hw - ssfx.aa(img, "ddaa2").astype(int))[..., :3].max(axis=2)
    assert (diff <= 2).mean() >= 0.99  # the device's precision (docs/gpu.md)


@pytest.mark.parametrize("kwargs, words", [
    (dict(backend="metal"), "backend: 'metal' is not cpu or vulkan"),
    (dict(device="0"), "device: goes with backend='vulkan'"),
    (dict(sampling="hardware"), "sampling: a choice of backend='vulkan'"),
    (dict(edges="list"), "edges: a choice of backend='vulkan'"),
    (dict(backend="vulkan", device="no-such-gpu"), "looked for a Vulkan 1.3 device with a compute queue matching "
                                                   "'no-such-gpu'"),
])
def test_bad_choices_are_refused(kwargs, words):
    with pytest.raises(ssfx.Error, match=words.replace("(", r"\(").replace(")", r"\)")):
        ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", **kwargs)


@needs_device
@pytest.mark.parametrize("kwargs, words", [
    (dict(sampling="fast"), "sampling 'fast': expected model or hardware"),
    (dict(edges="tiles"), "edges 'tiles': expected auto, list or one-pass"),
    (dict(filtering="exact"), "exact filtering is a CPU option"),
])
def test_bad_vulkan_settings_are_refused(kwargs, words):
    with pytest.raises(ssfx.Error, match=words):
        ssfx.aa(np.zeros((8, 8, 4), np.uint8), "ddaa2", backend="vulkan", **kwargs)
