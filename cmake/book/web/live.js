// The book's live scenes: a scene's own C++, compiled with emscripten into one single-file module
// (cmake/book/live/), run in the page when the reader moves a control. The page never computes a
// number: it passes the scene's options to the module's live_run (the scene's main() with
// --json --no-figure), shows the numbers of the scene's report, draws the data its drawing code
// sent to its figure (cmake/book/live/figure_live.cpp), and hands its --motion samples to the motion
// viewer (motion_viewer.js) on the same page.
//
// Each <div class="live"> holds its spec (<script type="application/json" class="live-spec">,
// written by the book's render from cmake/book/live/<scene>.json and the scene's --list-options) and
// names its module (data-module). Works from file://: the module is a <script>, not a fetch.
//
// For the book's browser test (cmake/book/tests/browser_live.py) each live scene is also
// window.liveScenes[i]: {scene, state ("loading" | "ready" | "failed"), runs, firstResultMs,
// lastRunMs, lastComputeMs, result, set(option, value) -> result}.
"use strict";

(function () {
  window.liveScenes = window.liveScenes || [];
  const SVG = "http://www.w3.org/2000/svg";
  const COLOURS = ["#999999", "#0072b2", "#56b4e9", "#e69f00", "#009e73", "#000000", "#d55e00", "#cc79a7"];

  function el(tag, attrs, text) {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // A number as the book writes it: 3 significant digits, ×10ⁿ for the very small and large.
  function show(x) {
    if (typeof x !== "number") return String(x);
    if (!isFinite(x)) return String(x);
    if (x === 0) return "0";
    const a = Math.abs(x);
    if (a >= 1e-3 && a < 1e5) return String(Number(x.toPrecision(4)));
    const [m, e] = x.toExponential(2).split("e");
    const sup = { "-": "⁻", "0": "⁰", "1": "¹", "2": "²", "3": "³", "4": "⁴", "5": "⁵", "6": "⁶", "7": "⁷", "8": "⁸", "9": "⁹" };
    return m + "×10" + String(Number(e)).split("").map((c) => sup[c]).join("");
  }

  // A value of the report by the value markers' key path: a.b, a[2] (a table's row or a list's
  // item), a[2].column (a table's column in that row).
  function lookup(report, key) {
    let v = report, row = null;
    for (const part of key.match(/[^.[\]]+|\[\d+\]/g)) {
      if (v === null || v === undefined) return undefined;
      if (part[0] === "[") {
        const i = Number(part.slice(1, -1));
        if (v.columns && v.rows) row = { columns: v.columns, values: v.rows[i] }, v = row;
        else v = v[i];
      } else if (row && v === row) {
        v = row.values ? row.values[row.columns.indexOf(part)] : undefined;
        row = null;
      } else v = v[part];
    }
    return v;
  }

  // ------------------------------------------------------------------------ the plot
  // The figure's gnuplot commands, cut at each plot/splot: one panel each, with the title set
  // before it, its data blocks (one per '-'), its log scales and its 3D view.
  function panels(plot) {
    const out = [];
    let title = "", log = "", view = [60, 30], block = 0;
    for (const line of plot.commands.split("\n")) {
      const t = line.match(/^\s*set title '((?:[^']|'')*)'/);
      if (t) title = t[1].replace(/''/g, "'");
      const l = line.match(/^\s*set logscale\s*(\w*)/);
      if (l) log = l[1] || "xy";
      if (/^\s*unset logscale/.test(line)) log = "";
      const v = line.match(/^\s*set view\s+([\d.]+)\s*,\s*([\d.]+)/);
      if (v) view = [Number(v[1]), Number(v[2])];
      const p = line.match(/^\s*(s?plot)\s/);
      if (p) {
        // Each '-' with what its clause plots: "using 1:3", "using ($1-0.2):2" (a column, or a
        // column shifted or scaled by a number); without "using", gnuplot's 1:2 or 1:2:3.
        const clauses = line.split(/'-'/).slice(1);
        const cols = clauses.map((c) => {
          const u = c.match(/^\s*using\s+([^\s,]+)/);
          const d = p[1] === "splot" ? [1, 2, 3] : [1, 2];
          return (u ? u[1].split(":") : d.map(String)).map(column);
        });
        const n = clauses.length;
        out.push({ kind: p[1], title, log, view, cols, blocks: plot.blocks.slice(block, block + n) });
        block += n;
      }
    }
    return out;
  }

  // One part of a "using": N, or ($N op number) with op one of + - * /; a function of the row.
  function column(part) {
    const n = part.match(/^\d+$/) ? [part, null, null] : part.match(/^\(\$(\d+)\s*([-+*/])\s*([\d.eE+-]+)\)$/)?.slice(1);
    if (!n) throw new Error(`live plot: cannot read the column "${part}" of a gnuplot "using"`);
    const i = Number(n[0]) - 1, k = Number(n[2]);
    const op = { "+": (v) => v + k, "-": (v) => v - k, "*": (v) => v * k, "/": (v) => v / k }[n[1]] || ((v) => v);
    return (row) => (row[i] === undefined ? undefined : op(row[i]));
  }

  // Points of a panel on the screen: 2D as they are (log scales as asked), 3D turned by
  // gnuplot's view (about z, then about x) and seen along the new y... as gnuplot draws it.
  function project(panel) {
    const [rx, rz] = panel.view.map((d) => (d * Math.PI) / 180);
    const cz = Math.cos(rz), sz = Math.sin(rz), cx = Math.cos(rx), sx = Math.sin(rx);
    const f = (row, cols) => {
      const r = row && cols.map((c) => c(row));
      if (!r || r.length < 2 || r.some((v) => v === undefined)) return null;
      if (panel.kind === "plot") {
        let x = r[0], y = r[1];
        if (panel.log.includes("x")) x = x > 0 ? Math.log10(x) : NaN;
        if (panel.log.includes("y")) y = y > 0 ? Math.log10(y) : NaN;
        return isFinite(x) && isFinite(y) ? [x, y] : null;
      }
      const x = r[0] * cz - r[1] * sz, y = r[0] * sz + r[1] * cz, z = r[2];
      return [x, y * -sx + z * cx];
    };
    return panel.blocks.map((rows, i) => rows.map((row) => f(row, panel.cols[i])));
  }

  // Text for SVG markup.
  function esc(text) {
    return String(text).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");
  }

  // The panel as one SVG text, parsed once (innerHTML): a path per series, the frame, the title,
  // the ranges at the corners of a 2D plot. One pass over the points for the ranges, one to
  // write them.
  function draw(host, panel) {
    const W = 520, H = 380, pad = 44;
    const series = project(panel);
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const rows of series)
      for (const p of rows)
        if (p) {
          if (p[0] < x0) x0 = p[0];
          if (p[0] > x1) x1 = p[0];
          if (p[1] < y0) y0 = p[1];
          if (p[1] > y1) y1 = p[1];
        }
    const head = `<svg xmlns="${SVG}" viewBox="0 0 ${W} ${H}" class="live-plot" role="img" aria-label="${esc(panel.title)}">`;
    if (x0 > x1) {
      host.innerHTML = head + "</svg>";
      return;
    }
    if (panel.kind === "splot") {
      const half = Math.max(x1 - x0, y1 - y0) / 2 || 1, cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
      [x0, x1, y0, y1] = [cx - half, cx + half, cy - half, cy + half];
    }
    const sx = (W - 2 * pad) / (x1 - x0 || 1), sy = (H - 2 * pad) / (y1 - y0 || 1);
    const s = panel.kind === "splot" ? Math.min(sx, sy) : null;
    const ox = pad + (s ? (W - 2 * pad - (x1 - x0) * s) / 2 : 0), oy = H - pad - (s ? (H - 2 * pad - (y1 - y0) * s) / 2 : 0);
    const kx = s || sx, ky = s || sy;
    const out = [head, `<rect x="0" y="0" width="${W}" height="${H}" fill="#fff"/>`];
    if (panel.kind === "plot") out.push(`<rect x="${pad}" y="${pad}" width="${W - 2 * pad}" height="${H - 2 * pad}" fill="none" stroke="#888"/>`);
    series.forEach((rows, i) => {
      let d = "", pen = false;
      for (const p of rows) {
        if (!p) {
          pen = false;
          continue;
        }
        d += (pen ? "L" : "M") + (ox + (p[0] - x0) * kx).toFixed(1) + " " + (oy - (p[1] - y0) * ky).toFixed(1);
        pen = true;
      }
      out.push(`<path d="${d}" fill="none" stroke="${COLOURS[i % COLOURS.length]}" stroke-width="1.4" class="live-series"/>`);
    });
    out.push(`<text x="${W / 2}" y="18" text-anchor="middle" class="live-plot-title">${esc(panel.title)}</text>`);
    if (panel.kind === "plot") {
      const lab = (x, y, text, anchor) => out.push(`<text x="${x}" y="${y}" text-anchor="${anchor}" class="live-plot-tick">${esc(text)}</text>`);
      const tx = (v, log) => show(log ? Math.pow(10, v) : v);
      lab(pad, H - pad + 14, tx(x0, panel.log.includes("x")), "start");
      lab(W - pad, H - pad + 14, tx(x1, panel.log.includes("x")), "end");
      lab(pad - 4, H - pad, tx(y0, panel.log.includes("y")), "end");
      lab(pad - 4, pad + 10, tx(y1, panel.log.includes("y")), "end");
    }
    out.push("</svg>");
    host.innerHTML = out.join("");
  }

  // ------------------------------------------------------------------------ a live scene
  function LiveScene(div) {
    this.div = div;
    this.spec = JSON.parse(div.querySelector("script.live-spec").textContent);
    this.scene = this.spec.scene;
    this.state = "loading";
    this.runs = 0;
    this.values = {};
    this.status = div.querySelector(".live-status") || div.appendChild(el("p", { class: "live-status" }));
    this.status.textContent = "Loading the scene's C++ (WebAssembly)…";
    this.build();
    this.load();
  }

  LiveScene.prototype.option = function (name) {
    return this.spec.options.find((o) => o.name === name);
  };

  // The controls: one slider and one number box per option, in the scene's range (the spec may
  // narrow it for the slider, never widen it: cmake/book/live/spec.cmake checks), starting at the
  // scene's default.
  LiveScene.prototype.build = function () {
    const form = el("form", { class: "live-controls", "aria-label": "Parameters of " + this.scene });
    form.addEventListener("submit", (e) => e.preventDefault());
    for (const c of this.spec.controls) {
      const o = this.option(c.option);
      if (o.kind === "word") {
        form.appendChild(this.choice(c, o));
        continue;
      }
      if (o.kind === "x,y,z") {
        form.appendChild(this.vector(c, o));
        continue;
      }
      const lo = c.min !== undefined ? c.min : o.min, hi = c.max !== undefined ? c.max : o.max;
      const log = c.scale === "log";
      const row = el("label", { class: "live-control" });
      row.appendChild(el("span", { class: "live-label" }, c.label + " (--" + c.option + ")"));
      const slider = el("input", { type: "range", min: 0, max: 1000, step: 1, "data-option": c.option });
      const box = el("input", { type: "number", min: o.min, max: o.max, step: "any", "data-option": c.option, class: "live-value" });
      const toSlider = (v) => (log ? Math.log(v / lo) / Math.log(hi / lo) : (v - lo) / (hi - lo)) * 1000;
      const fromSlider = (s) => {
        const v = log ? lo * Math.pow(hi / lo, s / 1000) : lo + ((hi - lo) * s) / 1000;
        const step = c.step || 0;
        return step ? Math.round(v / step) * step : Number(v.toPrecision(3));
      };
      const v0 = Number(o.default);
      this.values[c.option] = v0;
      slider.value = toSlider(v0);
      box.value = v0;
      slider.addEventListener("input", () => {
        const v = fromSlider(Number(slider.value));
        box.value = v;
        this.request(c.option, v);
      });
      box.addEventListener("change", () => {
        slider.value = toSlider(Number(box.value));
        this.request(c.option, Number(box.value));
      });
      row.appendChild(slider);
      row.appendChild(box);
      if (c.unit) row.appendChild(el("span", { class: "live-unit" }, c.unit));
      form.appendChild(row);
    }
    this.div.appendChild(form);
    this.message = this.div.appendChild(el("p", { class: "live-message", role: "status" }));
    const table = el("table", { class: "live-numbers" });
    this.cells = {};
    for (const n of this.spec.numbers) {
      const tr = el("tr");
      tr.appendChild(el("th", {}, n.label));
      const td = el("td", { class: "live-number", "data-key": n.key });
      this.cells[n.key] = td;
      tr.appendChild(td);
      tr.appendChild(el("td", { class: "live-unit" }, n.unit || ""));
      table.appendChild(tr);
    }
    this.div.appendChild(table);
    this.plot = this.div.appendChild(el("div", { class: "live-figure" }));
    this.timing = this.div.appendChild(el("p", { class: "live-timing" }));
  };

  // A word option (--sense ccw|cw): a menu of the scene's own choices.
  LiveScene.prototype.choice = function (c, o) {
    const row = el("label", { class: "live-control" });
    row.appendChild(el("span", { class: "live-label" }, c.label + " (--" + c.option + ")"));
    const menu = el("select", { "data-option": c.option });
    for (const w of o.choices) menu.appendChild(el("option", { value: w }, w));
    menu.value = o.default;
    this.values[c.option] = o.default;
    menu.addEventListener("change", () => this.request(c.option, menu.value));
    row.appendChild(menu);
    return row;
  };

  // A vector option (--axis x,y,z): a slider per component, each in the spec's range (within the
  // scene's: spec.cmake checks), the three sent as one "x,y,z".
  LiveScene.prototype.vector = function (c, o) {
    const row = el("fieldset", { class: "live-control live-vector" });
    row.appendChild(el("legend", { class: "live-label" }, c.label + " (--" + c.option + ")"));
    const v = o.default.split(",").map(Number);
    const lo = c.min !== undefined ? c.min : o.min, hi = c.max !== undefined ? c.max : o.max;
    this.values[c.option] = v.join(",");
    ["x", "y", "z"].forEach((name, k) => {
      const slider = el("input", { type: "range", min: 0, max: 1000, step: 1, "data-option": c.option, "aria-label": name });
      slider.value = ((v[k] - lo) / (hi - lo)) * 1000;
      const shown = el("span", { class: "live-value" }, String(v[k]));
      slider.addEventListener("input", () => {
        v[k] = Number((lo + ((hi - lo) * Number(slider.value)) / 1000).toPrecision(3));
        shown.textContent = String(v[k]);
        this.request(c.option, v.join(","));
      });
      row.appendChild(el("span", {}, name));
      row.appendChild(slider);
      row.appendChild(shown);
    });
    return row;
  };

  LiveScene.prototype.load = function () {
    const t0 = performance.now();
    const script = el("script", { src: this.div.dataset.module });
    const fail = (why) => {
      this.state = "failed";
      this.div.classList.add("live-failed");
      this.status.textContent = "The live scene cannot run here (" + why + "); the figure and the numbers of the text are the scene's own run.";
      console.error("live scene " + this.scene + ": " + why);
    };
    script.addEventListener("error", () => fail("its module " + this.div.dataset.module + " did not load"));
    script.addEventListener("load", () => {
      const factory = window["live_" + this.scene];
      if (typeof factory !== "function") return fail("its module defines no live_" + this.scene);
      factory().then((m) => {
        this.module = m;
        this.state = "ready";
        this.status.textContent = "Live: move a control and the scene's own C++ runs again in this page (WebAssembly, offline).";
        this.run();
        this.firstResultMs = performance.now() - t0;
        this.timing.textContent += " First result " + this.firstResultMs.toFixed(0) + " ms after the page asked for the module.";
      }, (e) => fail(String(e)));
    });
    document.head.appendChild(script);
  };

  // A moved control: one run a frame at most, with the latest values.
  LiveScene.prototype.request = function (option, value) {
    this.values[option] = value;
    if (this.pending || this.state !== "ready") return;  // a failed module runs no more
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.run();
    });
  };

  // The scene's command line for the current values: its name, the spec's fixed arguments, and
  // --<option> <value> for each control (the same line the browser test gives the native scene).
  LiveScene.prototype.argv = function () {
    const args = [this.scene].concat(this.spec.args || []);
    for (const c of this.spec.controls) args.push("--" + c.option, String(this.values[c.option]));
    return args;
  };

  LiveScene.prototype.run = function () {
    const t0 = performance.now();
    let text;
    try {
      text = this.module.ccall("live_run", "string", ["string"], [this.argv().join("\n")]);
    } catch (e) {
      // The module stopped (a GSL function reached in a page that has no GSL, memory): it says so.
      this.state = "failed";
      this.div.classList.add("live-failed");
      this.status.textContent = "The live scene stopped (" + e + "); the figure and the numbers of the text are the scene's own run.";
      console.error("live scene " + this.scene + ": " + e);
      return null;
    }
    const t1 = performance.now();
    const r = JSON.parse(text);
    this.result = r;
    this.runs++;
    this.showResult(r);
    const t2 = performance.now();
    this.lastComputeMs = t1 - t0;
    this.lastRunMs = t2 - t0;
    this.timing.textContent = "Computed in " + this.lastComputeMs.toFixed(1) + " ms, drawn in " + (t2 - t1).toFixed(1) + " ms (run " + this.runs + ").";
    this.div.dataset.runs = String(this.runs);
    return r;
  };

  LiveScene.prototype.showResult = function (r) {
    const ok = r.status === 0 && r.report;
    this.div.classList.toggle("live-refused", !ok);
    this.message.textContent = ok ? "" : (r.stderr || "the scene failed (exit status " + r.status + ")").trim();
    for (const n of this.spec.numbers) {
      const td = this.cells[n.key];
      const v = ok ? lookup(r.report, n.key) : undefined;
      td.textContent = v === undefined || v === null ? "—" : show(v);
      td.dataset.value = v === undefined || v === null ? "" : JSON.stringify(v);
    }
    if (!ok) return;
    const p = this.spec.plot;
    const fig = p && r.plots.find((f) => f.file === p.file);
    if (fig) {
      const all = panels(fig);
      const panel = all[Math.min(p.panel || 0, all.length - 1)];
      if (panel) draw(this.plot, panel);
    }
    if (this.spec.motion && r.motion && window.motionViewerReplace)
      for (const f of this.motionFigures()) window.motionViewerReplace(f, r.motion);
  };

  // The page's motion figures of this scene, found once: their data (parsed here only to read
  // the scene's name) is large, and a run must not parse it again.
  LiveScene.prototype.motionFigures = function () {
    if (!this.figures)
      this.figures = Array.from(document.querySelectorAll("figure.motion")).filter(
        (f) => JSON.parse(f.querySelector("script.motion-data").textContent).scene === this.scene);
    return this.figures;
  };

  LiveScene.prototype.set = function (option, value) {
    this.values[option] = value;
    for (const i of this.div.querySelectorAll("[data-option='" + option + "']")) if (i.type === "number" || i.tagName === "SELECT") i.value = value;
    return this.run();
  };

  function start() {
    for (const div of document.querySelectorAll("div.live[data-module]")) window.liveScenes.push(new LiveScene(div));
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
