"""Image quality measures of the evaluation (docs/evaluation.md)."""
from ._ssfx import psnr, score_x8, ssim

__all__ = ["psnr", "ssim", "score_x8"]
