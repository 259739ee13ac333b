// graphkin's scene drawn as SVG: the mechanism, its forces, the torque curve and the force polygons of a presolved
// cycle (docs/json.md, "scene"). One ES module, no library, no network, no build step.
//
// It draws what the scene holds and computes nothing of the mechanics: every coordinate drawn is a number of the
// scene, placed (y up becomes SVG's y down) or scaled by the scene's own force scale. Its only other arithmetic is
// the reader's: a vector's polar form for the table and the hover read-out, and the nearest presolved position
// to the pointer when the crank is dragged. A new input speed is speed.js's (the scene's two presolved parts added,
// or a presolved speed picked); this module draws the live copy of the scene it gives.
//
//   import { draw } from "./scene.js";
//   const view = draw(element, scene);     // view.show(i), view.index, view.timings, view.scene (at its speed),
//                                          // view.pause()

import { live, setRate } from "./speed.js";

const SVG = "http://www.w3.org/2000/svg";
const INK = { link: "#333", fill: "#dfe7f1", joint: "#1565c0", graphical: "#2e7d32", load: "#c62828",
  inertia: "#6a1b9a", ground: "#555", curve: "#1565c0", cursor: "#c62828" };

function el(tag, attrs, parent) {
  const node = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

function html(tag, attrs, parent, text) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  if (parent) parent.appendChild(node);
  return node;
}

// A label {symbol, sub, mark, unit} as SVG text (the subscript lowered) or as HTML (<sub>).
function svgLabel(label, parent, size) {
  const t = el("text", { "font-size": size, class: "gk-label" }, parent);
  t.appendChild(document.createTextNode(label.symbol));
  if (label.sub) {
    const s = el("tspan", { "baseline-shift": "sub", "font-size": "70%" }, t);
    s.textContent = label.sub;
  }
  if (label.mark) {
    const m = el("tspan", {}, t);
    m.textContent = label.mark;
  }
  return t;
}

function htmlLabel(label, parent) {
  parent.appendChild(document.createTextNode(label.symbol));
  if (label.sub) html("sub", {}, parent, label.sub);
  if (label.mark) parent.appendChild(document.createTextNode(label.mark));
}

const UNIT = { "N*m": "N·m", N: "N", m: "m", rad: "rad" };

// The polar form as the books print it: 27.04 N ∠ −73.78°.
export function polar(x, y, unit) {
  if (x === null || y === null) return "—";
  const size = Math.hypot(x, y);
  const angle = (Math.atan2(y, x) * 180) / Math.PI;
  return `${number(size)} ${UNIT[unit] || unit} ∠ ${number(angle, 2, true)}°`;
}

function number(v, decimals, fixed) {
  if (v === null) return "—";
  const text = fixed ? v.toFixed(decimals) : Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0)
    ? v.toExponential(3) : v.toPrecision(4);
  return text.replace("-", "−");
}

// One vector of a flat [x0, y0, x1, y1, …] list at position i, or null.
function at(flat, i) {
  const x = flat[2 * i];
  return x === null || x === undefined ? null : [x, flat[2 * i + 1]];
}

function setLine(line, a, b) {
  line.setAttribute("x1", a[0]);
  line.setAttribute("y1", -a[1]);
  line.setAttribute("x2", b[0]);
  line.setAttribute("y2", -b[1]);
}

function shown(node, yes) {
  node.style.display = yes ? "" : "none";
}

// An arrow drawn tail at `tail` [m] with its vector `F` [N] at `scale` N per metre of drawing.
function arrow(group, colour, marker, name, label, size) {
  const g = el("g", { class: "gk-arrow", "data-name": name }, group);
  const hit = el("line", { stroke: "transparent", "stroke-width": 10, "vector-effect": "non-scaling-stroke" }, g);
  const line = el("line", { stroke: colour, "stroke-width": 2, "vector-effect": "non-scaling-stroke",
    "marker-end": `url(#${marker})` }, g);
  const text = svgLabel(label, g, size);
  text.setAttribute("fill", colour);
  return { g, hit, line, text };
}

function placeArrow(a, tail, F, scale) {
  if (tail === null || F === null) return shown(a.g, false);
  shown(a.g, true);
  const tip = [tail[0] + F[0] / scale, tail[1] + F[1] / scale];
  setLine(a.line, tail, tip);
  setLine(a.hit, tail, tip);
  a.text.setAttribute("x", tip[0]);
  a.text.setAttribute("y", -tip[1]);
}

