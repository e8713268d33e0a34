"""Ambient obscurance on float32 depth buffers (ssfx ao)."""
from ._ssfx import alchemy, sao

__all__ = ["sao", "alchemy"]
