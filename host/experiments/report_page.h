// report_page.h -- the fixed parts of report.html (report.h): style, the
// picture viewer's controls and the script. The report inlines them, so the
// page needs nothing from the network or beside it.
#pragma once

namespace lb::experiments::report_page {

inline constexpr const char* kCss = R"CSS(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1em 2em; color: #222; background: #fff; }
@media (max-width: 900px) { body { margin: 0.5em 0.8em; } }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 1.6em; }
p, figcaption, li, h1, h2 { overflow-wrap: anywhere; }
/* A table is its own scrolling box, never wider than the page; its first
   column (the row's key: luminaire or method) stays in view while the
   others scroll under it. */
table { border-collapse: separate; border-spacing: 0; margin: 0.5em 0; display: block; width: fit-content;
        max-width: 100%; overflow-x: auto; border-top: 1px solid #ccc; border-left: 1px solid #ccc; }
th, td { border-right: 1px solid #ccc; border-bottom: 1px solid #ccc; padding: 2px 6px; text-align: right;
         white-space: nowrap; }
thead th { white-space: normal; overflow-wrap: anywhere; min-width: 4em; max-width: 16em; vertical-align: bottom; }
th:first-child, td:first-child { position: sticky; left: 0; z-index: 1; background: #fff;
                                 box-shadow: 1px 0 0 #ccc; }
table.info td { white-space: normal; overflow-wrap: anywhere; }
/* The verdicts' last column lists scenes: text that wraps, not a number. */
#verdicts td:last-child, #verdicts th:last-child { text-align: left; white-space: normal; min-width: 20em; }
td:first-child, th:first-child, table.info td, table.info th { text-align: left; }
table.sortable th { cursor: pointer; background: #f0f0f0; user-select: none; }
table.sortable th[data-dir="asc"]::after { content: " \25B2"; }
table.sortable th[data-dir="desc"]::after { content: " \25BC"; }
table.sortable tbody tr:hover td { background: #f6f6ff; }
code { background: #f3f3f3; padding: 0 2px; }
nav { margin: 0.8em 0; }
/* Plots scale to the page: one per row, at most their own width. */
figure { display: block; margin: 0.8em 0; max-width: 100%; }
figure img { display: block; max-width: 100%; height: auto; }
figcaption { font-size: 0.85em; color: #555; }
#lbv .ctl { display: flex; flex-wrap: wrap; gap: 0.4em 1.2em; align-items: center; margin-bottom: 0.5em; }
#lbv .ctl button { font: inherit; padding: 1px 8px; }
#lbv .ctl button.on { background: #333; color: #fff; }
#lbv select { max-width: 100%; }
#lbCanvas { border: 1px solid #888; image-rendering: pixelated; cursor: pointer; background: #000; max-width: 100%;
            height: auto; }
#lbCap { margin: 0.3em 0; font-weight: 600; overflow-wrap: anywhere; }
#lbv .help { color: #555; font-size: 0.9em; max-width: 60em; }
/* The error pictures' colour bar: under the picture, as wide as it. */
#lbBar { width: 512px; max-width: 100%; margin: 0.2em 0 0.4em; }
#lbBar.off { visibility: hidden; }
#lbBarC { display: block; width: 100%; height: 14px; border: 1px solid #888; box-sizing: border-box; }
#lbBarT { position: relative; height: 2.6em; font-size: 0.8em; }
#lbBarT span { position: absolute; top: 0; transform: translateX(-50%); white-space: nowrap; text-align: center; }
#lbBarT span:first-child { transform: none; } #lbBarT span:last-child { transform: translateX(-100%); }
#lbBarCap { font-size: 0.85em; color: #444; margin-top: 0.2em; }
)CSS";

inline constexpr const char* kViewerHtml = R"HTML(<div id="lbv">
<div class="ctl">
<label>Scene <select id="lbScene"></select></label>
<label>Method <select id="lbMethod"></select></label>
<span id="lbViews"></span>
<label>Exposure <input id="lbExp" type="range" min="-12" max="12" step="0.5" value="0"> <span id="lbExpV">0</span> stops</label>
<label>Zoom <select id="lbZoom"><option>1</option><option>2</option><option>4</option><option>8</option><option>16</option></select> x</label>
</div>
<canvas id="lbCanvas" width="512" height="512"></canvas>
<div id="lbBar" class="off"><canvas id="lbBarC" width="512" height="1"></canvas><div id="lbBarT"></div>
<div id="lbBarCap"></div></div>
<div id="lbCap"></div>
<p class="help">Keys: <b>1</b> reference, <b>2</b> method, <b>3</b> its error, <b>4</b> MCI at equal time,
<b>5</b> MCI's error; <b>space</b> or a click on the picture: the next one; <b>&larr; &rarr;</b> scene;
<b>&uarr; &darr;</b> method; <b>+ &minus;</b> zoom on the near field (the image centre, under the light);
<b>[ ]</b> exposure by half a stop; <b>0</b> resets zoom and exposure. Pictures: L/(1+L) of L = k 2<sup>exposure</sup> E,
k = 1/mean(reference) per scene (as <code>lumibench compare --png</code>), magenta where a pixel is not finite;
error pictures: test &minus; reference, orange too bright, blue too dark, white no error, on one symmetric
scale per scene shared by every method and MCI (the bar under the picture, in lux and in % of the reference
mean; saturated beyond it; docs/figures.md says how it is chosen).
The URL fragment holds the view (e.g. <code>#scene=3&amp;view=mci&amp;zoom=4</code>): copy the address to share it.</p>
</div>
)HTML";

// One function, show(), applies every change of view: the URL fragment at
// load, keys, clicks and the controls all call it.
inline constexpr const char* kScript = R"JS(
(function () {
  "use strict";
  var VIEWS = ["reference", "method", "error", "mci", "mci_error"];
  var NAMES = { reference: "Reference", method: "Method", error: "Method's error",
                mci: "MCI at equal time", mci_error: "MCI's error" };
  var ZOOMS = [1, 2, 4, 8, 16];
  var el = document.getElementById("lbdata");
  var DATA = el ? JSON.parse(el.textContent) : {};
  var D = DATA.scenes || [];
  // The error colours of host/metrics/tonemap.h (colourBar): -bound .. +bound.
  var BAR = (DATA.bar || ["#ffffff"]).map(function (h) {
    return [parseInt(h.slice(1, 3), 16), parseInt(h.slice(3, 5), 16), parseInt(h.slice(5, 7), 16)];
  });
  var S = { scene: 0, method: 0, view: "reference", exposure: 0, zoom: 1 };
  var canvas = document.getElementById("lbCanvas");

  // --- sortable tables ---------------------------------------------------
  function sortBy(th) {
    var table = th.closest("table"), body = table.tBodies[0];
    var idx = Array.prototype.indexOf.call(th.parentNode.children, th);
    var dir = th.getAttribute("data-dir") === "asc" ? "desc" : "asc";
    Array.prototype.forEach.call(th.parentNode.children, function (h) { h.removeAttribute("data-dir"); });
    th.setAttribute("data-dir", dir);
    var rows = Array.prototype.slice.call(body.rows);
    rows.sort(function (a, b) {
      var x = a.cells[idx], y = b.cells[idx];
      var xs = x ? x.getAttribute("data-sort") : null, ys = y ? y.getAttribute("data-sort") : null;
      var c;
      if (xs !== null && ys !== null) c = parseFloat(xs) - parseFloat(ys);
      else if (xs !== null) return -1;  // blank cells last either way
      else if (ys !== null) return 1;
      else c = (x ? x.textContent : "").localeCompare(y ? y.textContent : "", undefined, { numeric: true });
      return dir === "asc" ? c : -c;
    });
    rows.forEach(function (r) { body.appendChild(r); });
  }
  Array.prototype.forEach.call(document.querySelectorAll("table.sortable th"), function (th) {
    th.addEventListener("click", function () { sortBy(th); });
  });

  if (!canvas || !D.length) return;

  // --- pictures -------------------------------------------------------------
  var floatCache = {};
  function floats(key, b64) {
    if (!floatCache[key]) {
      var bin = atob(b64), u = new Uint8Array(bin.length);
      for (var i = 0; i < bin.length; i++) u[i] = bin.charCodeAt(i);
      floatCache[key] = new Float32Array(u.buffer);
    }
    return floatCache[key];
  }
  // The tone map of host/metrics/tonemap.h (tonemapValue, toByte, kNonFinite),
  // with the exposure as a factor 2^exposure on k.
  function toned(f, w, h, k) {
    var c = document.createElement("canvas");
    c.width = w; c.height = h;
    var ctx = c.getContext("2d"), img = ctx.createImageData(w, h), d = img.data;
    for (var i = 0; i < w * h; i++) {
      var e = f[i], r, g, b;
      if (!isFinite(e)) { r = 255; g = 0; b = 255; }
      else {
        var L = k * Math.max(e, 0), v = Math.round(Math.min(Math.max(L / (1 + L), 0), 1) * 255);
        r = g = b = v;
      }
      d[4 * i] = r; d[4 * i + 1] = g; d[4 * i + 2] = b; d[4 * i + 3] = 255;
    }
    ctx.putImageData(img, 0, 0);
    return c;
  }
  // The error picture of f against the reference r at the scene's bound:
  // tonemap.h errorColour through the bar's colours, magenta where not finite.
  function errored(f, r, w, h, bound) {
    var c = document.createElement("canvas");
    c.width = w; c.height = h;
    var ctx = c.getContext("2d"), img = ctx.createImageData(w, h), d = img.data, n = BAR.length;
    for (var i = 0; i < w * h; i++) {
      var e = f[i] - r[i], col;
      if (!isFinite(e)) col = [255, 0, 255];
      else {
        var t = bound > 0 ? Math.min(Math.max(e / bound, -1), 1) : 0;
        col = BAR[Math.round((t + 1) / 2 * (n - 1))];
      }
      d[4 * i] = col[0]; d[4 * i + 1] = col[1]; d[4 * i + 2] = col[2]; d[4 * i + 3] = 255;
    }
    ctx.putImageData(img, 0, 0);
    return c;
  }
  // "+4", "\u22122.5", "0", "+8420": three significant digits, whole numbers
  // from 1000 on (tonemap::barTicks).
  function mag(v) {
    var s = Math.abs(v) >= 1000 ? Math.abs(v).toFixed(0) : Math.abs(v).toPrecision(3);
    if (s.indexOf(".") >= 0 && s.indexOf("e") < 0) s = s.replace(/0+$/, "").replace(/\.$/, "");
    return s;
  }
  function signed(v) { return v === 0 ? "0" : (v > 0 ? "+" : "\u2212") + mag(v); }
  // The colour bar of the scene's error pictures, labelled in lux and in % of
  // the reference mean; hidden on the other views.
  function bar(sc, on) {
    var box = document.getElementById("lbBar"), bc = document.getElementById("lbBarC");
    box.className = on ? "" : "off";
    if (!on) return;
    bc.width = BAR.length;
    var ctx = bc.getContext("2d"), img = ctx.createImageData(BAR.length, 1);
    BAR.forEach(function (c, i) { img.data.set([c[0], c[1], c[2], 255], 4 * i); });
    ctx.putImageData(img, 0, 0);
    var T = document.getElementById("lbBarT"), B = sc.bound, M = sc.mean_ref, U = " " + (sc.unit || "lx");
    T.innerHTML = "";
    [-1, -0.5, 0, 0.5, 1].forEach(function (t) {
      var s = document.createElement("span");
      s.style.left = ((t + 1) * 50) + "%";
      s.textContent = signed(t * B) + U;
      if (M > 0) { s.appendChild(document.createElement("br")); s.appendChild(document.createTextNode(signed(100 * t * B / M) + " %")); }
      T.appendChild(s);
    });
    document.getElementById("lbBarCap").textContent = B > 0
      ? "Error scale of this scene, shared by every method and MCI: \u00b1" + mag(B) + U + " = \u00b1" +
        mag(100 * B / M) + " % of the reference mean " + mag(M) + U + "; saturated beyond."
      : "Every picture of this scene is exact: no error to show.";
  }
  function current() {
    var sc = D[S.scene], m = sc.methods[S.method] || null;
    var mci = m && sc.mci[m.label] ? sc.mci[m.label] : null;
    if (!mci) for (var key in sc.mci) { mci = sc.mci[key]; break; }
    return { sc: sc, m: m, mci: mci };
  }
  function draw() {
    var c = current(), sc = c.sc, w = sc.width, h = sc.height_px, k = sc.k * Math.pow(2, S.exposure);
    var src = null, cap = NAMES[S.view] + ": ", item = null;
    if (S.view === "reference") { src = toned(floats(S.scene + "/ref", sc.ref), w, h, k); cap += sc.label; }
    else {
      item = S.view.indexOf("mci") === 0 ? c.mci : c.m;
      if (!item) cap += "none in this scene";
      else {
        cap += item.label + " (" + item.caption + (item.ms ? ", " + item.ms.toPrecision(3) + " ms" : "") + ")";
        if (S.view === "error" || S.view === "mci_error") {
          src = errored(floats(S.scene + "/" + item.label, item.img), floats(S.scene + "/ref", sc.ref), w, h, sc.bound);
        } else {
          src = toned(floats(S.scene + "/" + item.label, item.img), w, h, k);
        }
      }
    }
    var W = 512, H = Math.round(512 * h / w);
    canvas.width = W; canvas.height = H;
    var ctx = canvas.getContext("2d");
    ctx.imageSmoothingEnabled = false;
    ctx.fillStyle = "#444"; ctx.fillRect(0, 0, W, H);
    if (src) {
      var sw = w / S.zoom, sh = h / S.zoom;
      ctx.drawImage(src, (w - sw) / 2, (h - sh) / 2, sw, sh, 0, 0, W, H);
    }
    bar(sc, S.view === "error" || S.view === "mci_error");
    document.getElementById("lbCap").textContent = cap + (S.zoom > 1 ? " - zoom " + S.zoom + "x on the centre" : "");
  }
  function fragment() {
    return "scene=" + S.scene + "&method=" + S.method + "&view=" + S.view + "&zoom=" + S.zoom + "&exposure=" + S.exposure;
  }
  function parseFragment(h) {
    var p = {};
    h.replace(/^#/, "").split("&").forEach(function (kv) {
      var i = kv.indexOf("="); if (i < 0) return;
      var k = decodeURIComponent(kv.slice(0, i)), v = decodeURIComponent(kv.slice(i + 1));
      if (k === "view") p.view = v;
      else if (k in S) p[k] = parseFloat(v);
    });
    return p;
  }
  // Every change of view goes through here: fragment, keys, clicks, controls.
  function show(p) {
    for (var k in p) if (k in S) S[k] = p[k];
    S.scene = Math.min(Math.max(Math.round(S.scene) || 0, 0), D.length - 1);
    S.method = Math.min(Math.max(Math.round(S.method) || 0, 0), Math.max(D[S.scene].methods.length - 1, 0));
    if (VIEWS.indexOf(S.view) < 0) S.view = "reference";
    S.zoom = ZOOMS.reduce(function (a, z) { return Math.abs(z - S.zoom) < Math.abs(a - S.zoom) ? z : a; }, 1);
    S.exposure = Math.min(Math.max(isFinite(S.exposure) ? S.exposure : 0, -12), 12);
    sync();
    draw();
    try { history.replaceState(null, "", "#" + fragment()); } catch (e) { /* file: URLs in some browsers */ }
  }
  function next(step) { return VIEWS[(VIEWS.indexOf(S.view) + step + VIEWS.length) % VIEWS.length]; }

  var sceneSel = document.getElementById("lbScene"), methodSel = document.getElementById("lbMethod");
  var expIn = document.getElementById("lbExp"), zoomSel = document.getElementById("lbZoom");
  var views = document.getElementById("lbViews");
  D.forEach(function (sc, i) { sceneSel.add(new Option(sc.label, i)); });
  VIEWS.forEach(function (v, i) {
    var b = document.createElement("button");
    b.textContent = (i + 1) + " " + NAMES[v];
    b.setAttribute("data-view", v);
    b.addEventListener("click", function () { show({ view: v }); });
    views.appendChild(b);
  });
  function sync() {
    sceneSel.value = String(S.scene);
    methodSel.innerHTML = "";
    D[S.scene].methods.forEach(function (m, i) { methodSel.add(new Option(m.label, i)); });
    methodSel.value = String(S.method);
    expIn.value = String(S.exposure);
    document.getElementById("lbExpV").textContent = (S.exposure > 0 ? "+" : "") + S.exposure;
    zoomSel.value = String(S.zoom);
    Array.prototype.forEach.call(views.children, function (b) {
      b.className = b.getAttribute("data-view") === S.view ? "on" : "";
    });
  }
  sceneSel.addEventListener("change", function () { show({ scene: +sceneSel.value }); });
  methodSel.addEventListener("change", function () { show({ method: +methodSel.value }); });
  expIn.addEventListener("input", function () { show({ exposure: +expIn.value }); });
  zoomSel.addEventListener("change", function () { show({ zoom: +zoomSel.value }); });
  canvas.addEventListener("click", function () { show({ view: next(1) }); });
  var KEYS = {
    " ": function () { return { view: next(1) }; },
    "ArrowRight": function () { return { scene: S.scene + 1 }; },
    "ArrowLeft": function () { return { scene: S.scene - 1 }; },
    "ArrowDown": function () { return { method: S.method + 1 }; },
    "ArrowUp": function () { return { method: S.method - 1 }; },
    "+": function () { return { zoom: S.zoom * 2 }; },
    "=": function () { return { zoom: S.zoom * 2 }; },
    "-": function () { return { zoom: S.zoom / 2 }; },
    "]": function () { return { exposure: S.exposure + 0.5 }; },
    "[": function () { return { exposure: S.exposure - 0.5 }; },
    "0": function () { return { zoom: 1, exposure: 0 }; }
  };
  document.addEventListener("keydown", function (ev) {
    var t = ev.target && ev.target.tagName;
    if (t === "INPUT" || t === "SELECT" || t === "TEXTAREA" || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    var i = "12345".indexOf(ev.key), p = i >= 0 && ev.key.length === 1 ? { view: VIEWS[i] } : KEYS[ev.key] && KEYS[ev.key]();
    if (p) { ev.preventDefault(); show(p); }
  });
  window.addEventListener("hashchange", function () { show(parseFragment(location.hash)); });
  // Without a method in the fragment: the first that has an MCI partner.
  var init = parseFragment(location.hash), sc0 = D[Math.min(Math.max(Math.round(init.scene) || 0, 0), D.length - 1)];
  if (!("method" in init))
    sc0.methods.some(function (m, i) { if (sc0.mci[m.label]) { init.method = i; return true; } return false; });
  show(init);
})();
)JS";

}  // namespace lb::experiments::report_page
