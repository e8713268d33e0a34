"""Ambient obscurance on float32 depth buffers (ssfx ao): one function per registry method."""
from ._ssfx import alchemy, gtao, sao

__all__ = ["sao", "alchemy", "gtao"]
