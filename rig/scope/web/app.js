// rig-scope's page: frames from /events (server-sent events, rig/scope/rig_scope/server.py)
// into uPlot charts, a top view and tables, redrawn once per animation frame when new data
// came. Every shown value sits in an element with data-signal="<prefix><CHANNEL>.<column>"
// (rig-log2csv's columns): its text rounded, its data-value attribute the exact number.
"use strict";

const WINDOW_S = 20; // the plots' time window [s of simulated time]
const COLORS = ["#2563eb", "#dc2626", "#16a34a", "#d97706", "#7c3aed", "#0891b2", "#db2777",
  "#65a30d", "#9333ea", "#ea580c", "#0d9488", "#4b5563"];
const UNIT_SIZE_M = [[4.6, 1.8], [4.0, 2.0]]; // drawn size of unit 0, of the others (schematic)

const rigs = new Map(); // prefix -> Rig
const stats = { frames: 0, draws: 0, drawTimes: [], connected: false };
window.rigScope = stats; // for tests and the curious: frames received, draws made

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === "class") e.className = v; else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

function fmt(v) {
  if (v === null || v === undefined) return "–";
  if (typeof v !== "number") return String(v);
  if (Number.isInteger(v)) return String(v);
  const a = Math.abs(v);
  if (a !== 0 && (a < 1e-3 || a >= 1e6)) return v.toExponential(3);
  return v.toPrecision(4);
}

// One signal's readout: its text and its exact value.
function setSignal(node, value) {
  const text = fmt(value);
  if (node.textContent !== text) node.textContent = text;
  node.dataset.value = value === null ? "null" : String(value);
}

class Rig {
  constructor(prefix, layout, container) {
    this.container = container; // the page's element the rig's section goes into
    this.prefix = prefix;
    this.layout = layout;
    this.signals = new Map(); // name -> element
    this.t = [];
    this.cols = layout.columns.map(() => []);
    this.colIndex = new Map(layout.columns.map((c, i) => [c, i]));
    this.trace = new Map();
    this.misses = [[], [], []];
    this.hist = null;
    this.dirty = true;
    this.build();
  }

  signal(name, label, unit, color) {
    const b = el("b", { "data-signal": name });
    this.signals.set(name, b);
    const span = el("span", {}, color ? el("i", { style: `background:${color}` }) : "",
      `${label} `, b, unit ? ` ${unit}` : "");
    return span;
  }

  build() {
    const L = this.layout;
    const title = this.prefix ? `Rig "${this.prefix}"` : "Rig";
    this.statusLine = el("span", { class: "warn" }, "waiting");
    const status = el("div", { class: "status" }, this.statusLine);
    for (const f of L.status_fields) status.append(this.signal(`${L.status_channel}.${f}`, f));
    this.root = el("section", { class: "rig", "data-prefix": this.prefix }, el("h2", {}, title),
      status);
    this.container.append(this.root); // in the document first: the charts take their card's width
    const grid = el("div", { class: "grid" });
    this.root.append(grid);

    this.canvas = el("canvas", { class: "top" });
    const poses = el("div", { class: "readout" });
    for (let u = 0; u < L.units; u++) {
      for (const [q, unit] of [["x_m", "m"], ["y_m", "m"], ["yaw_rad", "rad"]]) {
        poses.append(this.signal(`${L.state_channel}.unit${u}_${q}`, `unit ${u} ${q.split("_")[0]}`, unit));
      }
    }
    grid.append(el("div", { class: "card" }, el("h3", {}, "Top view (road frame, trace of each unit's CG)"),
      this.canvas, poses));

    this.charts = [];
    for (const panel of L.panels) this.charts.push(this.timeChart(grid, panel));
    this.histChart = this.makeHistogram(grid);
    this.missChart = this.makeMisses(grid);
    this.inputsCard = el("table");
    grid.append(el("div", { class: "card" }, el("h3", {}, "Input validity (RIG_STATUS)"), this.inputsCard));
    const can = el("table");
    for (const f of L.can_fields) {
      const b = el("b", { "data-signal": `${L.status_channel}.${f}` });
      this.signals.set(`${L.status_channel}.${f}`, b);
      can.append(el("tr", {}, el("td", {}, f), el("td", {}, b)));
    }
    grid.append(el("div", { class: "card" }, el("h3", {}, "CAN: bus state and counters"), can));
  }

  chartWidth(card) {
    return Math.max(300, card.clientWidth - 16);
  }

