"use strict";
(function () {
  const D = JSON.parse(document.getElementById("ncsight-data").textContent);
  const $ = (id) => document.getElementById(id);
  const el = (tag, attrs, text) => {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = String(text);
    return e;
  };
  const NS = "http://www.w3.org/2000/svg";
  const sel = (tag, attrs) => {
    const e = document.createElementNS(NS, tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    return e;
  };
  const fmt = (v, d) => (v === null || v === undefined ? "-" : Number(v).toFixed(d === undefined ? 3 : d));

  $("title").textContent = "ncsight report: " + D.file;
  $("subtitle").textContent = D.title + " (" + D.machine + "), cycle time " + fmt(D.total, 2) + " s";
  if (!D.lathe) document.body.classList.add("mill");
  // What the stock simulation could not do is said first, never left out in silence.
  const notes = [];
  if (D.sim_error) notes.push("The thread could not be simulated on the stock: " + D.sim_error);
  ((D.sim && D.sim.findings) || []).filter((f) => f.kind === "not_simulated").forEach((f) => notes.push("Not simulated (line " + f.line + "): " + f.message));
  notes.forEach((n) => $("notices").appendChild(el("p", { class: "notice" }, n)));
  if (!D.lathe) $("diam-label").hidden = true;

  // ---- backplot -------------------------------------------------------------------------
  let radiusView = false;
  // Screen coordinates of a data point: lathe Z across, X up; mill X across, Y up (side: X, Z).
  const proj = (p, side) => (D.lathe ? [p[0], radiusView ? p[1] / 2 : p[1]] : side ? [p[0], p[2]] : [p[0], p[1]]);
  const views = [{ svg: $("plot-main"), side: false }];
  if (!D.lathe) views.push({ svg: $("plot-side"), side: true });
  const segEls = []; // [view][seg] -> path
  const BULK = D.segs.length > 20000;
  function bounds(side) {
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    // The first move starts where the machine was at power on: leave it out of the fit.
    const fit = D.segs.length > 1 ? D.segs.slice(1) : D.segs;
    for (const s of fit) for (const p of s.p) {
      const q = proj(p, side);
      x0 = Math.min(x0, q[0]); x1 = Math.max(x1, q[0]); y0 = Math.min(y0, q[1]); y1 = Math.max(y1, q[1]);
    }
    if (!isFinite(x0)) return [0, 0, 1, 1];
    const m = Math.max(x1 - x0, y1 - y0) * 0.05 + 0.5;
    return [x0 - m, y0 - m, x1 - x0 + 2 * m, y1 - y0 + 2 * m];
  }
  function draw() {
    segEls.length = 0;
    views.forEach((v, vi) => {
      const svg = v.svg;
      while (svg.firstChild) svg.removeChild(svg.firstChild);
      const b = bounds(v.side);
      v.box = b.slice();
      v.home = b.slice();
      svg.setAttribute("viewBox", b.join(" "));
      // y up: flip with a group transform around the box.
      const g = sel("g", { transform: "matrix(1 0 0 -1 0 " + (2 * b[1] + b[3]) + ")" });
      v.g = g;
      const list = [];
      const pathOf = (s) => s.p.map((p, j) => { const q = proj(p, v.side); return (j ? "L" : "M") + q[0] + " " + q[1]; }).join("");
      if (BULK) {
        // Many segments: one path per kind keeps the page responsive; a click on a source line
        // still lights that line's motion (an overlay), the tables keep everything.
        const byKind = {};
        D.segs.forEach((s) => { const c = "seg-" + (s.pull ? "p" : s.k); (byKind[c] = byKind[c] || []).push(pathOf(s)); });
        for (const c in byKind) g.appendChild(sel("path", { d: byKind[c].join(""), class: c }));
        v.overlay = sel("path", { class: "hl", d: "" });
        g.appendChild(v.overlay);
      } else {
        D.segs.forEach((s, i) => {
          const cls = "seg-" + (s.pull ? "p" : s.k) + (s.k === "t" || s.k === "ta" ? " thread-pass" : "");
          const path = sel("path", { d: pathOf(s), class: cls, "data-i": i, "data-line": s.l });
          if (s.pass) path.setAttribute("data-pass", s.pass);
          g.appendChild(path);
          list.push(path);
        });
      }
      const tool = sel("circle", { r: Math.max(b[2], b[3]) / 150, class: "tool", cx: 0, cy: 0 });
      g.appendChild(tool);
      v.tool = tool;
      svg.appendChild(g);
      segEls[vi] = list;
    });
    updateTool();
  }
  // zoom and pan
  views.forEach((v) => {
    const svg = v.svg;
    svg.addEventListener("wheel", (e) => {
      e.preventDefault();
      const r = svg.getBoundingClientRect();
      const fx = (e.clientX - r.left) / r.width, fy = (e.clientY - r.top) / r.height;
      const k = e.deltaY < 0 ? 0.8 : 1.25;
      const b = v.box;
      const nx = b[0] + fx * b[2] * (1 - k), ny = b[1] + fy * b[3] * (1 - k);
      v.box = [nx, ny, b[2] * k, b[3] * k];
      svg.setAttribute("viewBox", v.box.join(" "));
    }, { passive: false });
    let drag = null;
    svg.addEventListener("pointerdown", (e) => { drag = [e.clientX, e.clientY, v.box.slice()]; svg.setPointerCapture(e.pointerId); });
    svg.addEventListener("pointermove", (e) => {
      if (drag) {
        const r = svg.getBoundingClientRect();
        const dx = (e.clientX - drag[0]) / r.width * drag[2][2], dy = (e.clientY - drag[1]) / r.height * drag[2][3];
        v.box = [drag[2][0] - dx, drag[2][1] - dy, drag[2][2], drag[2][3]];
        svg.setAttribute("viewBox", v.box.join(" "));
        return;
      }
      const i = e.target.getAttribute && e.target.getAttribute("data-i");
      const tip = $("tooltip");
      if (i === null || i === undefined) { tip.hidden = true; return; }
      const s = D.segs[+i];
      const end = s.p[s.p.length - 1];
      let t = "line " + s.l + ": " + ({ r: "rapid", f: "feed", a: "arc", t: "thread", ta: "thread arc" })[s.k] + (s.pull ? " (pull-out)" : "");
      t += "\nend " + (D.lathe ? "X" + fmt(end[1]) + " Z" + fmt(end[0]) : "X" + fmt(end[0]) + " Y" + fmt(end[1]) + " Z" + fmt(end[2]));
      if (s.f) t += "\nF " + fmt(s.f, 1) + " mm/min";
      if (s.lead) t += "\nlead " + s.lead + "  from " + s.deg + " deg  " + s.rpm + " rpm";
      t += "\nt " + fmt(s.t0, 3) + " - " + fmt(s.t1, 3) + " s";
      tip.textContent = t;
      tip.style.left = e.clientX + 12 + "px";
      tip.style.top = e.clientY + 12 + "px";
      tip.hidden = false;
    });
    svg.addEventListener("pointerup", () => { drag = null; });
    svg.addEventListener("pointerleave", () => { $("tooltip").hidden = true; });
  });
  $("zoom-reset").addEventListener("click", () => views.forEach((v) => { v.box = v.home.slice(); v.svg.setAttribute("viewBox", v.box.join(" ")); }));
  $("radius-view").addEventListener("change", (e) => { radiusView = e.target.checked; draw(); highlight(selected); });

  // ---- player -------------------------------------------------------------------------
  let now = 0;
  const total = Math.max(D.total, 1e-9);
  const blockEnds = D.segs.filter((s) => s.be).map((s) => s.t1);
  function segAt(t) {
    let lo = 0, hi = D.segs.length - 1, best = -1;
    while (lo <= hi) { const m = (lo + hi) >> 1; if (D.segs[m].t0 <= t) { best = m; lo = m + 1; } else hi = m - 1; }
    return best;
  }
  function posAt(t) {
    const i = segAt(t);
    if (i < 0) return D.segs.length ? { s: null, p: D.segs[0].p[0] } : { s: null, p: [0, 0, 0] };
    const s = D.segs[i];
    const u = s.t1 > s.t0 ? Math.min(1, Math.max(0, (t - s.t0) / (s.t1 - s.t0))) : 1;
    const n = s.p.length - 1, x = u * n, k = Math.min(n - 1, Math.floor(x)), f = x - k;
    const a = s.p[k], b = s.p[k + 1];
    return { s: s, p: a.map((v, j) => v + (b[j] - v) * f), u: u };
  }
  function spindleAt(t, seg, u) {
    if (seg && seg.lead) return (seg.deg + (seg.t1 > seg.t0 ? 360 * u * Math.abs(seg.rpm) * (seg.t1 - seg.t0) / 60 : 0)) % 360;
    let rpm = 0;
    for (const e of D.events) { if (e.t > t) break; if (e.k === "spindle") rpm = e.rpm; }
    return null === rpm ? 0 : rpm;
  }
  function updateTool() {
    const at = posAt(now);
    views.forEach((v) => {
      if (!v.tool) return;
      const q = proj(at.p, v.side);
      v.tool.setAttribute("cx", q[0]);
      v.tool.setAttribute("cy", q[1]);
    });
    let rpm = 0, stop = "";
    for (const e of D.events) { if (e.t > now) break; if (e.k === "spindle") rpm = e.rpm; if (e.k === "stop") stop = e.reason; }
    const s = at.s;
    const lines = [
      "t " + fmt(now, 3) + " s of " + fmt(D.total, 3) + " s",
      "line " + (s ? s.l : "-") + "  " + (s ? ({ r: "G00 rapid", f: "G01 feed", a: "arc", t: "thread", ta: "thread arc" })[s.k] : "-"),
      (D.lathe ? "X " + fmt(radiusView ? at.p[1] / 2 : at.p[1]) + "  Z " + fmt(at.p[0]) : "X " + fmt(at.p[0]) + "  Y " + fmt(at.p[1]) + "  Z " + fmt(at.p[2])),
      "spindle " + fmt(s && s.lead ? s.rpm : rpm, 0) + " rpm" + (s && s.lead ? "  angle " + fmt(spindleAt(now, s, at.u), 2) + " deg" : ""),
      s && s.f ? "feed " + fmt(s.f, 1) + " mm/min" : s && s.lead ? "lead " + s.lead + " mm" : "",
    ];
    $("state").textContent = lines.join("\n");
    $("clock").textContent = fmt(now, 2) + " s";
  }
  function setTime(t) { now = Math.max(0, Math.min(total, t)); $("slider").value = Math.round(now / total * 1000); updateTool(); }
  $("slider").addEventListener("input", (e) => setTime(e.target.value / 1000 * total));
  $("step").addEventListener("click", () => { const n = blockEnds.find((t) => t > now + 1e-9); setTime(n === undefined ? total : n); });
  $("step-back").addEventListener("click", () => { const b = blockEnds.filter((t) => t < now - 1e-9); setTime(b.length ? b[b.length - 1] : 0); });
  let timer = null;
  $("play").addEventListener("click", () => {
    if (timer) { clearInterval(timer); timer = null; $("play").textContent = "Play"; return; }
    $("play").textContent = "Pause";
    const step = total / 600;
    timer = setInterval(() => { if (now >= total) { clearInterval(timer); timer = null; $("play").textContent = "Play"; return; } setTime(now + step); }, 25);
  });

  // ---- source listing with its diagnostics; a click highlights the line's motion -------
  let selected = null;
  const byLine = {};
  D.diags.forEach((d) => { (byLine[d.l] = byLine[d.l] || []).push(d); });
  const src = $("source");
  const frag = document.createDocumentFragment();
  D.lines.forEach((text, i) => {
    const n = i + 1;
    const row = el("div", { class: "src", "data-line": n });
    row.appendChild(el("span", { class: "ln" }, n));
    row.appendChild(el("span", { class: "code" }, text));
    row.addEventListener("click", () => highlight(n));
    frag.appendChild(row);
    (byLine[n] || []).forEach((d) => {
      frag.appendChild(el("div", { class: "diag " + d.sev }, d.sev + " " + d.code + " col " + d.c + ": " + d.msg + (d.hint ? " (" + d.hint + ")" : "")));
    });
  });
  src.appendChild(frag);
  function highlight(n) {
    selected = n;
    document.querySelectorAll(".src.sel").forEach((e) => e.classList.remove("sel"));
    const row = src.querySelector('.src[data-line="' + n + '"]');
    if (row) row.classList.add("sel");
    segEls.forEach((list) => list.forEach((p, i) => p.classList.toggle("hl", D.segs[i].l === n)));
    if (BULK) views.forEach((v) => {
      v.overlay.setAttribute("d", D.segs.filter((s) => s.l === n).map((s) => s.p.map((p, j) => { const q = proj(p, v.side); return (j ? "L" : "M") + q[0] + " " + q[1]; }).join("")).join(""));
    });
    const first = D.segs.find((s) => s.l === n);
    if (first) setTime(first.t0);
  }

  // ---- thread form from the stock simulation -------------------------------------------
  const th = $("thread");
  if (D.sim) {
    const m = D.sim;
    const t = el("table");
    [["major diameter", fmt(m.major_diameter_mm), "mm"], ["minor diameter", fmt(m.minor_diameter_mm), "mm"], ["depth", fmt(m.depth_mm), "mm"],
     ["pitch", fmt(m.pitch_mm), "mm"], ["lead", fmt(m.lead_mm), "mm"], ["starts", m.starts === null ? "-" : m.starts, ""],
     ["flank angles", m.flank_angles_deg ? fmt(m.flank_angles_deg[0], 1) + " + " + fmt(m.flank_angles_deg[1], 1) : "-", "deg"],
     ["full-depth length", fmt(m.full_depth_length_mm), "mm"], ["run-out length", fmt(m.runout_length_mm), "mm"]].forEach((r) => {
      const tr = el("tr"); tr.appendChild(el("th", {}, r[0])); tr.appendChild(el("td", {}, r[1] + " " + r[2])); t.appendChild(tr);
    });
    th.appendChild(t);
    if (D.section && D.section.length) {
      const svg = sel("svg", { class: "plot", id: "section", role: "img", "aria-label": "axial section" });
      let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
      D.section.forEach((p) => { x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]); y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]); });
      const h = Math.max(y1 - y0, 1e-3), w = Math.max(x1 - x0, 1e-3);
      svg.setAttribute("viewBox", x0 + " 0 " + w + " " + (h * 6));
      svg.setAttribute("preserveAspectRatio", "none");
      svg.style.height = "160px";
      svg.appendChild(sel("path", { d: D.section.map((p, i) => (i ? "L" : "M") + p[0] + " " + ((y1 - p[1]) * 5 + h * 0.5)).join(""), class: "seg-t" }));
      th.appendChild(el("div", {}, "Axial section at 0 degrees (radial scale stretched):"));
      th.appendChild(svg);
    }
    if (D.unrolled) {
      th.appendChild(el("div", {}, "Unrolled surface: z across, angle down, darker is deeper:"));
      th.appendChild(el("img", { src: D.unrolled, alt: "unrolled thread surface" }));
    }
    const fl = el("ul");
    (m.findings || []).forEach((f) => fl.appendChild(el("li", {}, f.kind + (f.line ? " (line " + f.line + ")" : "") + ": " + f.message)));
    if (!(m.findings || []).length) fl.appendChild(el("li", {}, "no findings"));
    th.appendChild(fl);
  } else {
    th.textContent = D.sim_error
      ? "The thread could not be simulated on the stock: " + D.sim_error
      : "The programme cuts no thread on a lathe: no stock simulation.";
  }

  // ---- time breakdown ----------------------------------------------------------------
  const kinds = {};
  D.segs.forEach((s) => { const k = s.pull ? "pull-out" : ({ r: "rapid", f: "feed", a: "arc", t: "thread", ta: "thread arc" })[s.k]; kinds[k] = (kinds[k] || 0) + (s.t1 - s.t0); });
  let dwell = 0, turn = 0; D.events.forEach((e) => { if (e.k === "dwell") dwell += e.s; if (e.k === "rotary") turn += e.s; });
  if (dwell) kinds.dwell = dwell;
  if (turn) kinds["rotary turn"] = turn;
  const keys = Object.keys(kinds).sort((a, b) => kinds[b] - kinds[a]);
  const chart = sel("svg", { width: 520, height: 24 * keys.length + 10, role: "img", "aria-label": "time by kind of motion" });
  const maxv = Math.max(...keys.map((k) => kinds[k]), 1e-9);
  keys.forEach((k, i) => {
    chart.appendChild(sel("rect", { x: 90, y: 5 + i * 24, width: Math.max(1, 300 * kinds[k] / maxv), height: 18, class: "bar" }));
    const a = sel("text", { x: 0, y: 19 + i * 24, class: "barlabel" }); a.textContent = k; chart.appendChild(a);
    const b = sel("text", { x: 95 + 300 * kinds[k] / maxv, y: 19 + i * 24, class: "barlabel" }); b.textContent = fmt(kinds[k], 2) + " s"; chart.appendChild(b);
  });
  $("time-chart").appendChild(chart);
  const perLine = {};
  D.segs.forEach((s) => { perLine[s.l] = (perLine[s.l] || 0) + (s.t1 - s.t0); });
  D.events.forEach((e) => { if (e.k === "rotary" && e.s > 0) perLine[e.l] = (perLine[e.l] || 0) + e.s; });
  const rows = Object.keys(perLine).map((l) => [+l, perLine[l]]).sort((a, b) => b[1] - a[1]);
  const tt = el("table", { id: "time-by-block" });
  const head = el("tr"); ["line", "block", "seconds"].forEach((h) => head.appendChild(el("th", {}, h))); tt.appendChild(head);
  let shown = 0;
  const more = el("button", { type: "button" }, "Show more");
  function showMore() {
    rows.slice(shown, shown + 500).forEach((r) => {
      const tr = el("tr"); tr.appendChild(el("td", {}, r[0])); tr.appendChild(el("td", {}, D.lines[r[0] - 1] || "")); tr.appendChild(el("td", {}, fmt(r[1], 3))); tt.appendChild(tr);
    });
    shown = Math.min(rows.length, shown + 500);
    more.hidden = shown >= rows.length;
  }
  more.addEventListener("click", showMore);
  $("time-table").appendChild(el("div", {}, "Total " + fmt(D.total, 3) + " s; by block (" + rows.length + " blocks with motion):"));
  $("time-table").appendChild(tt);
  $("time-table").appendChild(more);
  showMore();

  // ---- parameters and assumptions ---------------------------------------------------------
  const pt = el("table");
  const ph = el("tr"); ["parameter", "value", "unit", "meaning", "source"].forEach((h) => ph.appendChild(el("th", {}, h))); pt.appendChild(ph);
  D.params.forEach((p) => { const tr = el("tr"); p.forEach((c) => tr.appendChild(el("td", {}, c))); pt.appendChild(tr); });
  const pl = el("ul");
  D.settings.forEach((s) => pl.appendChild(el("li", {}, s)));
  if (D.thin) pl.appendChild(el("li", {}, "The backplot draws arcs with fewer points to stay fast; every block is in the tables."));
  $("params").appendChild(pl);
  $("params").appendChild(pt);

  draw();
  window.ncsightReport = { passes: D.passes, segments: D.segs.length, setTime: setTime, highlight: highlight };
})();