function markers(defs, size) {
  for (const [name, colour] of Object.entries(INK)) {
    const m = el("marker", { id: `gk-head-${name}`, viewBox: "0 0 10 10", refX: 9, refY: 5,
      markerUnits: "userSpaceOnUse", markerWidth: 0.035 * size, markerHeight: 0.035 * size, orient: "auto" }, defs);
    el("path", { d: "M0,0 L10,5 L0,10 z", fill: colour }, m);
  }
}

// -- the mechanism ------------------------------------------------------------------------------------------------
function mechanism(view, scene) {
  const [x0, y0, x1, y1] = scene.view;
  const size = scene.size;
  const svg = el("svg", { class: "gk-mechanism", viewBox: `${x0} ${-y1} ${x1 - x0} ${y1 - y0}`,
    role: "img", "aria-label": `${scene.title}: the mechanism and its forces` }, view.figures);
  markers(el("defs", {}, svg), size);
  const parts = { svg, links: [], forces: [], loads: [], inertia: [], points: [] };
  const bodies = el("g", { class: "gk-links" }, svg);
  const font = 0.04 * size;
  for (const link of scene.links) {
    const frame = link.number === scene.frame;
    if (frame) {
      for (const [name, flat] of Object.entries(link.points)) {
        const p = at(flat, 0);
        const s = 0.04 * size;
        el("path", { d: `M${p[0]},${-p[1]} l${-s},${1.6 * s} h${2 * s} z`, fill: "none", stroke: INK.ground,
          "stroke-width": 1.5, "vector-effect": "non-scaling-stroke", "data-point": `${link.number}.${name}` }, bodies);
      }
      continue;
    }
    // A bar or a plate: its outline; a block: a rectangle at its point; a gear: its pitch circle (below).
    if (link.outline.length > 1) {
      parts.links.push({ link, shape: el("polygon", { fill: INK.fill, "fill-opacity": 0.8, stroke: INK.link,
        "stroke-width": 2, "stroke-linejoin": "round", "vector-effect": "non-scaling-stroke",
        "data-link": link.number }, bodies) });
    } else if (link.outline.length === 1) {
      parts.links.push({ link, shape: el("rect", { width: 0.08 * size, height: 0.06 * size, fill: INK.fill,
        stroke: INK.link, "stroke-width": 2, "vector-effect": "non-scaling-stroke", "data-link": link.number },
      bodies) });
    }
    if (link.G) {
      parts.points.push({ flat: link.G, node: el("circle", { r: 0.012 * size, fill: INK.link,
        "data-point": `${link.number}.G` }, bodies) });
    }
    for (const [name, flat] of Object.entries(link.points)) {
      parts.points.push({ flat, node: el("circle", { r: 0.01 * size, fill: "#fff", stroke: INK.link,
        "stroke-width": 1.5, "vector-effect": "non-scaling-stroke", "data-point": `${link.number}.${name}` }, bodies) });
    }
  }
  parts.gears = scene.gears.map((gear) => ({
    flat: scene.links.find((l) => l.number === gear.link).points[gear.centre],
    node: el("circle", { r: gear.radius, fill: gear.internal ? "none" : INK.fill, "fill-opacity": 0.6,
      stroke: INK.link, "stroke-width": gear.internal ? 3 : 2, "stroke-dasharray": "8 3",
      "vector-effect": "non-scaling-stroke", "data-gear": `${gear.link}.${gear.centre}` }, bodies),
  }));
  bodies.append(...parts.points.map((p) => p.node)); // the pins above the gears
  parts.guides = scene.guides.map((guide) => el("line", { stroke: INK.ground, "stroke-width": 1,
    "stroke-dasharray": "6 3", "vector-effect": "non-scaling-stroke", "data-guide": guide.slider }, bodies));
  const forces = el("g", { class: "gk-forces" }, svg);
  for (const f of scene.forces) {
    parts.forces.push({ f, a: arrow(forces, INK.joint, "gk-head-joint", f.name, f.label, font) });
  }
  const loads = el("g", { class: "gk-loads" }, svg);
  for (const ld of scene.loads.filter((x) => x.force)) {
    parts.loads.push({ ld, a: arrow(loads, INK.load, "gk-head-load", ld.name, ld.label, font) });
  }
  const inertia = el("g", { class: "gk-inertia" }, svg);
  for (const inn of scene.inertia) {
    const offset = el("line", { stroke: INK.inertia, "stroke-width": 1, "stroke-dasharray": "3 3",
      "vector-effect": "non-scaling-stroke" }, inertia);
    parts.inertia.push({ inn, offset, a: arrow(inertia, INK.inertia, "gk-head-inertia", inn.name, inn.label, font) });
  }
  parts.groups = { forces, loads, inertia };
  parts.reason = el("text", { x: x0 + 0.02 * size, y: -y1 + 0.06 * size, "font-size": font, fill: INK.load,
    class: "gk-reason" }, svg);
  return parts;
}

