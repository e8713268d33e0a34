#!/usr/bin/env python3
"""DDAA on a real plot: matplotlib draws one figure with anti-aliasing switched off (lines,
markers, text) at 1x, 2x, 4x and 8x; every ssfx method is applied through ssfx.aa and scored
as the DDAA paper scores (the 1x output upscaled x8 against the x8 drawing) and against the
x8 drawing resolved to 1x (ssaax-style truth, what the eye would see). Writes the images and
a Markdown table (docs/python.md shows a full run).

    PYTHONPATH=build/release/python python3 examples/matplotlib_ddaa.py --out out/matplotlib
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ssfx  # noqa: E402


def draw(dpi):
    """The figure at `dpi`, aliased: every element with antialiased=False."""
    with plt.rc_context({"lines.antialiased": False, "patch.antialiased": False, "text.antialiased": False,
                         "font.family": "DejaVu Sans"}):
        fig, ax = plt.subplots(figsize=(4, 3), dpi=dpi)
        x = np.linspace(0, 4 * np.pi, 200)
        ax.plot(x, np.sin(x), lw=1.0, color="tab:blue", label="sin")
        ax.plot(x, 0.6 * np.cos(1.7 * x), lw=1.5, color="tab:red", label="cos")
        ax.plot(x[::12], 0.3 * np.sin(0.5 * x[::12]) - 0.5, "o", ms=4, color="tab:green", label="samples")
        ax.set_title("aliased matplotlib, ssfx.aa")
        ax.set_xlabel("phase")
        ax.grid(True, lw=0.5, antialiased=False)
        ax.legend(loc="upper right")
        fig.canvas.draw()
        img = np.array(fig.canvas.buffer_rgba())
        plt.close(fig)
    return img


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default="out/matplotlib", help="output folder (images, table.md)")
    ap.add_argument("--dpi", type=int, default=100, help="1x resolution in dots per inch (400x300 px at 100)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    renders = {s: draw(args.dpi * s) for s in (1, 2, 4, 8)}
    h, w = renders[1].shape[:2]
    for s, img in renders.items():  # matplotlib may round a size: every scale must be exact
        assert img.shape[:2] == (h * s, w * s), f"the {s}x drawing is {img.shape[:2]}, not {(h * s, w * s)}"
        ssfx.io.write_png(os.path.join(args.out, f"plot{'' if s == 1 else f'x{s}'}.png"), img)
    truth = ssfx.resample(renders[8], 8)  # the x8 drawing resolved to 1x (Mitchell), as in the report
    ssfx.io.write_png(os.path.join(args.out, "plot_truth.png"), truth)
    rows = []
    for m in ssfx.methods("aa"):
        out = ssfx.aa(renders[m["input_scale"]], m["id"])
        ssfx.io.write_png(os.path.join(args.out, f"plot_{m['id']}.png"), out)
        p8, s8 = ssfx.metrics.score_x8(out, renders[8])
        rows.append((m["id"], p8, s8, ssfx.metrics.psnr(out, truth), ssfx.metrics.ssim(out, truth)))
    # A close-up of the legend (the same region of every 1x image), 3x, side by side.
    y0, x0 = h // 10, w * 23 // 40
    tiles = []
    for name in ("plot", "plot_truth", "plot_ddaa2", "plot_fxaa3d", "plot_ddaa2p", "plot_ssaax4"):
        tile = ssfx.io.read_png(os.path.join(args.out, name + ".png"))[y0:y0 + h // 3, x0:x0 + w * 2 // 5]
        tiles += [tile.repeat(3, 0).repeat(3, 1), np.full((tile.shape[0] * 3, 6, 4), 255, np.uint8)]
    ssfx.io.write_png(os.path.join(args.out, "crops.png"), np.concatenate(tiles[:-1], axis=1))
    lines = [f"{w}x{h} px ({args.dpi} dpi), matplotlib {matplotlib.__version__}, antialiased=False everywhere.",
             "", "| method | PSNR vs x8 (dB) | SSIM vs x8 | PSNR vs resolved 1x (dB) | SSIM vs resolved 1x |",
             "|---|---:|---:|---:|---:|"]
    lines += [f"| `{r[0]}` | {r[1]:.2f} | {r[2]:.4f} | {r[3]:.2f} | {r[4]:.4f} |" for r in rows]
    table = "\n".join(lines) + "\n"
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(table)
    print(table, end="")


if __name__ == "__main__":
    main()
