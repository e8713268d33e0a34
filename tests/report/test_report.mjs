// Headless-Chromium test of the HTML report written by `ssfx eval report` (issue #3):
// the page loads with no console errors, every image and local link resolves, nothing
// points to the network, and the comparison viewer switches methods, zooms, wipes, shows the
// difference to the truth and the readout, and keeps its view in the URL: the pixels
// of its screenshots are compared with the PNG files they should show (nearest-neighbour
// zoom: each image pixel becomes a z x z block).
// Usage: node test_report.mjs REPORT_DIR
import { chromium } from "playwright-core";
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";

const dir = path.resolve(process.argv[2]);
const debug = process.env.SSFX_REPORT_DEBUG;
let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
}

// Minimal PNG decoder: 8-bit RGB or RGBA, not interlaced (what Chromium and ssfx write).
function decodePng(buf) {
  let pos = 8, width = 0, height = 0, type = 0;
  const idat = [];
  while (pos < buf.length) {
    const len = buf.readUInt32BE(pos), kind = buf.toString("latin1", pos + 4, pos + 8);
    const data = buf.subarray(pos + 8, pos + 8 + len);
    if (kind === "IHDR") {
      width = data.readUInt32BE(0); height = data.readUInt32BE(4); type = data[9];
      if (data[8] !== 8 || (type !== 2 && type !== 6) || data[12] !== 0) throw new Error("unsupported PNG");
    } else if (kind === "IDAT") idat.push(data);
    else if (kind === "IEND") break;
    pos += 12 + len;
  }
  const bpp = type === 6 ? 4 : 3, stride = width * bpp;
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const px = Buffer.alloc(width * height * 4);
  let prev = Buffer.alloc(stride);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)], line = Buffer.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; i++) {
      const a = i >= bpp ? line[i - bpp] : 0, b = prev[i], c = i >= bpp ? prev[i - bpp] : 0;
      let p = 0;
      if (f === 1) p = a; else if (f === 2) p = b; else if (f === 3) p = (a + b) >> 1;
      else if (f === 4) { const q = a + b - c, pa = Math.abs(q - a), pb = Math.abs(q - b), pc = Math.abs(q - c);
        p = pa <= pb && pa <= pc ? a : pb <= pc ? b : c; }
      line[i] = (line[i] + p) & 255;
    }
    for (let x = 0; x < width; x++)
      for (let k = 0; k < 4; k++) px[(y * width + x) * 4 + k] = k < bpp ? line[x * bpp + k] : 255;
    prev = line;
  }
  return { width, height, px };
}

// Share of the visible pane pixels equal (within 1 level) to image pixel
// ((scrollLeft + x) / zoom, (scrollTop + y) / zoom).
function matchShare(shot, img, view, zoom) {
  let same = 0, total = 0;
  for (let y = 0; y < view.h; y++)
    for (let x = 0; x < view.w; x++) {
      const ix = Math.floor((view.left + x) / zoom), iy = Math.floor((view.top + y) / zoom);
      const s = (y * shot.width + x) * 4, i = (iy * img.width + ix) * 4;
      let ok = true;
      for (let k = 0; k < 3; k++) if (Math.abs(shot.px[s + k] - img.px[i + k]) > 1) ok = false;
      same += ok; total++;
    }
  return same / total;
}

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  args: ["--no-sandbox", "--disable-gpu", "--allow-file-access-from-files"],
});
const page = await browser.newPage({ viewport: { width: 1280, height: 1000 }, deviceScaleFactor: 1 });
const errors = [];
page.on("console", m => { if (m.type() === "error") errors.push(m.text()); });
page.on("pageerror", e => errors.push(String(e)));
page.on("requestfailed", r => errors.push("request failed: " + r.url()));
page.on("request", r => { if (!r.url().startsWith("file:") && !r.url().startsWith("data:")) errors.push("network: " + r.url()); });
await page.goto("file://" + path.join(dir, "index.html"), { waitUntil: "load" });