function drawMechanism(parts, scene, i, ok) {
  const scale = scene.scales.force;
  for (const { link, shape } of parts.links) {
    shown(shape, ok);
    if (!ok) continue;
    if (link.outline.length > 1) {
      shape.setAttribute("points", link.outline.map((name) => {
        const p = at(link.points[name], i);
        return `${p[0]},${-p[1]}`;
      }).join(" "));
    } else {
      const p = at(link.points[link.outline[0]], i);
      shape.setAttribute("x", p[0] - 0.04 * scene.size);
      shape.setAttribute("y", -p[1] - 0.03 * scene.size);
    }
  }
  for (const { flat, node } of [...parts.gears, ...parts.points]) {
    const p = ok ? at(flat, i) : null;
    shown(node, p !== null);
    if (p === null) continue;
    node.setAttribute("cx", p[0]);
    node.setAttribute("cy", -p[1]);
  }
  scene.guides.forEach((guide, k) => {
    const a = ok ? at(guide.ends[0], i) : null;
    shown(parts.guides[k], a !== null);
    if (a !== null) setLine(parts.guides[k], a, at(guide.ends[1], i));
  });
  for (const { f, a } of parts.forces) placeArrow(a, ok ? at(f.at, i) : null, at(f.analytical, i), scale);
  for (const { ld, a } of parts.loads) {
    const F = at(ld.force, i);
    placeArrow(a, ok && F !== null && (F[0] !== 0 || F[1] !== 0) ? at(ld.at, i) : null, F, scale);
  }
  for (const { inn, offset, a } of parts.inertia) {
    const P = ok ? at(inn.line_point, i) : null;
    placeArrow(a, P, at(inn.force, i), scale);
    shown(offset, P !== null);
    if (P !== null) setLine(offset, at(inn.G, i), P);
  }
  parts.reason.textContent = ok ? "" : `Not reachable: ${scene.invalid.find((e) => e.index === i)?.reason || ""}`;
}

// -- the driving effort against the input --------------------------------------------------------------------------
function curve(view, scene) {
  const svg = el("svg", { class: "gk-curve", preserveAspectRatio: "none", role: "img",
    "aria-label": `the driving effort ${scene.effort.name} over the cycle` }, view.curveBox);
  const axis = el("line", { y1: 0, y2: 0, stroke: "#999", "stroke-width": 1, "vector-effect": "non-scaling-stroke" },
    svg);
  const path = el("path", { fill: "none", stroke: INK.curve, "stroke-width": 2, "vector-effect": "non-scaling-stroke" },
    svg);
  const cursor = el("line", { stroke: INK.cursor, "stroke-width": 1.5, "vector-effect": "non-scaling-stroke",
    class: "gk-cursor" }, svg);
  const dot = el("line", { stroke: INK.cursor, "stroke-width": 8, "stroke-linecap": "round",
    "vector-effect": "non-scaling-stroke", class: "gk-dot" }, svg);
  const parts = { svg, axis, path, cursor, dot };
  setCurve(parts, scene);
  return parts;
}

// The curve of the scene's effort (again when the speed changes it).
function setCurve(parts, scene) {
  const q = scene.input.values;
  const T = scene.effort.analytical;
  const [lo, hi] = scene.effort.range;
  const pad = 0.05 * (hi - lo || 1);
  const q0 = q[0];
  const q1 = q[q.length - 1];
  parts.svg.setAttribute("viewBox", `${q0} ${-(hi + pad)} ${q1 - q0 || 1} ${hi - lo + 2 * pad}`);
  parts.axis.setAttribute("x1", q0);
  parts.axis.setAttribute("x2", q1);
  let d = "";
  let pen = "M";
  for (let k = 0; k < q.length; k += 1) {
    if (T[k] === null) {
      pen = "M";
      continue;
    }
    d += `${pen}${q[k]},${-T[k]}`;
    pen = "L";
  }
  parts.path.setAttribute("d", d);
  parts.cursor.setAttribute("y1", -(hi + pad));
  parts.cursor.setAttribute("y2", -(lo - pad));
}

