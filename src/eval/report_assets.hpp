// Style sheet and script of the HTML report (report.cpp inlines them into index.html so the
// page is one self-contained file plus its images). No libraries, no network.
//
// The comparison viewer: each <section class="viewer"> carries its image size and the URL
// of every method's output in data attributes. Buttons pick methods (several at once),
// the mode (side by side; flip between the picked ones: button or 'f' key, optional
// auto-flip; wipe: a slider between the first two picked; difference: |method - truth|
// through a colour scale with its legend and a gain) and the zoom (1x..16x,
// nearest-neighbour: crisp pixels). All panes of a viewer scroll together; dragging pans.
// Under the cursor, a readout gives the RGB of the truth and of each shown method. The view
// (image, methods, mode, zoom, pan, gain, wipe) is kept in the URL's #fragment, so a view
// can be linked. The difference mode and the readout read exact pixels from a per-viewer
// script of data URLs (data-pixels), loaded when first needed.
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
.viewer .scroll img, .viewer .scroll canvas { display: block; image-rendering: pixelated; image-rendering: crisp-edges;
                                              max-width: none; }
.viewer .stack { position: relative; }
.viewer .stack img.over { position: absolute; left: 0; top: 0; }
.viewer .wipe-line { position: absolute; top: 0; bottom: 0; width: 1px; margin-left: -1px; background: #fff;
                     box-shadow: 0 0 0 1px rgba(0, 0, 0, 0.5); pointer-events: none; }
