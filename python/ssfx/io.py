"""PNG, APNG and OpenEXR files as numpy arrays (written atomically, like the ssfx tool's outputs)."""
from ._ssfx import read_apng, read_exr, read_png, write_apng, write_exr, write_png

__all__ = ["read_png", "write_png", "read_apng", "write_apng", "read_exr", "write_exr"]