function drawCurve(parts, scene, i) {
  const q = scene.input.values[i];
  parts.cursor.setAttribute("x1", q);
  parts.cursor.setAttribute("x2", q);
  const T = scene.effort.analytical[i];
  shown(parts.dot, T !== null);
  if (T !== null) setLine(parts.dot, [q, T], [q, T]);
}

// -- the force polygons ---------------------------------------------------------------------------------------------
function polygons(view, scene) {
  const g = scene.graphical;
  if (!g) return null;
  // Each polygon at its own scale, the one that fits its extent over the whole cycle: it does not jump between
  // positions, and a sub-problem's small polygon is not a speck beside the largest.
  const cells = g.polygons.map((p, k) => {
    const side = Math.max(p.box[2] - p.box[0], p.box[3] - p.box[1]) * 1.25 || 1;
    const cx = (p.box[0] + p.box[2]) / 2;
    const cy = (p.box[1] + p.box[3]) / 2;
    const box = html("figure", { class: "gk-cell" }, view.polygonBox);
    const svg = el("svg", { viewBox: `${cx - side / 2} ${-cy - side / 2} ${side} ${side}`, "data-polygon": k,
      role: "img" }, box);
    markers(el("defs", {}, svg), side * 0.6);
    const sides = p.names.map((name, j) => {
      const colour = p.known[j] ? INK.load : INK.graphical;
      const a = arrow(svg, colour, p.known[j] ? "gk-head-load" : "gk-head-graphical", name, p.labels[j], side * 0.05);
      return a;
    });
    const caption = html("figcaption", {}, box);
    caption.textContent = `${p.kind}${p.sub ? ` (${p.sub})` : ""}, link ${p.link}`;
    svg.setAttribute("aria-label", `the ${p.kind} of link ${p.link}${p.sub ? ` in sub-problem ${p.sub}` : ""}`);
    return { p, box, svg, sides, m: p.names.length };
  });
  const reason = html("p", { class: "gk-reason" }, view.polygonBox);
  return { cells, reason };
}

function drawPolygons(parts, scene, i) {
  const ok = scene.graphical.valid[i] === 1;
  parts.reason.textContent = ok || scene.valid[i] !== 1 ? ""
    : `No construction: ${scene.graphical.invalid.find((e) => e.index === i)?.reason || ""}`;
  for (const { p, box, sides, m } of parts.cells) {
    const base = 2 * (m + 1) * i;
    const here = ok && p.vertices[base] !== null;
    shown(box, here);
    if (!here) continue;
    sides.forEach((a, j) => {
      const tail = [p.vertices[base + 2 * j], p.vertices[base + 2 * j + 1]];
      const tip = [p.vertices[base + 2 * j + 2], p.vertices[base + 2 * j + 3]];
      setLine(a.line, tail, tip);
      setLine(a.hit, tail, tip);
      a.text.setAttribute("x", (tail[0] + tip[0]) / 2);
      a.text.setAttribute("y", -(tail[1] + tip[1]) / 2);
    });
  }
}

// -- the table of forces --------------------------------------------------------------------------------------------
function table(view, scene) {
  const t = html("table", { class: "gk-table" }, view.tableBox);
  html("caption", {}, t, "Joint forces (F_ij: of link i on link j) and the driving effort");
  const head = html("tr", {}, html("thead", {}, t));
  for (const h of ["force", "analytical", "graphical"]) html("th", { scope: "col" }, head, h);
  const body = html("tbody", {}, t);
  const rows = scene.forces.map((f) => {
    const tr = html("tr", { "data-name": f.name }, body);
    htmlLabel(f.label, html("th", { scope: "row" }, tr));
    return { f, a: html("td", {}, tr), g: html("td", {}, tr) };
  });
  const tr = html("tr", { "data-name": scene.effort.name }, body);
  htmlLabel(scene.effort.label, html("th", { scope: "row" }, tr));
  const effort = { a: html("td", {}, tr), g: html("td", {}, tr) };
  return { rows, effort };
}

