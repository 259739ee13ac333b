// graphkin's scene drawn as SVG: the mechanism, its forces, the torque curve and the force polygons of a presolved
// cycle (docs/json.md, "scene"). One ES module, no library, no network, no build step.
//
// It draws what the scene holds and computes nothing of the mechanics: every coordinate drawn is a number of the
// scene, placed (y up becomes SVG's y down), scaled by the scene's own force scale, or (a free body's reaction)
// multiplied by the sign the scene states. Its only other arithmetic is the reader's: a vector's polar form for the
// table and the hover read-out (in SI or in the book's units, by the factors the scene gives), the nearest presolved
// position to the pointer when the crank is dragged, and, when playing, the presolved position whose time (the
// scene's) has come. A new input speed is speed.js's (the scene's two presolved parts added,
// or a presolved speed picked); this module draws the live copy of the scene it gives.
//
//   import { draw } from "./scene.js";
//   const view = draw(element, scene);     // view.show(i), view.index, view.timings, view.scene (at its speed),
//                                          // view.pause()

import { el, html } from "./dom.js";
import { live, setRate } from "./speed.js";

const INK = { link: "#333", fill: "#dfe7f1", joint: "#1565c0", graphical: "#2e7d32", load: "#c62828",
  inertia: "#6a1b9a", ground: "#555", curve: "#1565c0", cursor: "#c62828" };

// A label {symbol, sub, mark, unit} as SVG text (the subscript lowered) or as HTML (<sub>).
function svgLabel(label, parent, size) {
  const t = el("text", { "font-size": size, class: "gk-label" }, parent);
  t.appendChild(document.createTextNode(label.symbol));
  if (label.sup) {
    const s = el("tspan", { "baseline-shift": "super", "font-size": "70%" }, t);
    s.textContent = label.sup;
  }
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
  if (label.sup) html("sup", {}, parent, label.sup);
  if (label.sub) html("sub", {}, parent, label.sub);
  if (label.mark) parent.appendChild(document.createTextNode(label.mark));
}

// Each kind's unit in SI as the page writes it; the book's are the scene's (scene.book), with their factors from SI.
export const SI = { length: { unit: "m", scale: 1 }, force: { unit: "N", scale: 1 }, torque: { unit: "N·m", scale: 1 },
  velocity: { unit: "m/s", scale: 1 }, acceleration: { unit: "m/s²", scale: 1 } };
const KIND = { "N*m": "torque", N: "force", m: "length", "m/s": "velocity", "m/s^2": "acceleration" };

// The polar form as the books print it, in the unit u ({unit, scale}: shown = scale × SI): 27.04 N ∠ −73.78°.
export function polar(x, y, u = SI.force) {
  if (x === null || y === null) return "—";
  const size = u.scale * Math.hypot(x, y);
  const angle = (Math.atan2(y, x) * 180) / Math.PI;
  return `${number(size)} ${u.unit} ∠ ${number(angle, 2, true)}°`;
}

// Distinct arrowheads' ids for each SVG of a page (an id is the document's: a second SVG's marker of the same id
// would draw the first's, at the first's size).
let heads = 0;

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
  // `marker` is an id markers() gave.
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

// Arrowheads of each colour for one SVG, `size` its drawing's size; returns the id of the head of a colour's name.
function markers(defs, size) {
  heads += 1;
  const prefix = `gk${heads}-head-`;
  for (const [name, colour] of Object.entries(INK)) {
    const m = el("marker", { id: `${prefix}${name}`, viewBox: "0 0 10 10", refX: 9, refY: 5,
      markerUnits: "userSpaceOnUse", markerWidth: 0.035 * size, markerHeight: 0.035 * size, orient: "auto" }, defs);
    el("path", { d: "M0,0 L10,5 L0,10 z", fill: colour }, m);
  }
  return (name) => `${prefix}${name}`;
}