  timeChart(grid, panel) {
    const card = el("div", { class: "card" }, el("h3", {}, `${panel.title} [${panel.unit}]`));
    grid.append(card);
    const series = [{ label: "t [s]" }];
    const readout = el("div", { class: "readout" });
    panel.series.forEach(([column, label], k) => {
      const color = COLORS[k % COLORS.length];
      series.push({ label, stroke: color, width: 1.5, points: { show: false } });
      readout.append(this.signal(`${this.layout.state_channel}.${column}`, label, panel.unit, color));
    });
    const opts = { width: this.chartWidth(card), height: 170, series, legend: { show: false },
      cursor: { show: false }, scales: { x: { time: false } },
      axes: [{ label: "simulated time [s]", size: 34, labelSize: 14 }, { size: 60 }] };
    const plot = new uPlot(opts, [[], ...panel.series.map(() => [])], card);
    card.append(readout);
    return { plot, columns: panel.series.map(([c]) => this.colIndex.get(c)) };
  }

  makeHistogram(grid) {
    const card = el("div", { class: "card" }, el("h3", {}, "Loop lateness (wake-up minus deadline), cycles per bin"));
    grid.append(card);
    const opts = { width: this.chartWidth(card), height: 170, legend: { show: false },
      cursor: { show: false },
      series: [{ label: "µs" }, { label: "cycles", fill: "#2563eb88", stroke: "#2563eb",
        paths: uPlot.paths.bars({ size: [1, Infinity] }), points: { show: false } }],
      scales: { x: { time: false }, y: { distr: 3 } },
      axes: [{ label: "lateness [µs] (last bin: beyond two periods)", size: 34, labelSize: 14 }, { size: 60 }] };
    return new uPlot(opts, [[], []], card); // percentiles: in the status line
  }

  makeMisses(grid) {
    const card = el("div", { class: "card" }, el("h3", {}, "Deadline misses (RIG_STATUS)"));
    grid.append(card);
    const opts = { width: this.chartWidth(card), height: 170, legend: { show: false },
      cursor: { show: false }, scales: { x: { time: false } },
      series: [{ label: "t" }, { label: "total", stroke: "#dc2626", width: 1.5 },
        { label: "in the last second", stroke: "#d97706", width: 1.5 }],
      axes: [{ label: "simulated time [s]", size: 34, labelSize: 14 }, { size: 60 }] };
    return new uPlot(opts, [[], [], []], card); // values: in the status line
  }

  // --- data -----------------------------------------------------------------------------------
  take(frame) {
    for (const s of frame.samples || []) {
      this.t.push(s[0]);
      for (let k = 0; k < this.cols.length; k++) this.cols[k].push(s[k + 1]);
    }
    if (this.t.length) {
      const cut = this.t[this.t.length - 1] - WINDOW_S;
      let n = 0;
      while (n < this.t.length && this.t[n] < cut) n++;
      if (n > 0) { this.t.splice(0, n); for (const c of this.cols) c.splice(0, n); }
    }
    for (const [u, x, y] of frame.trace || []) {
      if (!this.trace.has(u)) this.trace.set(u, []);
      const tr = this.trace.get(u);
      tr.push([x, y]);
      if (tr.length > 20000) tr.splice(0, 10000);
    }
    for (const [t, total, win] of frame.misses || []) {
      this.misses[0].push(t); this.misses[1].push(total); this.misses[2].push(win);
    }
    if (this.misses[0].length > 400) for (const m of this.misses) m.splice(0, 200);
    this.hist = frame.hist;
    this.latest = frame.latest;
    this.status = frame.status;
    this.age = frame.age_s;
    this.dirty = true;
  }

  draw() {
    if (!this.dirty) return;
    this.dirty = false;
    for (const c of this.charts) c.plot.setData([this.t, ...c.columns.map(k => this.cols[k])]);
    this.drawHistogram();
    this.missChart.setData(this.misses);
    this.drawTop();
    this.drawTables();
  }

  drawHistogram() {
    if (!this.hist) return;
    const bin = this.layout.hist_bin_us;
    const xs = this.hist.map((_, k) => (k + 0.5) * bin);
    const ys = this.hist.map(c => (c > 0 ? c : null));
    this.histChart.setData([xs, ys]);
  }

  drawTables() {
    const latest = this.latest || {};
    for (const [name, node] of this.signals) if (name in latest) setSignal(node, latest[name]);
    const inputs = (this.status && this.status.inputs) || {};
    for (const [name, valid] of Object.entries(inputs)) {
      const key = `${this.layout.status_channel}.input_valid_${name}`;
      let node = this.signals.get(key);
      if (!node) {
        node = el("b", { "data-signal": key });
        this.signals.set(key, node);
        this.inputsCard.append(el("tr", {}, el("td", {}, name), el("td", {}, node)));
      }
      setSignal(node, valid);
      node.textContent = valid ? "valid" : "INVALID";
      node.className = `badge v${valid}`;
    }
    const age = this.age;
    if (age === null || age === undefined) { this.statusLine.textContent = "waiting"; this.statusLine.className = "warn"; }
    else if (age < 1.0) { this.statusLine.textContent = "live"; this.statusLine.className = "ok"; }
    else { this.statusLine.textContent = `no data for ${age.toFixed(0)} s (stopped?)`; this.statusLine.className = "bad"; }
  }

