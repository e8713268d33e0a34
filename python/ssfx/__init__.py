"""ssfx: screen-space rendering effects (post-processing anti-aliasing, resolves, ambient
obscurance) on numpy arrays, with the C++ library's exact bytes. See docs/python.md.

    import ssfx
    out = ssfx.aa(image, "ddaa2")             # (H, W, 4) or (H, W, 3) uint8
    ssfx.methods("aa")                        # ids, parameters, defaults, ranges, presets
    vis = ssfx.ao.sao(depth, {"fov_y_deg": 60, "z_near": -0.1, "z_far": None}, guardBand=16)
"""
from ._ssfx import Error, aa, methods, resample
from . import ao, io, metrics

__all__ = ["Error", "aa", "methods", "resample", "ao", "io", "metrics"]