// -- the mechanism ------------------------------------------------------------------------------------------------
function mechanism(view, scene) {
  const [x0, y0, x1, y1] = scene.view;
  const size = scene.size;
  const svg = el("svg", { class: "gk-mechanism", viewBox: `${x0} ${-y1} ${x1 - x0} ${y1 - y0}`,
    role: "img", "aria-label": `${scene.title}: the mechanism and its forces` }, view.figures);
  const head = markers(el("defs", {}, svg), size);
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
  // A spoke from each gear's centre to a point of its pitch circle that turns with it (schema 3's "mark").
  parts.spokes = scene.gears.filter((gear) => gear.mark).map((gear) => ({
    centre: scene.links.find((l) => l.number === gear.link).points[gear.centre], mark: gear.mark,
    node: el("line", { stroke: INK.link, "stroke-width": 2, "vector-effect": "non-scaling-stroke",
      "data-spoke": `${gear.link}.${gear.centre}` }, bodies),
  }));
  bodies.append(...parts.points.map((p) => p.node)); // the pins above the gears
  parts.guides = scene.guides.map((guide) => el("line", { stroke: INK.ground, "stroke-width": 1,
    "stroke-dasharray": "6 3", "vector-effect": "non-scaling-stroke", "data-guide": guide.slider }, bodies));
  const forces = el("g", { class: "gk-forces" }, svg);
  for (const f of scene.forces) {
    parts.forces.push({ f, a: arrow(forces, INK.joint, head("joint"), f.name, f.label, font) });
  }
  const loads = el("g", { class: "gk-loads" }, svg);
  for (const ld of scene.loads.filter((x) => x.force)) {
    parts.loads.push({ ld, a: arrow(loads, INK.load, head("load"), ld.name, ld.label, font) });
  }
  const inertia = el("g", { class: "gk-inertia" }, svg);
  for (const inn of scene.inertia) {
    const offset = el("line", { stroke: INK.inertia, "stroke-width": 1, "stroke-dasharray": "3 3",
      "vector-effect": "non-scaling-stroke" }, inertia);
    parts.inertia.push({ inn, offset, a: arrow(inertia, INK.inertia, head("inertia"), inn.name, inn.label, font) });
  }
  parts.groups = { forces, loads, inertia };
  parts.reason = el("text", { x: x0 + 0.02 * size, y: -y1 + 0.06 * size, "font-size": font, fill: INK.load,
    class: "gk-reason" }, svg);
  return parts;
}

// A link's outline (a polygon), a block (a rectangle at its point) or a gear (its pitch circle) at position i.
function placeLink(shape, link, scene, i) {
  if (link.outline.length > 1) {
    shape.setAttribute("points", link.outline.map((name) => {
      const p = at(link.points[name], i);
      return `${p[0]},${-p[1]}`;
    }).join(" "));
  } else if (link.outline.length === 1) {
    const p = at(link.points[link.outline[0]], i);
    shape.setAttribute("x", p[0] - 0.04 * scene.size);
    shape.setAttribute("y", -p[1] - 0.03 * scene.size);
  } else {
    const gear = scene.gears.find((g) => g.link === link.number);
    const p = at(link.points[gear.centre], i);
    shape.setAttribute("cx", p[0]);
    shape.setAttribute("cy", -p[1]);
  }
}