function drawTable(parts, scene, i) {
  for (const { f, a, g } of parts.rows) {
    const A = at(f.analytical, i);
    a.textContent = A ? polar(A[0], A[1], "N") : "—";
    const G = f.graphical ? at(f.graphical, i) : null;
    g.textContent = G ? polar(G[0], G[1], "N") : "—";
  }
  const unit = UNIT[scene.effort.label.unit];
  const A = scene.effort.analytical[i];
  const G = scene.effort.graphical ? scene.effort.graphical[i] : null;
  parts.effort.a.textContent = A === null ? "—" : `${number(A)} ${unit}`;
  parts.effort.g.textContent = G === null ? "—" : `${number(G)} ${unit}`;
}

// -- the input speed -------------------------------------------------------------------------------------------------
// The speed box: any speed of the file's sense (superpose), the presolved speeds (a list), or the one speed stated.
function rateControl(bar, scene) {
  const sp = scene.speed;
  const crank = sp.unit === "rad/s";
  const shownValue = (v) => String(Number((crank ? (v * 30) / Math.PI : v).toPrecision(6)));
  const lab = html("label", {}, bar);
  lab.appendChild(document.createTextNode(`${crank ? "ω" : "v"}${scene.driver.link} = `));
  let box;
  if (sp.kind === "superpose") {
    box = html("input", { type: "number", step: "any", value: shownValue(sp.value), size: 8, "data-do": "rate",
      "aria-label": "the input speed" }, lab);
  } else if (sp.kind === "presolved") {
    box = html("select", { "data-do": "rate", "aria-label": "the input speed (presolved)" }, lab);
    for (const p of sp.presolved) {
      html("option", p.value === sp.value ? { value: p.value, selected: "" } : { value: p.value }, box,
        shownValue(p.value));
    }
  } else {
    box = html("output", { "data-do": "rate" }, lab, sp.value === null ? "as the file gives" : shownValue(sp.value));
  }
  lab.appendChild(document.createTextNode(` ${crank ? "rpm" : "m/s"}`));
  const how = { superpose: "any speed of this sense, exactly", presolved: "presolved speeds only",
    static: "no force depends on it", fixed: "this speed only" }[sp.kind];
  const note = html("span", { class: "gk-note", "data-do": "rate-note" }, bar, `(${how}: ${sp.reason})`);
  const own = box.value;
  // The rate the box says [rad/s or m/s]: the scene's own where the box shows it unchanged; a list's options hold
  // the presolved rates themselves, a typed speed is in rpm for a crank.
  const typed = (text) => (crank ? (Number(text) * Math.PI) / 30 : Number(text));
  const rate = () => (box.value === own ? sp.value : sp.kind === "presolved" ? Number(box.value) : typed(box.value));
  return { box, note, own, rate, text: note.textContent };
}

// -- the page -------------------------------------------------------------------------------------------------------
function controls(view, scene) {
  const bar = html("div", { class: "gk-controls" }, view.root);
  const play = html("button", { type: "button", "data-do": "play", "aria-label": "play" }, bar, "▶");
  const slider = html("input", { type: "range", min: 0, max: scene.n - 1, step: 1, value: 0,
    "aria-label": "position in the cycle", "data-do": "position" }, bar);
  const where = html("output", { "data-do": "where" }, bar);
  const speed = html("select", { "aria-label": "positions a second while playing", "data-do": "speed" }, bar);
  for (const v of [15, 30, 60, 120]) html("option", v === 30 ? { value: v, selected: "" } : { value: v }, speed, `${v}/s`);
  const toggles = {};
  const names = [["forces", "joint forces"], ["loads", "loads"], ["inertia", "inertia"], ["curve", "torque curve"],
    ["table", "table"]];
  if (scene.graphical) names.push(["polygons", "force polygons"]);
  for (const [key, text] of names) {
    const lab = html("label", {}, bar);
    toggles[key] = html("input", { type: "checkbox", checked: "", "data-toggle": key }, lab);
    lab.appendChild(document.createTextNode(` ${text}`));
  }
  const rate = scene.speed ? rateControl(bar, scene) : null;
  return { play, slider, where, speed, toggles, rate };
}

function inputText(scene, i) {
  const q = scene.input.values[i];
  const { symbol, sub } = scene.input.label;
  return scene.input.name === "theta" ? `${symbol}${sub} = ${((q * 180) / Math.PI).toFixed(1)}°`
    : `${symbol}${sub} = ${(q * 1000).toFixed(2)} mm`;
}

