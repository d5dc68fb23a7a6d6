// The book's motion viewer: plays back a motion that a scene computed (its --motion FILE, which
// the book puts into the page as <script type="application/json"> inside <figure class="motion">)
// with three.js (Debian's libjs-three, r111, copied into the book: no network). The page never
// integrates anything: it shows R(t) at the scene's own sample times and, between two samples,
// turns the body along the shortest rotation (quaternion slerp), for a smooth picture.
//
// What it draws: the body as its inertia box or ellipsoid, its principal axes R_A, R_B, R_C
// (the columns of R, coloured as in the figures), the fixed point O, the vertical k, the cones of
// Theorem 1 where the scene gives them, the trail of the centre of mass and of the tip of R_B.
// Controls: play/pause, speed, a time scrubber, drag to turn the view, reset.
//
// For the book's browser test (cmake/book/tests/browser_motion.py) each viewer is also
// window.motionViewers[i]: {play(), pause(), seek(t), time, playing, frames, ready, error}.
/* global THREE */
"use strict";

(function () {
  const COLOURS = {
    A: 0x009e73,     // R_A, the axis of the smallest moment (figures: line style 3)
    B: 0x0072b2,     // R_B (line style 1)
    C: 0xd55e00,     // R_C, the largest moment (line style 2)
    k: 0x000000,
    cm: 0xcc79a7,    // trail of the centre of mass (line style 4)
    tip: 0x56b4e9,   // trail of the tip of R_B (line style 6)
    body: 0xbfbfbf,
    cones: [0x999999, 0xe69f00],  // space cone grey (style 8), body cone orange (style 5)
  };
  const hex = (c) => "#" + c.toString(16).padStart(6, "0");
  const SPEEDS = [0.25, 0.5, 1, 2, 4];

  window.motionViewers = window.motionViewers || [];

  function el(tag, attrs, text) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // Row-major R (columns = body axes in the lab) as a unit quaternion.
  function quaternion(r) {
    const m = new THREE.Matrix4();
    m.set(r[0], r[1], r[2], 0, r[3], r[4], r[5], 0, r[6], r[7], r[8], 0, 0, 0, 0, 1);
    return new THREE.Quaternion().setFromRotationMatrix(m);
  }

  function vec(a) {
    return new THREE.Vector3(a[0], a[1], a[2]);
  }

  function line(points, colour, width) {
    const g = new THREE.BufferGeometry().setFromPoints(points);
    return new THREE.Line(g, new THREE.LineBasicMaterial({ color: colour, linewidth: width || 1 }));
  }

  // A cone with its apex at the origin, its generators of length L at angle theta about axis.
  function cone(axis, theta, L, colour) {
    let a = vec(axis).normalize();
    if (theta > Math.PI / 2) {  // the same generators about -axis
      a = a.negate();
      theta = Math.PI - theta;
    }
    const h = L * Math.cos(theta), r = L * Math.sin(theta);
    const g = new THREE.ConeGeometry(r, h, 48, 1, true);
    g.translate(0, -h / 2, 0);  // apex at the origin, opening towards -y
    const mesh = new THREE.Mesh(g, new THREE.MeshBasicMaterial({
      color: colour, transparent: true, opacity: 0.22, side: THREE.DoubleSide, depthWrite: false }));
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, -1, 0), a);
    const rim = new THREE.LineSegments(new THREE.EdgesGeometry(g, 30), new THREE.LineBasicMaterial({ color: colour }));
    mesh.add(rim);
    mesh.add(line([new THREE.Vector3(), new THREE.Vector3(0, -1.15 * L, 0)], colour));  // its axis
    return mesh;
  }

  function Viewer(figure, data) {
    this.figure = figure;
    this.data = data;
    this.t = data.t;
    this.time = this.t[0];
    this.playing = true;
    this.base = data.speed > 0 ? data.speed : 1;  // t per second at 1x, as the scene chose
    this.speed = 1;
    this.frames = 0;
    this.ready = false;
    this.build();
  }

  Viewer.prototype.build = function () {
    const d = this.data, fig = this.figure;
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });  // throws without WebGL
    const stage = el("div", { class: "motion-stage" });
    const fallback = fig.querySelector(".motion-fallback");
    if (fallback) fallback.hidden = true;
    fig.insertBefore(stage, fig.querySelector("figcaption"));

    const width = Math.max(200, stage.clientWidth || 640), height = Math.round(Math.min(460, width * 0.66));
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(width, height);
    renderer.setClearColor(0xffffff, 1);
    renderer.domElement.className = "motion-canvas";
    renderer.domElement.setAttribute("aria-label", "3D view of the motion: drag to turn");
    stage.appendChild(renderer.domElement);
    this.renderer = renderer;

    const scene = new THREE.Scene();
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    const sun = new THREE.DirectionalLight(0xffffff, 0.6);
    sun.position.set(3, -2, 5);
    scene.add(sun);
    this.scene = scene;
    const camera = new THREE.PerspectiveCamera(35, width / height, 0.05, 100);
    camera.up.set(0, 0, 1);
    this.camera = camera;
    this.load(d);
    this.reset();
    this.controls(stage);
    this.legend(stage);
    this.ready = true;
  };

  // Frees what three.js keeps on the GPU for the objects of a group.
  function dispose(group) {
    group.traverse((o) => {
      if (o.geometry) o.geometry.dispose();
      if (o.material) o.material.dispose();
    });
  }

  // The motion's objects, in one group of the scene (the lights and the renderer stay): each
  // body, its frame turned by R(t) about its fixed point, its trails and cones; and where the
  // camera looks. Called again with new samples (update), it replaces the group.
  Viewer.prototype.load = function (d) {
    if (this.world) {
      this.scene.remove(this.world);
      dispose(this.world);
    }
    this.data = d;
    this.t = d.t;
    this.world = new THREE.Group();
    this.scene.add(this.world);
    this.bodies = [d].concat(d.others || []).map((b) => this.addBody(b, d.k));
    this.trails = [].concat(...this.bodies.map((b) => b.trails));
    const reach = Math.max(...this.bodies.map((b) => b.reach));
    const points = this.bodies.map((b) => vec(b.data.fixed_point));
    const O = points.reduce((a, p) => a.add(p), new THREE.Vector3()).multiplyScalar(1 / points.length);
    const spread = Math.max(...points.map((p) => p.distanceTo(O)));
    const span = Math.max(reach, 1.6);
    this.target = O.clone().add(new THREE.Vector3(0, 0, 0.35 * span));
    this.distance = 3.6 * span + 0.8 * spread;
  };

  // New samples (a live scene ran again, live.js): the same renderer, stage, controls and view
  // (its turn by the reader kept); the motion's objects and the legend are built again, the
  // time starts over and the viewer stays paused if it was. Far cheaper than a new viewer: no
  // new WebGL context.
  Viewer.prototype.update = function (data) {
    this.load(data);
    this.base = data.speed > 0 ? data.speed : 1;
    this.place();
    const stage = this.legendList.parentNode;
    this.legendList.remove();
    this.legend(stage);
    this.seek(this.t[0]);
  };

  // One body of the motion: returns {data, frame, q, trails, reach}.
  Viewer.prototype.addBody = function (b, k) {
    const scene = this.world;
    const O = vec(b.fixed_point);
    const frame = new THREE.Group();
    frame.position.copy(O);
    scene.add(frame);
    const ax = b.body.half_axes, cm = vec(b.centre_of_mass);
    const geometry = b.body.shape === "box"
      ? new THREE.BoxGeometry(2 * ax[0], 2 * ax[1], 2 * ax[2])
      : new THREE.SphereGeometry(1, 40, 24).scale(ax[0], ax[1], ax[2]);
    const body = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({
      color: COLOURS.body, transparent: true, opacity: 0.55, depthWrite: false }));
    body.position.copy(cm);
    body.add(new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 20), new THREE.LineBasicMaterial({ color: 0x777777 })));
    frame.add(body);
    // The principal axes through the fixed point (the body's moments there are A, B, C).
    const reach = 1.25 * Math.max(ax[0], ax[1], ax[2]) + cm.length();
    const origin = new THREE.Vector3();
    ["A", "B", "C"].forEach((name, i) => {
      const u = new THREE.Vector3();
      u.setComponent(i, 1);
      frame.add(new THREE.ArrowHelper(u, origin, reach, COLOURS[name], 0.12, 0.07));
      frame.add(line([origin.clone(), origin.clone().addScaledVector(u, -reach * 0.8)], COLOURS[name]));
    });
    if (cm.length() > 0) frame.add(line([origin.clone(), cm.clone()], 0x444444));
    const dot = new THREE.Mesh(new THREE.SphereGeometry(0.05, 16, 12), new THREE.MeshBasicMaterial({ color: 0x000000 }));
    dot.position.copy(O);
    scene.add(dot);
    scene.add(new THREE.ArrowHelper(vec(k).normalize(), O, 1.9, COLOURS.k, 0.14, 0.08));
    (b.cones || []).forEach((c, i) => {
      const m = cone(c.axis, c.half_angle, c.length, COLOURS.cones[i % 2]);
      (c.frame === "body" ? frame : scene).add(m);
      if (c.frame !== "body") m.position.copy(O);
    });
    const trails = [];
    for (const [key, colour] of [["centre_of_mass", COLOURS.cm], ["tip_R_B", COLOURS.tip]]) {
      const pts = (b.trails[key] || []).map(vec);
      if (pts.length < 2) continue;
      const l = line(pts, colour);
      l.geometry.setDrawRange(0, 1);
      scene.add(l);
      trails.push(l);
    }
    return { data: b, frame, q: b.R.map(quaternion), trails, reach };
  };

  Viewer.prototype.reset = function () {
    this.azimuth = -0.95;
    this.elevation = 0.38;
    this.place();
  };

  Viewer.prototype.place = function () {
    const c = Math.cos(this.elevation);
    this.camera.position.set(
      this.target.x + this.distance * c * Math.cos(this.azimuth),
      this.target.y + this.distance * c * Math.sin(this.azimuth),
      this.target.z + this.distance * Math.sin(this.elevation));
    this.camera.lookAt(this.target);
    this.dirty = true;
  };

  Viewer.prototype.controls = function (stage) {
    const bar = el("div", { class: "motion-controls" });
    const play = el("button", { type: "button", class: "motion-play" }, "Pause");
    const speed = el("select", { class: "motion-speed", "aria-label": "speed" });
    for (const s of SPEEDS) {
      const o = el("option", { value: String(s) }, s + "×");
      if (s === 1) o.selected = true;
      speed.appendChild(o);
    }
    const scrub = el("input", { type: "range", class: "motion-time", min: "0", max: "1000", value: "0", "aria-label": "time" });
    const clock = el("output", { class: "motion-clock" }, "t = 0");
    const reset = el("button", { type: "button", class: "motion-reset" }, "Reset");
    bar.append(play, el("label", {}, "speed "), speed, scrub, clock, reset);
    stage.appendChild(bar);
    this.ui = { play, speed, scrub, clock };
    play.addEventListener("click", () => (this.playing ? this.pause() : this.play()));
    speed.addEventListener("change", () => (this.speed = parseFloat(speed.value)));
    // The samples' first and last times, read at each use: update() may bring new ones.
    scrub.addEventListener("input", () => {
      const t = this.t, t0 = t[0], t1 = t[t.length - 1];
      this.pause();
      this.seek(t0 + (t1 - t0) * scrub.value / 1000);
    });
    reset.addEventListener("click", () => {
      this.reset();
      this.seek(this.t[0]);
      this.play();
      this.speed = 1;
      speed.value = "1";
    });
    // Drag to turn the view about the fixed point.
    const canvas = this.renderer.domElement;
    let drag = null;
    canvas.addEventListener("pointerdown", (e) => {
      drag = { x: e.clientX, y: e.clientY, az: this.azimuth, el: this.elevation };
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener("pointermove", (e) => {
      if (!drag) return;
      this.azimuth = drag.az - (e.clientX - drag.x) * 0.01;
      this.elevation = Math.max(-1.45, Math.min(1.45, drag.el + (e.clientY - drag.y) * 0.01));
      this.place();
    });
    const stop = () => (drag = null);
    canvas.addEventListener("pointerup", stop);
    canvas.addEventListener("pointercancel", stop);
  };

  Viewer.prototype.legend = function (stage) {
    const d = this.data;
    const items = [
      [COLOURS.A, "R_A, R_B, R_C: the body's principal axes (columns of R(t)), smallest to largest moment", [COLOURS.A, COLOURS.B, COLOURS.C]],
      [COLOURS.k, "k: the upward vertical; the black dot is the fixed point O"],
    ];
    (d.cones || []).forEach((c, i) => items.push([COLOURS.cones[i % 2], c.name]));
    if ((d.trails.centre_of_mass || []).length > 1) items.push([COLOURS.cm, "trail of the centre of mass"]);
    if ((d.trails.tip_R_B || []).length > 1) items.push([COLOURS.tip, "trail of the tip of R_B"]);
    items.push([COLOURS.body, "the body: the uniform " + d.body.shape + " with moments A, B, C = " + d.body.moments.join(", ")]);
    for (const b of [d].concat(d.others || [])) if (b.label && (d.others || []).length) items.push([COLOURS.body, b.label]);
    const list = el("ul", { class: "motion-legend" });
    for (const [colour, text, several] of items) {
      const li = el("li");
      for (const c of several || [colour]) {
        const sw = el("span", { class: "swatch" });
        sw.style.background = hex(c);
        li.appendChild(sw);
      }
      li.appendChild(document.createTextNode(" " + text));
      list.appendChild(li);
    }
    stage.appendChild(list);
    this.legendList = list;
  };

  Viewer.prototype.play = function () {
    this.playing = true;
    this.ui.play.textContent = "Pause";
  };
  Viewer.prototype.pause = function () {
    this.playing = false;
    this.ui.play.textContent = "Play";
  };

  // Shows the motion at time `time` (clamped to the samples).
  Viewer.prototype.seek = function (time) {
    const t = this.t, n = t.length;
    time = Math.max(t[0], Math.min(t[n - 1], time));
    this.time = time;
    let lo = 0, hi = n - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (t[mid] <= time) lo = mid;
      else hi = mid;
    }
    const s = t[hi] > t[lo] ? (time - t[lo]) / (t[hi] - t[lo]) : 0;
    for (const b of this.bodies) b.frame.quaternion.copy(b.q[lo]).slerp(b.q[hi], s);
    for (const l of this.trails) l.geometry.setDrawRange(0, lo + 1);
    this.ui.scrub.value = String(Math.round(1000 * (time - t[0]) / (t[n - 1] - t[0])));
    this.ui.clock.textContent = "t = " + time.toFixed(2);
    this.dirty = true;
  };

  Viewer.prototype.tick = function (dt) {
    if (this.playing) {
      const t0 = this.t[0], t1 = this.t[this.t.length - 1];
      let next = this.time + dt * this.speed * this.base;
      if (next > t1) next = t0 + ((next - t0) % (t1 - t0));
      this.seek(next);
    }
    if (this.dirty) {
      this.renderer.render(this.scene, this.camera);
      this.frames++;
      this.dirty = false;
    }
  };

  function start() {
    const viewers = [];
    for (const fig of document.querySelectorAll("figure.motion")) {
      try {
        const data = JSON.parse(fig.querySelector("script.motion-data").textContent);
        const v = new Viewer(fig, data);
        v.seek(v.t[0]);
        viewers.push(v);
        window.motionViewers.push(v);
      } catch (e) {
        // No WebGL (an old browser, print): the still picture stays, and the page says why.
        const note = el("p", { class: "motion-note" }, "The 3D viewer cannot run here (" + e.message + "); the picture shows the same motion.");
        fig.insertBefore(note, fig.querySelector("figcaption"));
        window.motionViewers.push({ error: String(e), ready: false });
        console.error("motion viewer: " + e);
      }
    }
    // A live scene (live.js) hands the viewer the motion its module just computed: the viewer of
    // that figure shows the new samples (update: same renderer and view, new objects).
    window.motionViewerReplace = function (fig, data) {
      const v = viewers.find((w) => w.figure === fig);
      if (!v) return null;
      v.update(data);
      v.replaced = (v.replaced || 0) + 1;
      return v;
    };
    let last = null;
    function loop(now) {
      const dt = last === null ? 0 : Math.min(0.1, (now - last) / 1000);
      last = now;
      for (const v of viewers) v.tick(dt);
      requestAnimationFrame(loop);
    }
    if (viewers.length) requestAnimationFrame(loop);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