function drawMechanism(parts, scene, i, ok) {
  const scale = scene.scales.force;
  for (const { link, shape } of parts.links) {
    shown(shape, ok);
    if (ok) placeLink(shape, link, scene, i);
  }
  for (const { flat, node } of [...parts.gears, ...parts.points]) {
    const p = ok ? at(flat, i) : null;
    shown(node, p !== null);
    if (p === null) continue;
    node.setAttribute("cx", p[0]);
    node.setAttribute("cy", -p[1]);
  }
  for (const { centre, mark, node } of parts.spokes) {
    const c = ok ? at(centre, i) : null;
    const m = ok ? at(mark, i) : null;
    shown(node, c !== null && m !== null);
    if (c !== null && m !== null) setLine(node, c, m);
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
    const head = markers(el("defs", {}, svg), side * 0.6);
    const sides = p.names.map((name, j) => {
      const colour = p.known[j] ? INK.load : INK.graphical;
      const a = arrow(svg, colour, head(p.known[j] ? "load" : "graphical"), name, p.labels[j], side * 0.05);
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

// -- the free bodies ------------------------------------------------------------------------------------------------
// Each moving link alone with the forces on it (scene.free_bodies): the scene's joint forces times the sign it states
// (+1: the force on this link as the scene holds it, −1: its reaction), its loads and its inertia resultant, at the
// scene's force scale, in a box that holds it over the whole cycle; the resultant's offset from G (dashed) and its
// arrow are cut at the box where its line lies outside. Its couples are curved arrows on the rings the scene gives
// (centre, radius, start, span), counter-clockwise for a positive value of the array each refers to: the driving
// effort, a load's torque, a sliding pair's couple (times the sign it states), or the inertia torque where the
// scene's resultant has no line (its force vanishes). A slider driver's free body carries its driving force: the
// effort times the guide's direction the scene gives, at the slider's point.
const COUPLE = { effort: "joint", load: "load", inertia: "inertia", joint: "joint" };

function couple(svg, t, head, font) {
  const g = el("g", { class: "gk-couple", "data-name": t.name }, svg);
  const hit = el("path", { fill: "none", stroke: "transparent", "stroke-width": 10,
    "vector-effect": "non-scaling-stroke" }, g);
  const path = el("path", { fill: "none", stroke: INK[COUPLE[t.of]], "stroke-width": 2,
    "vector-effect": "non-scaling-stroke", "marker-end": `url(#${head(COUPLE[t.of])})` }, g);
  const text = svgLabel(t.label, g, font);
  text.setAttribute("fill", INK[COUPLE[t.of]]);
  return { g, hit, path, text };
}

// The couple's value at position i in the live scene `sc` [N·m], or null where it is not drawn.
function coupleValue(sc, t, i) {
  if (t.of === "effort") return sc.effort.analytical[i];
  if (t.of === "load") return sc.loads[t.index].torque[i];
  if (t.of === "joint") {
    const C = sc.forces[t.index].couple[i];
    return C === null ? null : t.sign * C;
  }
  const inn = sc.inertia[t.index];
  return at(inn.line_point, i) === null ? inn.torque[i] : null;
}

function placeCouple(c, centre, t, T) {
  if (centre === null || T === null || T === 0) return shown(c.g, false);
  shown(c.g, true);
  const point = (a) => [centre[0] + t.radius * Math.cos(a), centre[1] + t.radius * Math.sin(a)];
  const [from, to] = T > 0 ? [t.start, t.start + t.span] : [t.start + t.span, t.start];
  const a = point(from);
  const b = point(to);
  // On the page y points down: counter-clockwise on the drawing is SVG's negative sweep.
  const d = `M${a[0]},${-a[1]} A${t.radius},${t.radius} 0 ${t.span > Math.PI ? 1 : 0} ${T > 0 ? 0 : 1} ${b[0]},${-b[1]}`;
  c.path.setAttribute("d", d);
  c.hit.setAttribute("d", d);
  const m = point(t.start + t.span / 2);
  c.text.setAttribute("x", centre[0] + 1.15 * (m[0] - centre[0]));
  c.text.setAttribute("y", -(centre[1] + 1.15 * (m[1] - centre[1])));
}

function bodies(view, scene, read) {
  if (!scene.free_bodies || scene.free_bodies.length === 0) return null;
  const cells = scene.free_bodies.map((b) => {
    const link = scene.links.find((l) => l.number === b.link);
    const [x0, y0, x1, y1] = b.box;
    const side = Math.max(x1 - x0, y1 - y0) || scene.size;
    const box = html("figure", { class: "gk-cell gk-body" }, view.bodyBox);
    const svg = el("svg", { viewBox: `${x0} ${-y1} ${x1 - x0 || side} ${y1 - y0 || side}`, "data-body": b.link,
      role: "img", "aria-label": `the free body of link ${b.link}`, overflow: "hidden" }, box);
    const head = markers(el("defs", {}, svg), side * 0.6);
    const style = { fill: INK.fill, "fill-opacity": 0.8, stroke: INK.link, "stroke-width": 2,
      "vector-effect": "non-scaling-stroke", "data-link": b.link };
    const gear = scene.gears.find((g) => g.link === b.link);
    const shape = link.outline.length > 1 ? el("polygon", style, svg)
      : link.outline.length === 1 ? el("rect", { ...style, width: 0.08 * scene.size, height: 0.06 * scene.size }, svg)
        : gear ? el("circle", { ...style, r: gear.radius, "stroke-dasharray": "8 3" }, svg) : null;
    const font = 0.05 * side;
    const arrows = [];
    for (const f of b.forces) {
      const a = arrow(svg, INK.joint, head("joint"), f.name, f.label, font);
      const vector = (sc, i) => {
        const F = at(sc.forces[f.index].analytical, i);
        return F === null ? null : [f.sign * F[0], f.sign * F[1]];
      };
      arrows.push({ a, tail: (sc, i) => at(sc.forces[f.index].at, i), vector });
      read.set(a.g, (sc, i) => [f.name, vector(sc, i), "force"]);
    }
    if (b.drive) {
      const a = arrow(svg, INK.joint, head("joint"), b.drive.name, b.drive.label, font);
      const vector = (sc, i) => {
        const u = at(scene.effort.direction, i);
        const P = sc.effort.analytical[i];
        return u === null || P === null ? null : [P * u[0], P * u[1]];
      };
      arrows.push({ a, tail: (sc, i) => at(scene.effort.at, i), vector });
      read.set(a.g, (sc, i) => [b.drive.name, vector(sc, i), "force"]);
    }
    for (const j of b.loads.filter((k) => scene.loads[k].force)) {
      const ld = scene.loads[j];
      const a = arrow(svg, INK.load, head("load"), ld.name, ld.label, font);
      arrows.push({ a, tail: (sc, i) => at(ld.at, i), vector: (sc, i) => at(ld.force, i) });
      read.set(a.g, (sc, i) => [ld.name, at(ld.force, i), "force"]);
    }
    let offset = null;
    if (b.inertia !== null) {
      const inn = scene.inertia[b.inertia];
      offset = el("line", { stroke: INK.inertia, "stroke-width": 1, "stroke-dasharray": "3 3",
        "vector-effect": "non-scaling-stroke", "data-offset": inn.name }, svg);
      const a = arrow(svg, INK.inertia, head("inertia"), inn.name, inn.label, font);
      arrows.push({ a, tail: (sc, i) => at(sc.inertia[b.inertia].line_point, i),
        vector: (sc, i) => at(sc.inertia[b.inertia].force, i) });
      read.set(a.g, (sc, i) => [inn.name, at(sc.inertia[b.inertia].force, i), "force"]);
    }
    const couples = (b.torques || []).map((t) => {
      const c = couple(svg, t, head, font);
      read.set(c.g, (sc, i) => [t.name, coupleValue(sc, t, i), "torque"]);
      const centre = t.of === "joint" ? scene.forces[t.index].at : t.point === "G" ? link.G : link.points[t.point];
      return { t, c, centre };
    });
    const caption = html("figcaption", {}, box);
    const inertia = b.inertia !== null ? scene.inertia[b.inertia].name : null;
    caption.textContent = `link ${b.link}${link.name ? ` (${link.name})` : ""}` + (inertia
      ? `; ${inertia}: −m a_G and −I_G α as one resultant, its line h from G (cut at this box)` +
        (couples.some(({ t }) => t.of === "inertia") ? `, or the couple T${b.link}i where the force vanishes` : "")
      : "");
    return { b, link, box, shape, arrows, offset, couples };
  });
  return { cells };
}

function drawBodies(parts, scene, i, ok) {
  const scale = scene.scales.force;
  for (const { b, link, box, shape, arrows, offset, couples } of parts.cells) {
    shown(box, ok);
    if (!ok) continue;
    if (shape) placeLink(shape, link, scene, i);
    for (const { a, tail, vector } of arrows) {
      const F = vector(scene, i);
      placeArrow(a, F !== null && (F[0] !== 0 || F[1] !== 0) ? tail(scene, i) : null, F, scale);
    }
    if (offset) {
      const P = at(scene.inertia[b.inertia].line_point, i);
      shown(offset, P !== null);
      if (P !== null) setLine(offset, at(link.G, i), P);
    }
    for (const { t, c, centre } of couples) placeCouple(c, at(centre, i), t, coupleValue(scene, t, i));
  }
}

// -- the velocity and acceleration polygons ----------------------------------------------------------------------------
// Each from its pole, each vector from its tail to its tip as the scene holds them (scene.motion): given vectors red,
// those whose line only is known green, those found blue.
function motionPolygons(view, scene, read) {
  if (!scene.motion) return null;
  const colour = { "size and direction": "load", direction: "graphical", found: "joint" };
  const cells = scene.motion.polygons.map((p, k) => {
    const side = Math.max(p.box[2] - p.box[0], p.box[3] - p.box[1]) * 1.25 || 1;
    const cx = (p.box[0] + p.box[2]) / 2;
    const cy = (p.box[1] + p.box[3]) / 2;
    const box = html("figure", { class: "gk-cell gk-motion" }, view.motionBox);
    const svg = el("svg", { viewBox: `${cx - side / 2} ${-cy - side / 2} ${side} ${side}`, "data-motion": k,
      role: "img", "aria-label": `the ${p.kind} polygon` }, box);
    const head = markers(el("defs", {}, svg), side * 0.6);
    const m = p.names.length;
    const sides = p.names.map((name, j) => {
      const a = arrow(svg, INK[colour[p.known[j]]], head(colour[p.known[j]]), name, p.labels[j], side * 0.05);
      read.set(a.g, (sc, i) => {
        const v = sc.motion ? sc.motion.polygons[k].vectors : null;
        const o = 4 * (m * i + j);
        return [name, v && v[o] !== null ? [v[o + 2] - v[o], v[o + 3] - v[o + 1]] : null, p.kind];
      });
      return a;
    });
    html("figcaption", {}, box, `${p.kind} polygon`);
    return { p, box, sides, m };
  });
  const reason = html("p", { class: "gk-reason" }, view.motionBox);
  return { cells, reason };
}

function drawMotion(parts, scene, i) {
  const ok = scene.motion.valid[i] === 1;
  parts.reason.textContent = ok || scene.valid[i] !== 1 ? ""
    : `No polygons: ${scene.motion.invalid.find((e) => e.index === i)?.reason || ""}`;
  for (const { p, box, sides, m } of parts.cells) {
    const base = 4 * m * i;
    const here = ok && p.vectors[base] !== null;
    shown(box, here);
    if (!here) continue;
    sides.forEach((a, j) => {
      const o = base + 4 * j;
      const tail = [p.vectors[o], p.vectors[o + 1]];
      const tip = [p.vectors[o + 2], p.vectors[o + 3]];
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

function drawTable(parts, scene, i, units) {
  const force = units("force");
  for (const { f, a, g } of parts.rows) {
    const A = at(f.analytical, i);
    a.textContent = A ? polar(A[0], A[1], force) : "—";
    const G = f.graphical ? at(f.graphical, i) : null;
    g.textContent = G ? polar(G[0], G[1], force) : "—";
  }
  const u = units(KIND[scene.effort.label.unit]);
  const A = scene.effort.analytical[i];
  const G = scene.effort.graphical ? scene.effort.graphical[i] : null;
  parts.effort.a.textContent = A === null ? "—" : `${number(u.scale * A)} ${u.unit}`;
  parts.effort.g.textContent = G === null ? "—" : `${number(u.scale * G)} ${u.unit}`;
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
  // Playing at the true speed or slowed (a fraction of it: the scene's time of each position), or, where the input
  // has no one speed, at so many positions a second.
  const timed = scene.input.time !== null && scene.input.time !== undefined;
  const speed = html("select", { "aria-label": timed ? "playing speed, of the true speed" : "positions a second while playing",
    "data-do": "speed" }, bar);
  if (timed) {
    const fractions = [1, 1 / 2, 1 / 5, 1 / 10, 1 / 20, 1 / 50, 1 / 100, 1 / 200, 1 / 500];
    // Slowed at first to the fastest that takes two seconds or more a cycle.
    const first = fractions.find((f) => scene.input.period / f >= 2) ?? fractions[fractions.length - 1];
    for (const f of fractions) {
      html("option", f === first ? { value: f, selected: "" } : { value: f }, speed,
        f === 1 ? "true speed" : `slowed ×1/${Math.round(1 / f)}`);
    }
  } else {
    for (const v of [15, 30, 60, 120]) html("option", v === 30 ? { value: v, selected: "" } : { value: v }, speed, `${v}/s`);
  }
  const toggles = {};
  const names = [["forces", "joint forces"], ["loads", "loads"], ["inertia", "inertia"], ["curve", "torque curve"],
    ["table", "table"]];
  if (scene.graphical) names.push(["polygons", "force polygons"]);
  if (scene.motion) names.push(["motion", "motion polygons"]);
  if (scene.free_bodies && scene.free_bodies.length) names.push(["bodies", "free bodies"]);
  for (const [key, text] of names) {
    const lab = html("label", {}, bar);
    toggles[key] = html("input", key === "bodies" ? { type: "checkbox", "data-toggle": key }
      : { type: "checkbox", checked: "", "data-toggle": key }, lab);
    lab.appendChild(document.createTextNode(` ${text}`));
  }
  // The units a value is read in: SI, or the book's.
  const lab = html("label", {}, bar, "units ");
  const units = html("select", { "data-do": "units", "aria-label": "the units values are read in" }, lab);
  html("option", { value: "SI", selected: "" }, units, "SI");
  const b = scene.book;
  html("option", { value: "book" }, units,
    `${b.name === "SI" ? "the book's" : b.name} (${b.length.unit}, ${b.force.unit}, ${b.torque.unit})`);
  const rate = scene.speed ? rateControl(bar, scene) : null;
  return { play, slider, where, speed, timed, toggles, units, rate };
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
  // Schema 2 has no couples on its free bodies and no graphical route at other speeds: drawn without them.
  if (base.schema !== 3 && base.schema !== 2) {
    throw new Error(`graphkin scene: schema ${base.schema} is not one this page reads (2, 3)`);
  }
  const scene = live(base);
  root.classList.add("gk-scene");
  const view = { root, index: 0, timings: [] };
  const ui = controls(view, scene);
  view.figures = html("div", { class: "gk-figures" }, root);
  const mech = mechanism(view, scene);
  view.polygonBox = html("div", { class: "gk-polygons" }, view.figures);
  let poly = polygons(view, scene);
  // What hovering an arrow of a free body or a motion polygon reads: its name, its vector at a position, its kind.
  const read = new Map();
  view.motionBox = html("div", { class: "gk-motions" }, view.figures);
  const motion = motionPolygons(view, scene, read);
  shown(view.motionBox, motion !== null);
  view.bodyBox = html("div", { class: "gk-bodies" }, view.figures);
  const body = bodies(view, scene, read);
  shown(view.bodyBox, false);
  view.readout = html("p", { class: "gk-readout", "aria-live": "polite" }, root);
  const below = html("div", { class: "gk-below" }, root);
  view.curveBox = html("div", { class: "gk-curvebox" }, below);
  view.tableBox = html("div", { class: "gk-tablebox" }, below);
  const curveParts = curve(view, scene);
  const tableParts = table(view, scene);

  const on = (key) => !ui.toggles[key] || ui.toggles[key].checked;
  view.units = "SI";
  const units = (kind) => (view.units === "book" ? scene.book[kind] : SI[kind]);
  function show(i) {
    const k = ((Math.round(i) % scene.n) + scene.n) % scene.n;
    view.index = k;
    const ok = scene.valid[k] === 1;
    drawMechanism(mech, scene, k, ok);
    if (on("curve")) drawCurve(curveParts, scene, k);
    if (poly && on("polygons") && scene.graphical) drawPolygons(poly, scene, k);
    if (motion && on("motion") && scene.motion) drawMotion(motion, scene, k);
    if (body && on("bodies")) drawBodies(body, scene, k, ok);
    if (on("table")) drawTable(tableParts, scene, k, units);
    ui.slider.value = k;
    ui.where.textContent = inputText(scene, k);
    readout();
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
    // At the true speed or slowed: the mechanism's time runs at the chosen fraction of the clock's, and the position
    // shown is the last one reached by then. Otherwise: so many positions a second.
    let clock = ui.timed ? scene.input.time[view.index] : 0;
    const frame = (now) => {
      if (ui.timed) {
        const { time, period } = scene.input;
        clock = (clock + ((now - last) / 1000) * Number(ui.speed.value)) % period;
        last = now;
        let k = view.index;
        let reached = -Infinity;
        for (let j = 0; j < scene.n; j += 1) {
          if (time[j] <= clock && time[j] > reached) { reached = time[j]; k = j; }
        }
        if (k !== view.index) show(k);
      } else {
        const steps = Math.floor(((now - last) * Number(ui.speed.value)) / 1000);
        if (steps > 0) {
          last += (steps * 1000) / Number(ui.speed.value);
          show(view.index + steps);
        }
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
        curve: view.curveBox, table: view.tableBox, polygons: view.polygonBox, motion: view.motionBox,
        bodies: view.bodyBox }[key];
      shown(target, box.checked && (key !== "polygons" || scene.graphical !== null)
        && (key !== "motion" || scene.motion !== null));
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
      // The polygons at the new speed: each at the scale of its extent there (a presolved speed's construction
      // may hold other steps).
      view.polygonBox.replaceChildren();
      poly = polygons(view, scene);
      shown(view.polygonBox, scene.graphical !== null && on("polygons"));
      shown(view.motionBox, scene.motion !== null && on("motion"));
      ui.rate.note.textContent = ui.rate.text + (base.graphical && !scene.graphical
        ? " The graphical route and the force polygons are presolved at the file's speed only." : "")
        + (base.motion && !scene.motion ? " The motion polygons are presolved at the file's speed only." : "");
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
  // (Chromium, in a secure context: a page from disk, over TLS, or from localhost). A mouse may report far more
  // moves than there are frames: the moves of one frame are drawn at once until they have taken BUDGET ms of it,
  // and any later one at the frame.
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

  // Hovering (or tapping) a force reads it in polar form, in the units chosen; so does a free body's arrow and a
  // motion polygon's vector. The read-out follows the position and the units until another arrow is hovered.
  let hovered = null;
  function readout() {
    if (!hovered) return;
    const k = view.index;
    const reader = read.get(hovered);
    if (reader) {
      const [name, v, kind] = reader(scene, k);
      const u = units(kind);
      view.readout.textContent = `${name} = ${kind === "torque"
        ? (v === null ? "—" : `${number(u.scale * Math.abs(v))} ${u.unit} ${v > 0 ? "CCW" : "CW"}`)
        : v ? polar(v[0], v[1], u) : "—"}`;
      return;
    }
    const name = hovered.getAttribute("data-name");
    const force = units("force");
    const f = scene.forces.find((x) => x.name === name);
    if (f) {
      const A = at(f.analytical, k);
      const G = f.graphical ? at(f.graphical, k) : null;
      view.readout.textContent = `${name} = ${A ? polar(A[0], A[1], force) : "—"} analytically` +
        (f.graphical ? `, ${G ? polar(G[0], G[1], force) : "—"} graphically` : "");
      return;
    }
    const other = scene.loads.find((x) => x.name === name) || scene.inertia.find((x) => x.name === name);
    if (other) {
      const F = at(other.force, k);
      const L = units("length");
      view.readout.textContent = `${name} = ${F ? polar(F[0], F[1], force) : "—"}` +
        (other.h !== undefined && other.h[k] !== null ? `, its line ${number(other.h[k] * L.scale)} ${L.unit} from G`
          : "");
    }
  }
  function hover(e) {
    const g = e.target.closest?.(".gk-arrow, .gk-couple");
    if (!g) return;
    hovered = g;
    readout();
  }
  for (const box of [mech.svg, view.motionBox, view.bodyBox]) box.addEventListener("pointerover", hover);
  ui.units.addEventListener("change", () => {
    view.units = ui.units.value;
    show(view.index);
  });
  show(0);
  view.ready = performance.now(); // the first frame's drawing done, from the page's start
  return view;
}