  drawTop() {
    const cv = this.canvas;
    const w = cv.clientWidth, h = cv.clientHeight;
    if (cv.width !== w || cv.height !== h) { cv.width = w; cv.height = h; }
    const g = cv.getContext("2d");
    g.clearRect(0, 0, w, h);
    const L = this.layout, latest = this.latest || {};
    const pose = u => ["x_m", "y_m", "yaw_rad"].map(q => latest[`${L.state_channel}.unit${u}_${q}`]);
    const [cx, cy] = pose(0);
    if (cx === undefined || cx === null) return;
    const scale = 6; // px per m
    const X = x => w / 2 + (x - cx) * scale, Y = y => h / 2 - (y - cy) * scale;
    g.strokeStyle = "#cbd5e1"; g.lineWidth = 1;
    const step = 10;
    for (let x = Math.floor((cx - w / 2 / scale) / step) * step; x < cx + w / 2 / scale; x += step) {
      g.beginPath(); g.moveTo(X(x), 0); g.lineTo(X(x), h); g.stroke();
    }
    for (let y = Math.floor((cy - h / 2 / scale) / step) * step; y < cy + h / 2 / scale; y += step) {
      g.beginPath(); g.moveTo(0, Y(y)); g.lineTo(w, Y(y)); g.stroke();
    }
    for (const [u, tr] of this.trace) {
      g.strokeStyle = COLORS[u % COLORS.length]; g.lineWidth = 1.5; g.beginPath();
      tr.forEach(([x, y], k) => (k ? g.lineTo(X(x), Y(y)) : g.moveTo(X(x), Y(y))));
      g.stroke();
    }
    for (let u = 0; u < L.units; u++) {
      const [x, y, yaw] = pose(u);
      if (x === null || x === undefined) continue;
      const [len, wid] = UNIT_SIZE_M[u === 0 ? 0 : 1];
      g.save(); g.translate(X(x), Y(y)); g.rotate(-yaw);
      g.fillStyle = COLORS[u % COLORS.length] + "cc";
      g.fillRect(-len / 2 * scale, -wid / 2 * scale, len * scale, wid * scale);
      g.fillStyle = "#111"; g.fillRect(len / 2 * scale - 4, -2, 4, 4); // the front
      g.restore();
    }
    g.fillStyle = "#334155";
    g.fillText(`grid ${step} m`, 6, h - 6);
  }
}

function onFrame(frame) {
  stats.frames++;
  if (frame.full) { // a new stream (first connect, reconnect, a page that lagged): start anew
    for (const r of rigs.values()) r.root.remove();
    rigs.clear();
  }
  for (const [prefix, f] of Object.entries(frame.rigs)) {
    let rig = rigs.get(prefix);
    if (f.layout && (!rig || rig.layout.generation !== f.layout.generation)) {
      if (rig) rig.root.remove();
      const waiting = document.getElementById("waiting");
      if (waiting) waiting.remove();
      rig = new Rig(prefix, f.layout, document.getElementById("rigs"));
      rigs.set(prefix, rig);
    }
    if (rig) rig.take(f);
  }
  stats.received = frame.received;
}

function loop(now) {
  let drew = false;
  for (const r of rigs.values()) { if (r.dirty) { r.draw(); drew = true; } }
  if (drew) {
    stats.draws++;
    stats.drawTimes.push(now);
    while (stats.drawTimes.length && now - stats.drawTimes[0] > 1000) stats.drawTimes.shift();
    stats.fps = stats.drawTimes.length;
    document.getElementById("rates").textContent = `${stats.fps} draws/s, ${stats.received} messages`;
  }
  requestAnimationFrame(loop);
}

window.addEventListener("resize", () => {
  for (const r of rigs.values()) {
    for (const p of [...r.charts.map(c => c.plot), r.histChart, r.missChart]) {
      p.setSize({ width: r.chartWidth(p.root.parentElement), height: 170 });
    }
  }
});

function connect() {
  const source = new EventSource("events");
  const conn = document.getElementById("connection");
  source.onopen = () => { stats.connected = true; conn.textContent = "connected"; conn.className = "ok"; };
  source.onerror = () => { stats.connected = false; conn.textContent = "reconnecting"; conn.className = "bad"; };
  source.onmessage = e => onFrame(JSON.parse(e.data));
}

connect();
requestAnimationFrame(loop);
