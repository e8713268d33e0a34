// Style sheet and script of the HTML report (report.cpp inlines them into index.html so the
// page is one self-contained file plus its images). No libraries, no network.
//
// The comparison viewer: each <section class="viewer"> carries its image size and the URL
// of every method's output in data attributes. Buttons pick methods (several at once),
// the mode (side by side, or flip between the picked ones: button or 'f' key, optional
// auto-flip) and the zoom (1x..16x, nearest-neighbour: crisp pixels). All panes of a viewer
// scroll together; dragging pans.
#pragma once

#include <string_view>

namespace ssfx::eval::detail {

inline constexpr std::string_view kReportCss = R"css(
body { font-family: "DejaVu Sans", sans-serif; margin: 0 auto; max-width: 1240px; padding: 0 16px 48px;
       color: #1a1a1a; background: #fff; line-height: 1.45; }
h1 { margin-top: 24px; } h2 { border-bottom: 1px solid #ddd; padding-bottom: 4px; margin-top: 40px; }
table { border-collapse: collapse; margin: 8px 0 16px; font-size: 14px; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: right; }
th:first-child, td:first-child { text-align: left; }
td.best { font-weight: bold; background: #e8f4e8; }
.note { color: #444; font-size: 14px; max-width: 900px; }
img.plot { max-width: 100%; height: auto; border: 1px solid #eee; }
.viewer { border: 1px solid #ccc; padding: 8px; margin: 12px 0 24px; }
.viewer .controls { display: flex; flex-wrap: wrap; gap: 4px; align-items: center; margin-bottom: 8px; }
.viewer .controls span { margin: 0 4px 0 12px; font-size: 13px; color: #555; }
.viewer button { font: inherit; font-size: 13px; padding: 2px 8px; border: 1px solid #999; background: #f4f4f4;
                 cursor: pointer; border-radius: 3px; }
.viewer button[aria-pressed="true"] { background: #2a5db0; color: #fff; border-color: #2a5db0; }
.viewer .panes { display: flex; flex-wrap: wrap; gap: 8px; }
.viewer .pane { border: 1px solid #bbb; }
.viewer .pane .label { font-size: 12px; height: 18px; line-height: 18px; padding: 0 6px; background: #eee; overflow: hidden; }
.viewer .scroll { overflow: auto; width: var(--pane-w); height: var(--pane-h); cursor: grab; background: #888; }
.viewer .scroll img { display: block; image-rendering: pixelated; image-rendering: crisp-edges; max-width: none; }
.anims { display: flex; flex-wrap: wrap; gap: 12px; }
.anims figure { margin: 0; font-size: 13px; text-align: center; }
.anims img.crop { width: 240px; height: 240px; }
.anims img.aoimg { width: 384px; height: auto; image-rendering: auto; }
.anims img { image-rendering: pixelated; width: 300px; height: 300px; border: 1px solid #ccc; }
.methods dt { font-weight: bold; margin-top: 8px; }
pre.doc { white-space: pre-wrap; font-size: 14px; max-width: 900px; }
)css";

inline constexpr std::string_view kReportJs = R"js(
"use strict";
function initViewer(v) {
  const sources = JSON.parse(v.dataset.sources);
  const methods = Object.keys(sources);
  const w = +v.dataset.width, h = +v.dataset.height;
  const state = { selected: JSON.parse(v.dataset.initial), mode: "side", zoom: 1, flip: 0, x: 0, y: 0, timer: null };
  const panes = v.querySelector(".panes");
  const paneW = Math.min(w, +v.dataset.paneWidth), paneH = Math.min(h, +v.dataset.paneHeight);
  v.style.setProperty("--pane-w", paneW + "px");
  v.style.setProperty("--pane-h", paneH + "px");
  function shown() {
    if (state.mode === "side") return state.selected;
    return state.selected.length ? [state.selected[state.flip % state.selected.length]] : [];
  }
  function render() {
    v.querySelectorAll("button[data-method]").forEach(b =>
      b.setAttribute("aria-pressed", String(state.selected.includes(b.dataset.method))));
    v.querySelectorAll("button[data-mode]").forEach(b =>
      b.setAttribute("aria-pressed", String(b.dataset.mode === state.mode)));
    v.querySelectorAll("button[data-zoom]").forEach(b =>
      b.setAttribute("aria-pressed", String(+b.dataset.zoom === state.zoom)));
    panes.textContent = "";
    for (const m of shown()) {
      const pane = document.createElement("div");
      pane.className = "pane";
      const label = document.createElement("div");
      label.className = "label";
      label.textContent = m;
      const scroll = document.createElement("div");
      scroll.className = "scroll";
      const img = document.createElement("img");
      img.src = sources[m];
      img.alt = m;
      img.dataset.method = m;
      img.width = w * state.zoom;
      img.height = h * state.zoom;
      img.draggable = false;
      scroll.appendChild(img);
      pane.appendChild(label);
      pane.appendChild(scroll);
      panes.appendChild(pane);
      scroll.scrollLeft = state.x;
      scroll.scrollTop = state.y;
      scroll.addEventListener("scroll", () => {
        state.x = scroll.scrollLeft;
        state.y = scroll.scrollTop;
        panes.querySelectorAll(".scroll").forEach(o => {
          if (o !== scroll) { o.scrollLeft = state.x; o.scrollTop = state.y; }
        });
      });
      let drag = null;
      scroll.addEventListener("mousedown", e => { drag = { x: e.clientX, y: e.clientY, l: scroll.scrollLeft, t: scroll.scrollTop }; e.preventDefault(); });
      window.addEventListener("mouseup", () => { drag = null; });
      scroll.addEventListener("mousemove", e => {
        if (drag) { scroll.scrollLeft = drag.l - (e.clientX - drag.x); scroll.scrollTop = drag.t - (e.clientY - drag.y); }
      });
    }
    snap();
  }
  // Crisp pixels need the panes on whole device pixels: text above may leave the viewer at a
  // fractional offset, which would resample every image pixel. Shift the panes to snap.
  // (Padding, not margin: the top margin would collapse with the controls' bottom margin.)
  function snap() {
    panes.style.paddingLeft = panes.style.paddingTop = "0px";
    const r = panes.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
    const fx = (r.left + window.scrollX) * dpr, fy = (r.top + window.scrollY) * dpr;
    panes.style.paddingLeft = (Math.ceil(fx - 1e-6) - fx) / dpr + "px";
    panes.style.paddingTop = (Math.ceil(fy - 1e-6) - fy) / dpr + "px";
  }
  window.addEventListener("load", snap);
  window.addEventListener("resize", snap);
  function setZoom(z) {
    // Keep the centre of the view where it is.
    const cx = (state.x + paneW / 2) / state.zoom, cy = (state.y + paneH / 2) / state.zoom;
    state.zoom = z;
    state.x = Math.max(0, Math.min(w * z - paneW, cx * z - paneW / 2));
    state.y = Math.max(0, Math.min(h * z - paneH, cy * z - paneH / 2));
    render();
  }
  v.querySelectorAll("button[data-method]").forEach(b => b.addEventListener("click", () => {
    const m = b.dataset.method;
    if (state.selected.includes(m)) state.selected = state.selected.filter(s => s !== m);
    else state.selected = methods.filter(s => s === m || state.selected.includes(s));
    if (state.mode === "flip") state.flip = Math.max(0, state.selected.indexOf(m));
    render();
  }));
  v.querySelectorAll("button[data-mode]").forEach(b => b.addEventListener("click", () => { state.mode = b.dataset.mode; render(); }));
  v.querySelectorAll("button[data-zoom]").forEach(b => b.addEventListener("click", () => setZoom(+b.dataset.zoom)));
  const flipButton = v.querySelector("button[data-action=flip]");
  function flip() { state.mode = "flip"; state.flip = (state.flip + 1) % Math.max(1, state.selected.length); render(); }
  flipButton.addEventListener("click", flip);
  v.querySelector("button[data-action=auto]").addEventListener("click", e => {
    if (state.timer) { clearInterval(state.timer); state.timer = null; e.target.setAttribute("aria-pressed", "false"); }
    else { state.timer = setInterval(flip, 700); e.target.setAttribute("aria-pressed", "true"); }
  });
  v.tabIndex = 0;
  v.addEventListener("keydown", e => { if (e.key === "f") flip(); });
  render();
}
document.querySelectorAll(".viewer").forEach(initViewer);
)js";

}  // namespace ssfx::eval::detail