.viewer input[data-action=wipe] { width: 120px; height: 16px; margin: 0 4px; }
.viewer .legend { display: flex; align-items: center; gap: 6px; font-size: 12px; color: #333; margin: 0 0 6px; }
.viewer .legend[hidden] { display: none; }
.viewer .legend .ramp { width: 256px; height: 12px; border: 1px solid #999;
  background: linear-gradient(to right, rgb(0,0,0), rgb(48,32,160), rgb(200,40,120), rgb(250,170,20), rgb(255,255,255)); }
.viewer .readout { font: 12px "DejaVu Sans Mono", monospace; min-height: 16px; margin-top: 6px; color: #222; }
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
// The difference mode's colour scale: e = max(|dR|, |dG|, |dB|) of a method against the
// reference, in levels, times the gain, clamped: t = min(1, e * gain / 255) is interpolated
// linearly between these stops at t = 0, 1/4, 1/2, 3/4, 1 (black = exact; white = off by
// 255 / gain levels or more).
const DIFF_STOPS = [[0, 0, 0], [48, 32, 160], [200, 40, 120], [250, 170, 20], [255, 255, 255]];
function diffColour(e, gain) {
  const s = Math.min(255, e * gain) * 4 / 255, i = Math.min(3, Math.floor(s)), f = s - i;
  return DIFF_STOPS[i].map((c, k) => Math.round(c + (DIFF_STOPS[i + 1][k] - c) * f));
}
// Exact pixels of a viewer's images: data/… scripts define ssfxPixels[id] = {label: data URL}
// (a file:// page may not read its images' pixels back; data URLs it may).
const pixelData = {};
function loadPixels(v) {
  if (!v.dataset.pixels) return Promise.resolve(null);
  const id = v.dataset.viewer;
  if (pixelData[id]) return pixelData[id];
  pixelData[id] = new Promise((resolve, reject) => {
    const script = document.createElement("script");
    script.src = v.dataset.pixels;
    script.onload = () => resolve(window.ssfxPixels[id]);
    script.onerror = () => reject(new Error("cannot load " + script.src));
    document.head.appendChild(script);
  }).then(urls => Promise.all(Object.entries(urls).map(([label, url]) => new Promise((resolve, reject) => {
    const img = new Image();
    img.onload = () => {
      const c = document.createElement("canvas");
      c.width = img.naturalWidth; c.height = img.naturalHeight;
      const g = c.getContext("2d", { willReadFrequently: true });
      g.drawImage(img, 0, 0);
      resolve([label, g.getImageData(0, 0, c.width, c.height)]);
    };
    img.onerror = () => reject(new Error("cannot decode the pixels of " + label));
    img.src = url;
  })))).then(Object.fromEntries);
  return pixelData[id];
}
function initViewer(v) {
  const sources = JSON.parse(v.dataset.sources);
  const methods = Object.keys(sources), reference = v.dataset.reference;
  const w = +v.dataset.width, h = +v.dataset.height;
  const state = { selected: JSON.parse(v.dataset.initial), mode: "side", zoom: 1, flip: 0, x: 0, y: 0,
                  gain: 4, wipe: 0.5, timer: null };
  const panes = v.querySelector(".panes"), readout = v.querySelector(".readout");
  const legend = v.querySelector(".legend"), wipeInput = v.querySelector("input[data-action=wipe]");
  const paneW = Math.min(w, +v.dataset.paneWidth), paneH = Math.min(h, +v.dataset.paneHeight);
  v.style.setProperty("--pane-w", paneW + "px");
  v.style.setProperty("--pane-h", paneH + "px");
  let pixels = null;  // {label: ImageData} once loaded
  function shown() {
    if (state.mode === "side" || state.mode === "diff") return state.selected;
    if (state.mode === "wipe") return state.selected.slice(0, 2);
    return state.selected.length ? [state.selected[state.flip % state.selected.length]] : [];
  }
  function image(m) {
    const img = document.createElement("img");
    img.src = sources[m];
    img.alt = m;
    img.dataset.method = m;
    img.width = w * state.zoom;
    img.height = h * state.zoom;
    img.draggable = false;
    return img;
  }
  // |m - reference| through the colour scale, one canvas pixel per image pixel.
  const diffs = {};
  function diffCanvas(m) {
    const c = document.createElement("canvas");
    c.width = w; c.height = h;
    c.style.width = w * state.zoom + "px";
    c.style.height = h * state.zoom + "px";
    c.dataset.method = m;
    c.className = "diff";
    if (!pixels) return c;
    const key = m + "@" + state.gain;
    if (!diffs[key]) {
      const a = pixels[m].data, b = pixels[reference].data, out = new ImageData(w, h);
      for (let i = 0; i < a.length; i += 4) {
        const e = Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2]));
        const rgb = diffColour(e, state.gain);
        out.data[i] = rgb[0]; out.data[i + 1] = rgb[1]; out.data[i + 2] = rgb[2]; out.data[i + 3] = 255;
      }
      diffs[key] = out;
    }
    c.getContext("2d").putImageData(diffs[key], 0, 0);
    c.dataset.ready = "";
    return c;
  }
  // Wipe: the second method under the first, the first clipped at the slider's place in the view.
  function wipeStack(list) {
    const stack = document.createElement("div");
    stack.className = "stack";
    stack.style.width = w * state.zoom + "px";
    stack.style.height = h * state.zoom + "px";
    const under = image(list[1] || list[0]), over = image(list[0]), line = document.createElement("div");
    over.classList.add("over");
    line.className = "wipe-line";
    stack.append(under, over, line);
    return stack;
  }
  function placeWipe(scroll) {
    const stack = scroll.querySelector(".stack");
    if (!stack) return;
    const cut = Math.round(scroll.scrollLeft + state.wipe * scroll.clientWidth);
    stack.dataset.cut = cut;
    stack.querySelector("img.over").style.clipPath = `inset(0 ${w * state.zoom - cut}px 0 0)`;
    stack.querySelector(".wipe-line").style.left = cut + "px";
  }
  function label(list, m) {
    if (state.mode === "wipe") return list.length > 1 ? `${list[0]} | ${list[1]}` : list[0];
    return state.mode === "diff" ? `|${m} - ${reference}|` : m;
  }
  function render() {
    v.querySelectorAll("button[data-method]").forEach(b =>
      b.setAttribute("aria-pressed", String(state.selected.includes(b.dataset.method))));
    v.querySelectorAll("button[data-mode]").forEach(b =>
      b.setAttribute("aria-pressed", String(b.dataset.mode === state.mode)));
    v.querySelectorAll("button[data-zoom]").forEach(b =>
      b.setAttribute("aria-pressed", String(+b.dataset.zoom === state.zoom)));
    v.querySelectorAll("button[data-gain]").forEach(b =>
      b.setAttribute("aria-pressed", String(+b.dataset.gain === state.gain)));
    if (legend) {
      legend.hidden = state.mode !== "diff";
      legend.querySelector(".hi").textContent = `${Math.round(255 / state.gain)}+ levels`;
    }
    if (wipeInput) { wipeInput.disabled = state.mode !== "wipe"; wipeInput.value = Math.round(state.wipe * 1000); }
    panes.textContent = "";
    const list = shown();
    for (const m of state.mode === "wipe" && list.length ? [list[0]] : list) {
      const pane = document.createElement("div");
      pane.className = "pane";
      const tag = document.createElement("div");
      tag.className = "label";
      tag.textContent = label(list, m);
      const scroll = document.createElement("div");
      scroll.className = "scroll";
      scroll.appendChild(state.mode === "diff" ? diffCanvas(m) : state.mode === "wipe" ? wipeStack(list) : image(m));
      pane.append(tag, scroll);
      panes.appendChild(pane);
      scroll.scrollLeft = state.x;
      scroll.scrollTop = state.y;
      placeWipe(scroll);
      scroll.addEventListener("scroll", () => {
        state.x = scroll.scrollLeft;
        state.y = scroll.scrollTop;
        panes.querySelectorAll(".scroll").forEach(o => {
          if (o !== scroll) { o.scrollLeft = state.x; o.scrollTop = state.y; }
        });
        placeWipe(scroll);
        save();
      });
      let drag = null;
      scroll.addEventListener("mousedown", e => { drag = { x: e.clientX, y: e.clientY, l: scroll.scrollLeft, t: scroll.scrollTop }; e.preventDefault(); });
      window.addEventListener("mouseup", () => { drag = null; });
      scroll.addEventListener("mousemove", e => {
        if (drag) { scroll.scrollLeft = drag.l - (e.clientX - drag.x); scroll.scrollTop = drag.t - (e.clientY - drag.y); }
        const r = scroll.getBoundingClientRect();
        read(Math.floor((e.clientX - r.left + scroll.scrollLeft) / state.zoom),
             Math.floor((e.clientY - r.top + scroll.scrollTop) / state.zoom));
      });
    }
    snap();
    save();
  }
  // The readout: RGB of the reference and of every shown method under the cursor.
  function read(x, y) {
    if (!readout || x < 0 || y < 0 || x >= w || y >= h) return;
    const go = () => {
      if (!pixels) return;
      const i = (y * w + x) * 4, rgb = m => [0, 1, 2].map(k => pixels[m].data[i + k]);
      const parts = [reference, ...shown().filter(m => m !== reference)].map(m => {
        const p = rgb(m), q = rgb(reference);
        const e = Math.max(...p.map((c, k) => Math.abs(c - q[k])));
        return `${m} ${p.join(" ")}` + (m === reference ? "" : ` (e ${e})`);
      });
      readout.dataset.x = x;
      readout.dataset.y = y;
      readout.textContent = `x ${x}, y ${y}: ` + parts.join(" | ");
    };
    if (pixels) go(); else ensurePixels().then(go);
  }
  function ensurePixels() {
    return loadPixels(v).then(p => { pixels = p; return p; });
  }
  // The state in the URL (#v=ID&m=...&mode=...&z=...&x=...&y=...), written a moment after the
  // last change (browsers throttle frequent history updates).
  let saveTimer = null, restoring = true;
  function save() {
    if (restoring) return;
    clearTimeout(saveTimer);
    saveTimer = setTimeout(() => {
      const p = new URLSearchParams({ v: v.dataset.viewer, m: state.selected.join(","), mode: state.mode,
                                      z: state.zoom, x: Math.round(state.x), y: Math.round(state.y) });
      if (state.mode === "diff") p.set("gain", state.gain);
      if (state.mode === "wipe") p.set("wipe", state.wipe);
      history.replaceState(null, "", "#" + p.toString());
    }, 150);
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
  function setMode(mode) {
    state.mode = mode;
    if (mode === "diff" && !pixels) ensurePixels().then(render);
    render();
  }
  v.querySelectorAll("button[data-method]").forEach(b => b.addEventListener("click", () => {
    const m = b.dataset.method;
    if (state.selected.includes(m)) state.selected = state.selected.filter(s => s !== m);
    else state.selected = [...state.selected, m];  // in the order picked (wipe: first left, second right)
    if (state.mode === "flip") state.flip = Math.max(0, state.selected.indexOf(m));
    render();
  }));
  v.querySelectorAll("button[data-mode]").forEach(b => b.addEventListener("click", () => setMode(b.dataset.mode)));
  v.querySelectorAll("button[data-zoom]").forEach(b => b.addEventListener("click", () => setZoom(+b.dataset.zoom)));
  v.querySelectorAll("button[data-gain]").forEach(b => b.addEventListener("click", () => { state.gain = +b.dataset.gain; render(); }));
  if (wipeInput) wipeInput.addEventListener("input", () => {
    state.wipe = wipeInput.value / 1000;
    panes.querySelectorAll(".scroll").forEach(placeWipe);
    save();
  });
  const flipButton = v.querySelector("button[data-action=flip]");
  function flip() { state.mode = "flip"; state.flip = (state.flip + 1) % Math.max(1, state.selected.length); render(); }
  flipButton.addEventListener("click", flip);
  v.querySelector("button[data-action=auto]").addEventListener("click", e => {
    if (state.timer) { clearInterval(state.timer); state.timer = null; e.target.setAttribute("aria-pressed", "false"); }
    else { state.timer = setInterval(flip, 700); e.target.setAttribute("aria-pressed", "true"); }
  });
  v.tabIndex = 0;
  v.addEventListener("keydown", e => { if (e.key === "f") flip(); });
  // A linked view: restore it and bring the viewer into sight.
  const link = new URLSearchParams(location.hash.slice(1));
  if (link.get("v") === v.dataset.viewer) {
    const picked = (link.get("m") || "").split(",").filter(m => methods.includes(m));
    if (picked.length) state.selected = [...new Set(picked)];  // in the linked order (wipe: left, right)
    if (["side", "flip", "wipe", "diff"].includes(link.get("mode"))) state.mode = link.get("mode");
    if (state.mode === "diff" && !v.dataset.pixels) state.mode = "side";
    if ([1, 2, 4, 8, 16].includes(+link.get("z"))) state.zoom = +link.get("z");
    if ([1, 4, 16, 64].includes(+link.get("gain"))) state.gain = +link.get("gain");
    const wipe = +link.get("wipe");
    if (link.has("wipe") && wipe >= 0 && wipe <= 1) state.wipe = wipe;
    state.x = Math.max(0, Math.min(w * state.zoom - paneW, +link.get("x") || 0));
    state.y = Math.max(0, Math.min(h * state.zoom - paneH, +link.get("y") || 0));
    if (state.mode === "diff") ensurePixels().then(render);
    render();
    v.scrollIntoView();
  } else {
    render();
  }
  restoring = false;
}
document.querySelectorAll(".viewer").forEach(initViewer);
)js";

}  // namespace ssfx::eval::detail