// Every <img> decodes (the viewers' images are created by the script on load).
const broken = await page.evaluate(async () => {
  const imgs = [...document.images];
  await Promise.all(imgs.map(i => i.decode().catch(() => {})));
  return { count: imgs.length, bad: imgs.filter(i => !i.complete || i.naturalWidth === 0).map(i => i.src) };
});
check(broken.count >= 20 && broken.bad.length === 0, `${broken.count} images load (broken: ${broken.bad.join(", ") || "none"})`);
const links = await page.evaluate(() => [...document.querySelectorAll("a[href]")].map(a => a.getAttribute("href")));
const badLinks = links.filter(h => /^[a-z]+:\/\//i.test(h) || !fs.existsSync(path.join(dir, h.split("#")[0])));
check(links.length > 5 && badLinks.length === 0, `${links.length} links are local and exist (bad: ${badLinks.join(", ") || "none"})`);

// The viewer of 'lines': starts with noaa and ddaa2 side by side.
const v = page.locator("#viewer-lines");
await v.scrollIntoViewIfNeeded();
const initial = await v.locator(".pane img").evaluateAll(ims => ims.map(i => i.dataset.method));
check(JSON.stringify(initial) === JSON.stringify(["noaa", "ddaa2"]), `side by side shows ${initial}`);

async function paneShot(zoom, expectMethod) {
  const scroll = v.locator(".pane .scroll").first();
  await v.locator(".pane img").first().evaluate(i => i.decode());
  const method = await v.locator(".pane img").first().evaluate(i => i.dataset.method);
  const view = await scroll.evaluate(s => ({ w: s.clientWidth, h: s.clientHeight, left: s.scrollLeft, top: s.scrollTop }));
  const shot = decodePng(await scroll.screenshot());
  const img = decodePng(fs.readFileSync(path.join(dir, "images", `lines_${expectMethod}.png`)));
  if (debug) {
    let first = null;
    for (let y = 0; y < view.h && !first; y++) for (let x = 0; x < view.w && !first; x++) {
      const ix = Math.floor((view.left + x) / zoom), iy = Math.floor((view.top + y) / zoom);
      const s = (y * shot.width + x) * 4, i = (iy * img.width + ix) * 4;
      if (Math.abs(shot.px[s] - img.px[i]) > 1) first = [x, y, shot.px[s], img.px[i]];
    }
    console.log(JSON.stringify({ view, shotW: shot.width, shotH: shot.height, first }));
  }
  return { method, share: matchShare(shot, img, view, zoom), view, shot };
}

await v.locator("button[data-mode=flip]").click();
const a = await paneShot(1, "noaa");
check(a.method === "noaa" && a.share > 0.999, `flip mode shows noaa: ${(a.share * 100).toFixed(2)} % of pixels match lines_noaa.png`);
await v.locator("button[data-action=flip]").click();
const b = await paneShot(1, "ddaa2");
check(b.method === "ddaa2" && b.share > 0.999, `'next' flips to ddaa2: ${(b.share * 100).toFixed(2)} % match lines_ddaa2.png`);
const bAsNoaa = matchShare(b.shot, decodePng(fs.readFileSync(path.join(dir, "images", "lines_noaa.png"))), b.view, 1);
check(bAsNoaa < 0.99, `and the pixels changed (${(bAsNoaa * 100).toFixed(2)} % still equal to noaa)`);

// Zoom 8x: crisp blocks of the image around the same centre.
await v.locator("button[data-zoom='8']").click();
const z = await paneShot(8, "ddaa2");
check(z.view.left > 0 && z.share > 0.999,
  `zoom 8x: scrolled to (${z.view.left}, ${z.view.top}), ${(z.share * 100).toFixed(2)} % of pixels are 8x8 blocks of lines_ddaa2.png`);
// Pan by dragging: the view moves and stays pixel-exact.
const box = await v.locator(".pane .scroll").first().boundingBox();
await page.mouse.move(box.x + 200, box.y + 200);
await page.mouse.down();
await page.mouse.move(box.x + 120, box.y + 150, { steps: 4 });
await page.mouse.up();
const p = await paneShot(8, "ddaa2");
check(p.view.left === z.view.left + 80 && p.view.top === z.view.top + 50 && p.share > 0.999,
  `drag pans to (${p.view.left}, ${p.view.top}), still ${(p.share * 100).toFixed(2)} % exact`);
// Picking a third method in side-by-side mode adds a pane.
await v.locator("button[data-mode=side]").click();
await v.locator("button[data-method=ssaax4]").click();
const three = await v.locator(".pane img").evaluateAll(ims => ims.map(i => i.dataset.method));
check(three.length === 3 && three.includes("ssaax4"), `side by side with ssaax4 added shows ${three}`);

// The modes of #20: difference, wipe, readout, and the view in the URL.
const png = m => decodePng(fs.readFileSync(path.join(dir, "images", `lines_${m}.png`)));
const truth = png("truth");
// The difference mode's colour scale, restated here from its documented definition (the report's
// note and report_assets.hpp): e = max |dR|,|dG|,|dB| in levels, t = min(1, e * gain / 255),
// linear between the stops at t = 0, 1/4, 1/2, 3/4, 1.
const STOPS = [[0, 0, 0], [48, 32, 160], [200, 40, 120], [250, 170, 20], [255, 255, 255]];
function expectedDiff(img, gain) {
  const out = { width: img.width, height: img.height, px: Buffer.alloc(img.px.length) };
  for (let i = 0; i < img.px.length; i += 4) {
    let e = 0;
    for (let k = 0; k < 3; k++) e = Math.max(e, Math.abs(img.px[i + k] - truth.px[i + k]));
    const t = Math.min(1, e * gain / 255) * 4, j = Math.min(3, Math.floor(t)), f = t - j;
    for (let k = 0; k < 3; k++) out.px[i + k] = Math.round(STOPS[j][k] + (STOPS[j + 1][k] - STOPS[j][k]) * f);
    out.px[i + 3] = 255;
  }
  return out;
}
async function shotOf(pane) {
  const scroll = v.locator(".pane .scroll").nth(pane);
  await scroll.evaluate(s => Promise.all([...s.querySelectorAll("img")].map(i => i.decode())));
  const view = await scroll.evaluate(s => ({ w: s.clientWidth, h: s.clientHeight, left: s.scrollLeft, top: s.scrollTop }));
  return { view, shot: decodePng(await scroll.screenshot()) };
}
await v.locator("button[data-zoom='1']").click();
for (const m of ["noaa", "ssaax4"]) await v.locator(`button[data-method=${m}]`).click();  // picked: ddaa2 only
await v.locator("button[data-mode=diff]").click();
await v.locator("button[data-gain='16']").click();
await v.locator(".pane canvas.diff[data-ready]").first().waitFor();
const legendShown = await v.locator(".legend").isVisible();
const legendHi = await v.locator(".legend .hi").textContent();
check(legendShown && legendHi === "16+ levels", `difference mode shows its legend ("${legendHi}")`);
const diffLabel = await v.locator(".pane .label").first().textContent();
const d = await shotOf(0);
const dShare = matchShare(d.shot, expectedDiff(png("ddaa2"), 16), d.view, 1);
check(diffLabel === "|ddaa2 - truth|" && dShare > 0.999,
  `difference mode, gain 16: ${(dShare * 100).toFixed(2)} % of pixels equal the colour scale of |lines_ddaa2 - lines_truth|`);
const dAsGain4 = matchShare(d.shot, expectedDiff(png("ddaa2"), 4), d.view, 1);
check(dAsGain4 < 0.99, `and the gain matters (${(dAsGain4 * 100).toFixed(2)} % equal at gain 4)`);

// Readout: the RGB under the cursor, read from the PNG files.
const sbox = await v.locator(".pane .scroll").first().boundingBox();
// (At a pixel where ddaa2 and the truth differ by 10 levels or more, the first one in the view.)
const ddaa2Png = png("ddaa2");
let rx = -1, ry = -1;
for (let y = 0; y < d.view.h && rx < 0; y++)
  for (let x = 0; x < d.view.w && rx < 0; x++) {
    const i = ((y + d.view.top) * truth.width + x + d.view.left) * 4, dp = ddaa2Png.px;
    if (Math.max(...[0, 1, 2].map(k => Math.abs(dp[i + k] - truth.px[i + k]))) >= 10) { rx = x; ry = y; }
  }
await page.mouse.move(sbox.x + rx + 0.5, sbox.y + ry + 0.5);
await page.waitForFunction(() => document.querySelector("#viewer-lines .readout").dataset.x !== undefined);
const readout = await v.locator(".readout").textContent();
const rgb = (img, x, y) => [0, 1, 2].map(k => img.px[(y * img.width + x) * 4 + k]);
const at = [rx + d.view.left, ry + d.view.top], dd = rgb(ddaa2Png, ...at), tt = rgb(truth, ...at);
const err = Math.max(...dd.map((c, k) => Math.abs(c - tt[k])));
const wantReadout = `x ${at[0]}, y ${at[1]}: truth ${tt.join(" ")} | ddaa2 ${dd.join(" ")} (e ${err})`;
check(rx >= 0 && err >= 10 && readout === wantReadout, `readout "${readout}" (expected "${wantReadout}")`);

// Wipe: ssaax4 left of the cut, noaa right of it.
await v.locator("button[data-method=ddaa2]").click();
for (const m of ["ssaax4", "noaa"]) await v.locator(`button[data-method=${m}]`).click();
await v.locator("button[data-mode=wipe]").click();
await v.locator("input[data-action=wipe]").evaluate(i => { i.value = "300"; i.dispatchEvent(new Event("input")); });
const cut = await v.locator(".pane .stack").first().evaluate(s => +s.dataset.cut);
const wv = await shotOf(0);
// (The slider's line and its shadow cover x = cut - 2 .. cut.)
const left = { ...wv.view, w: cut - 2 - wv.view.left }, right = { ...wv.view, left: cut + 1, w: wv.view.w - (cut + 1 - wv.view.left) };
const shotRight = { width: wv.shot.width, height: wv.shot.height, px: Buffer.alloc(wv.shot.px.length) };
for (let y = 0; y < wv.shot.height; y++)  // the right part, shifted to the shot's left edge
  for (let x = 0; x + cut + 1 - wv.view.left < wv.shot.width; x++)
    wv.shot.px.copy(shotRight.px, (y * wv.shot.width + x) * 4, (y * wv.shot.width + x + cut + 1 - wv.view.left) * 4,
                    (y * wv.shot.width + x + cut + 2 - wv.view.left) * 4);
const wl = matchShare(wv.shot, png("ssaax4"), left, 1), wr = matchShare(shotRight, png("noaa"), right, 1);
const wlAsNoaa = matchShare(wv.shot, png("noaa"), left, 1);
check(cut === Math.round(wv.view.left + 0.3 * wv.view.w) && wl > 0.999 && wr > 0.999 && wlAsNoaa < 0.99,
  `wipe at 30 % (x ${cut}): left ${(wl * 100).toFixed(2)} % ssaax4, right ${(wr * 100).toFixed(2)} % noaa (left as noaa ${(wlAsNoaa * 100).toFixed(2)} %)`);

// The view in the URL: zoom 4, pan, wipe; reload restores it.
await v.locator("button[data-zoom='4']").click();
await v.locator(".pane .scroll").first().evaluate(s => { s.scrollLeft = 333; s.scrollTop = 222; });
await page.waitForTimeout(400);  // the URL is written 150 ms after the last change
const url = page.url();
await page.reload({ waitUntil: "load" });
const restored = await page.locator("#viewer-lines").evaluate(vv => {
  const s = vv.querySelector(".pane .scroll");
  return { mode: vv.querySelector("button[aria-pressed=true][data-mode]")?.dataset.mode,
           zoom: +vv.querySelector("button[aria-pressed=true][data-zoom]")?.dataset.zoom,
           label: vv.querySelector(".pane .label").textContent, x: s.scrollLeft, y: s.scrollTop,
           wipe: +vv.querySelector("input[data-action=wipe]").value };
});
const wantState = { mode: "wipe", zoom: 4, label: "ssaax4 | noaa", x: 333, y: 222, wipe: 300 };
check(/#v=lines&/.test(url) && JSON.stringify(restored) === JSON.stringify(wantState),
  `the URL (${url.split("#")[1]}) restores ${JSON.stringify(restored)} after a reload`);
await page.goto("file://" + path.join(dir, "index.html#v=lines&m=ddaa2&mode=diff&z=1&x=0&y=0&gain=64"), { waitUntil: "load" });
await page.reload({ waitUntil: "load" });  // (a hash-only change does not reload the page)
await page.locator("#viewer-lines .pane canvas.diff[data-ready]").first().waitFor();
const linkedHi = await page.locator("#viewer-lines .legend .hi").textContent();
check(linkedHi === "4+ levels", `a linked difference view at gain 64 opens with its legend ("${linkedHi}")`);
await page.goto("file://" + path.join(dir, "index.html"), { waitUntil: "load" });  // no hash: the default view
await page.reload({ waitUntil: "load" });
const plain = await page.locator("#viewer-lines .pane img").evaluateAll(ims => ims.map(i => i.dataset.method));
check(JSON.stringify(plain) === JSON.stringify(["noaa", "ddaa2"]), `without a hash the viewer starts as before (${plain})`);

// Animations are APNGs with several frames (acTL chunk present).
const anim = fs.readFileSync(path.join(dir, "anim", "animated_ddaa2.png"));
check(anim.includes(Buffer.from("acTL")), "anim/animated_ddaa2.png is an APNG");

check(errors.length === 0, `no console errors (${errors.join(" | ") || "none"})`);
await browser.close();
console.log(failures ? `${failures} check(s) failed` : "all checks passed");
process.exit(failures ? 1 : 0);