// options.keys: what listens for the arrow keys and the space bar (the page: the document; a notebook's widget: its
// own element, so that keys typed in a cell stay the cell's).
export function draw(root, base, options = {}) {
  if (base.schema !== 1) throw new Error(`graphkin scene: schema ${base.schema} is not one this page reads (1)`);
  const scene = live(base);
  root.classList.add("gk-scene");
  const view = { root, index: 0, timings: [] };
  const ui = controls(view, scene);
  view.figures = html("div", { class: "gk-figures" }, root);
  const mech = mechanism(view, scene);
  view.polygonBox = html("div", { class: "gk-polygons" }, view.figures);
  const poly = polygons(view, scene);
  view.readout = html("p", { class: "gk-readout", "aria-live": "polite" }, root);
  const below = html("div", { class: "gk-below" }, root);
  view.curveBox = html("div", { class: "gk-curvebox" }, below);
  view.tableBox = html("div", { class: "gk-tablebox" }, below);
  const curveParts = curve(view, scene);
  const tableParts = table(view, scene);

  const on = (key) => !ui.toggles[key] || ui.toggles[key].checked;
  function show(i) {
    const k = ((Math.round(i) % scene.n) + scene.n) % scene.n;
    view.index = k;
    const ok = scene.valid[k] === 1;
    drawMechanism(mech, scene, k, ok);
    if (on("curve")) drawCurve(curveParts, scene, k);
    if (poly && on("polygons") && scene.graphical) drawPolygons(poly, scene, k);
    if (on("table")) drawTable(tableParts, scene, k);
    ui.slider.value = k;
    ui.where.textContent = inputText(scene, k);
    return k;
  }
  view.show = show;
  view.scene = scene;

  // Each input event is timed from the event (its timeStamp) to the SVG updated (view.timings, ms) and to the next
  // frame the browser draws (view.frames); view.work is the drawing alone, from the handler's start.
  view.frames = [];
  view.work = [];
  function step(event, i) {
    const t0 = event.timeStamp;
    const t1 = performance.now();
    show(i);
    const t2 = performance.now();
    view.timings.push(t2 - t0);
    view.work.push(t2 - t1);
    requestAnimationFrame(() => view.frames.push(performance.now() - t0));
  }
  ui.slider.addEventListener("input", (e) => step(e, Number(e.target.value)));
  (options.keys || document).addEventListener("keydown", (e) => {
    // The slider moves itself (and says so with "input"); the speed box keeps its own keys. A toggle has no use
    // for them: they step the position.
    if (e.target.matches?.("select, textarea, input:not([type=checkbox])")) return;
    if (e.key === "ArrowRight" || e.key === "ArrowUp") { e.preventDefault(); step(e, view.index + 1); }
    else if (e.key === "ArrowLeft" || e.key === "ArrowDown") { e.preventDefault(); step(e, view.index - 1); }
    else if (e.key === " " && e.target.tagName !== "BUTTON") { toggle(); e.preventDefault(); }
  });

  // Playing: one presolved position after another at the chosen rate.
  let playing = null;
  function toggle() {
    if (playing !== null) {
      cancelAnimationFrame(playing);
      playing = null;
      ui.play.textContent = "▶";
      ui.play.setAttribute("aria-label", "play");
      return;
    }
    let last = performance.now();
    ui.play.textContent = "⏸";
    ui.play.setAttribute("aria-label", "pause");
    const frame = (now) => {
      const steps = Math.floor(((now - last) * Number(ui.speed.value)) / 1000);
      if (steps > 0) {
        last += (steps * 1000) / Number(ui.speed.value);
        show(view.index + steps);
      }
      playing = requestAnimationFrame(frame);
    };
    playing = requestAnimationFrame(frame);
  }
  ui.play.addEventListener("click", toggle);
  view.pause = () => { if (playing !== null) toggle(); };

  for (const [key, box] of Object.entries(ui.toggles)) {
    box.addEventListener("change", () => {
      const target = { forces: mech.groups.forces, loads: mech.groups.loads, inertia: mech.groups.inertia,
        curve: view.curveBox, table: view.tableBox, polygons: view.polygonBox }[key];
      shown(target, box.checked && (key !== "polygons" || scene.graphical !== null));
      show(view.index);
    });
  }

  // A new speed: the live scene's forces at it (setRate), the curve redrawn, the polygons shown at the own speed only.
  if (ui.rate && ui.rate.box.tagName !== "OUTPUT") {
    ui.rate.box.addEventListener("change", () => {
      const rate = ui.rate.rate();
      if (!(rate * base.speed.value > 0)) {
        ui.rate.box.value = ui.rate.own;
        ui.rate.note.textContent = `(a speed of the file's sense only, not 0: ${base.speed.reason})`;
        return;
      }
      setRate(scene, base, rate);
      setCurve(curveParts, scene);
      shown(view.polygonBox, scene.graphical !== null && on("polygons"));
      ui.rate.note.textContent = ui.rate.text + (base.graphical && !scene.graphical
        ? " The graphical route and the force polygons are presolved at the file's speed only." : "");
      show(view.index);
    });
  }

  // Dragging the driver on the drawing: press near its handle (the crank's pin, the slider's point), then each move
  // shows the presolved position whose handle is nearest the pointer.
  const handle = scene.links.find((l) => l.number === scene.driver.link).points[scene.driver.handle];
  // The screen-to-drawing transform is read once a drag: reading it after a position is drawn would make the
  // browser lay the page out there and then, inside the move.
  let toDrawing = null;
  function pointer(event) {
    const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(toDrawing);
    return [p.x, -p.y];
  }
  function nearest(p) {
    let best = view.index;
    let gap = Infinity;
    for (let k = 0; k < scene.n; k += 1) {
      const h = at(handle, k);
      if (h === null) continue;
      const d = Math.hypot(h[0] - p[0], h[1] - p[1]);
      if (d < gap) { gap = d; best = k; }
    }
    return best;
  }
  //
  // A move is drawn when it comes. Chromium holds "pointermove" back to the start of the next frame (a drag's move
  // waited 5–15 ms there before its handler ran); "pointerrawupdate" comes at once, where the browser has it
  // (Chromium, in a page from disk, https or localhost). A mouse may report far more moves than there are frames:
  // the moves of one frame are drawn at once until they have taken BUDGET ms of it, and any later one at the frame.
  const BUDGET = 6;
  const MOVE = "onpointerrawupdate" in window ? "pointerrawupdate" : "pointermove";
  let dragging = false;
  let spent = 0; // ms of drawing moves since the last frame
  let held = null; // the last move held for the frame
  let counting = false;
  function move(event) {
    const k = nearest(pointer(event));
    if (k === view.index && held === null) return; // the pointer is still nearest the position shown
    if (!counting) {
      counting = true;
      requestAnimationFrame(() => {
        counting = false;
        spent = 0;
        if (held !== null) {
          const [e, j] = held;
          held = null;
          step(e, j);
        }
      });
    }
    if (spent >= BUDGET) {
      held = [event, k];
      return;
    }
    const t = performance.now();
    step(event, k);
    spent += performance.now() - t;
  }
  mech.svg.addEventListener("pointerdown", (e) => {
    toDrawing = mech.svg.getScreenCTM().inverse();
    const p = pointer(e);
    const h = at(handle, view.index);
    if (h === null || Math.hypot(h[0] - p[0], h[1] - p[1]) > 0.15 * scene.size) return;
    dragging = true;
    mech.svg.setPointerCapture(e.pointerId);
    e.preventDefault();
  });
  mech.svg.addEventListener(MOVE, (e) => { if (dragging) move(e); });
  mech.svg.addEventListener("pointerup", () => { dragging = false; });

  // Hovering a force reads it in polar form.
  function hover(e) {
    const g = e.target.closest?.(".gk-arrow");
    if (!g) return;
    const name = g.getAttribute("data-name");
    const k = view.index;
    const f = scene.forces.find((x) => x.name === name);
    if (f) {
      const A = at(f.analytical, k);
      const G = f.graphical ? at(f.graphical, k) : null;
      view.readout.textContent = `${name} = ${A ? polar(A[0], A[1], "N") : "—"} analytically` +
        (f.graphical ? `, ${G ? polar(G[0], G[1], "N") : "—"} graphically` : "");
      return;
    }
    const other = scene.loads.find((x) => x.name === name) || scene.inertia.find((x) => x.name === name);
    if (other) {
      const F = at(other.force, k);
      view.readout.textContent = `${name} = ${F ? polar(F[0], F[1], "N") : "—"}` +
        (other.h !== undefined && other.h[k] !== null ? `, its line ${number(other.h[k] * 1000)} mm from G` : "");
    }
  }
  mech.svg.addEventListener("pointerover", hover);
  show(0);
  view.ready = performance.now(); // the first frame's drawing done, from the page's start
  return view;
}
