// The student draws a construction (issue 38): a task's view drawn at its stated scale (docs/json.md, "Drawn
// answers") and the elements it asks for, placed with the mouse or the keyboard, snapped to the points and
// directions the task states. It computes no mechanics: every coordinate it draws is a number of the task placed at
// the task's scale, and what it hands back (`drawing()`) is where the student clicked, in the space's SI units.
// A practice page's Check matches the drawing against the targets the task carries (match.js); the notebook's Check
// asks the kernel (drawwidget.js).
import { el, html } from "./dom.js";
import { verdict } from "./match.js";

const SNAP_MM = 2; // a click within this many millimetres of drawing of a snap point lands on it
const SNAP_ANGLE = (2 * Math.PI) / 180; // a line within 2° of a snap direction takes it
const STEP_MM = 1; // an arrow key moves the cursor this far; with Shift ten times as far
const DRAG_MM = 1; // a press and release farther apart than this draw a line or vector in one stroke
const COLOURS = { given: "#455a64", known: "#8d6e63", drawn: "#1565c0", fault: "#c62828", right: "#2e7d32" };

const gapOf = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1]);
const NEEDS = { line: 2, vector: 2, point: 1 };

// Where the line through p at angle a crosses the box [x0, y0, x1, y1]: its two ends, or null if it misses it.
export function across(p, a, box) {
  const d = [Math.cos(a), Math.sin(a)];
  let lo = -Infinity;
  let hi = Infinity;
  for (let k = 0; k < 2; k += 1) {
    const [min, max] = [box[k], box[k + 2]];
    if (Math.abs(d[k]) < 1e-12) {
      if (p[k] < min || p[k] > max) return null;
    } else {
      const t1 = (min - p[k]) / d[k];
      const t2 = (max - p[k]) / d[k];
      lo = Math.max(lo, Math.min(t1, t2));
      hi = Math.min(hi, Math.max(t1, t2));
    }
  }
  return lo <= hi ? [[p[0] + lo * d[0], p[1] + lo * d[1]], [p[0] + hi * d[0], p[1] + hi * d[1]]] : null;
}

// Draw `task` into `root` and let the student draw its `draw` elements. options: `check` (a function given the
// drawing, for the notebook's kernel; default: a practice page's own match against task.check), `changed` (called
// with the drawing after every change). Returns the view: drawing(), onChange(cb), undo(), clear(), load(drawing),
// showFeedback(feedback), check(), toScreen([x, y]) (client pixels, for tests).
export function drawTask(root, task, options = {}) {
  const s = task.scale.si_per_mm;
  const [x0, y0, x1, y1] = task.view;
  const W = (x1 - x0) / s; // the view's size in millimetres of drawing
  const H = (y1 - y0) / s;
  const mm = (p) => [(p[0] - x0) / s, (y1 - p[1]) / s];
  const space = (q) => [x0 + q[0] * s, y1 - q[1] * s];
  const listeners = [];
  const snapPoints = (task.snap && task.snap.points) || [];
  const snapAngles = (task.snap && task.snap.angles) || [];

  const box = html("div", { class: "gk-draw" }, root);
  html("p", { class: "gk-ask" }, box, task.ask);
  const status = html("p", { class: "gk-draw-status", "aria-live": "polite" }, box);
  const sv = el("svg", { class: "gk-draw-svg", width: `${W}mm`, height: `${H}mm`, viewBox: `0 0 ${W} ${H}`,
    tabindex: "0", role: "application",
    "aria-label": `Drawing area for ${task.question}: ${task.ask}. Arrow keys move the cursor (Shift: ten times ` +
      "farther), Tab goes to the next snap point, Enter or Space places a point (with Alt: not snapped), Ctrl+Z " +
      "undoes." }, box);
  const defs = el("defs", {}, sv);
  for (const [name, colour] of Object.entries(COLOURS)) {
    const m = el("marker", { id: `gk-head-${name}-${task.question}`, viewBox: "0 0 10 10", refX: "10", refY: "5",
      markerWidth: "3.5", markerHeight: "3.5", markerUnits: "userSpaceOnUse", orient: "auto-start-reverse" }, defs);
    el("path", { d: "M0,0 L10,5 L0,10 z", fill: colour }, m);
  }
  const head = (name) => `url(#gk-head-${name}-${task.question})`;
  el("rect", { x: 0, y: 0, width: W, height: H, fill: "#fff", stroke: "#ccc", "stroke-width": 0.3 }, sv);
  const fixed = el("g", { class: "gk-given" }, sv);
  // A name as a book sets it: "a^c_B3B2" is a with c above and B3B2 below, "F43′" as it is.
  const label = (text, p, parent, colour) => {
    const t = el("text", { x: p[0] + 1, y: p[1] - 1, "font-size": 3.2, fill: colour, class: "gk-label" }, parent);
    const m = /^([^_^]+)(?:\^([^_]+))?(?:_(.+))?$/.exec(text);
    if (!m || (!m[2] && !m[3])) {
      t.textContent = text;
      return t;
    }
    t.textContent = m[1];
    if (m[2]) el("tspan", { "baseline-shift": "super", "font-size": 2.2 }, t).textContent = m[2];
    if (m[3]) el("tspan", { "baseline-shift": "sub", "font-size": 2.2 }, t).textContent = m[3];
    return t;
  };
  const shown = task.shown || {};
  for (const l of shown.lines || []) {
    const ends = across(l.through, l.angle, task.view);
    if (!ends) continue;
    const [a, b] = ends.map(mm);
    el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: COLOURS.known, "stroke-width": 0.35,
      "stroke-dasharray": "3 1 0.6 1", "data-known": l.name }, fixed);
    label(l.name, [a[0] + 0.85 * (b[0] - a[0]), a[1] + 0.85 * (b[1] - a[1])], fixed, COLOURS.known);
  }
  for (const g of shown.segments || []) {
    const [a, b] = [mm(g.from), mm(g.to)];
    el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: COLOURS.given, "stroke-width": 0.8,
      "stroke-linecap": "round", "data-segment": g.name }, fixed);
  }
  for (const v of shown.vectors || []) {
    const [a, b] = [mm(v.from), mm(v.to)];
    el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: COLOURS.given, "stroke-width": 0.5,
      "marker-end": head("given"), "data-vector": v.name }, fixed);
    label(v.name, [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2], fixed, COLOURS.given);
  }
  for (const p of shown.points || []) {
    const q = mm(p.at);
    el("circle", { cx: q[0], cy: q[1], r: 0.8, fill: COLOURS.given, "data-point": p.name }, fixed);
    label(p.name, q, fixed, COLOURS.given);
  }
  const scaleText = el("text", { x: 1.5, y: H - 1.5, "font-size": 3, fill: "#555", class: "gk-scale" }, sv);
  scaleText.textContent = `scale ${task.scale.text}`;
  const rightLayer = el("g", { class: "gk-right" }, sv);
  const drawnLayer = el("g", { class: "gk-drawn" }, sv);
  const hint = el("g", { class: "gk-hint", "pointer-events": "none" }, sv);
  const ring = el("circle", { r: SNAP_MM, fill: "none", stroke: "#f9a825", "stroke-width": 0.4, visibility: "hidden",
    class: "gk-snap-ring" }, hint);
  const rubber = el("line", { stroke: COLOURS.drawn, "stroke-width": 0.3, "stroke-dasharray": "1 1",
    visibility: "hidden" }, hint);
  const cursor = el("path", { stroke: "#000", "stroke-width": 0.25, fill: "none", visibility: "hidden",
    class: "gk-cursor" }, hint);

  const bar = html("div", { class: "gk-draw-controls" }, box);
  const button = (text, what, title) => {
    const b = html("button", { type: "button", "data-do": what, title }, bar, text);
    return b;
  };
  const undoButton = button("Undo", "undo", "Undo the last point placed (Ctrl+Z)");
  const clearButton = button("Clear", "clear", "Remove everything drawn");
  const checkButton = options.check || task.check ? button("Check", "check", "Check the drawing") : null;
  const todo = html("span", { class: "gk-draw-todo" }, bar);
  const message = html("div", { class: "gk-draw-feedback", "aria-live": "polite" }, box);
  if (!options.check && task.check) {
    html("p", { class: "gk-note gk-practice" }, box,
      "Practice: the check runs in this page only; no grade is recorded and nothing is sent anywhere.");
  }

  // The state: the finished elements (in the order task.draw asks), the points placed of the one being drawn.
  let elements = [];
  let placed = [];
  let feedback = null;
  let cursorAt = [W / 2, H / 2]; // the keyboard's cursor, in millimetres of drawing
  let snapIndex = -1;
  const want = () => task.draw[elements.length] || null;

  // Where a point at q (mm) lands: on a snap point within SNAP_MM, else (the second point of a line or vector) on the
  // direction from the first point nearest a snap angle within SNAP_ANGLE; with what it snapped to. With `free` (Alt
  // held with the mouse, Alt+Enter with the keys) where it is.
  function snapped(q, free = false) {
    if (free) return { at: q, to: null };
    let best = null;
    for (const p of snapPoints) {
      const d = gapOf(mm(p.at), q);
      if (d <= SNAP_MM && (!best || d < best.d)) best = { d, at: mm(p.at), name: p.name };
    }
    if (best) return { at: best.at, to: best.name };
    if (placed.length === 1 && NEEDS[want().kind] === 2) {
      const a = placed[0];
      const r = gapOf(a, q);
      if (r > 0) {
        const dir = Math.atan2(-(q[1] - a[1]), q[0] - a[0]); // in space (y up)
        for (const g of snapAngles) {
          let d = ((dir - g.angle) % Math.PI + Math.PI) % Math.PI;
          if (d > Math.PI / 2) d -= Math.PI;
          if (Math.abs(d) <= SNAP_ANGLE) {
            const t = r * Math.cos(dir - g.angle); // q projected on the snap direction through a, on its side
            return { at: [a[0] + t * Math.cos(g.angle), a[1] - t * Math.sin(g.angle)], to: g.name };
          }
        }
      }
    }
    return { at: q, to: null };
  }

  function drawing() {
    const out = elements.map((e) => ({ ...e }));
    return { drawing: 1, question: task.question, space: task.space, unit: task.unit, elements: out };
  }

  function changed() {
    feedback = null;
    render();
    const d = drawing();
    for (const cb of listeners) cb(d);
    if (options.changed) options.changed(d);
  }

  // A coordinate handed back is rounded to a thousandth of a millimetre of drawing: far below what a hand places.
  const decimals = Math.max(0, Math.ceil(-Math.log10(s * 1e-3)));
  const rounded = (q) => space(q).map((v) => Number(v.toFixed(decimals)));

  function element(kind, name, points) {
    const p = points.map(rounded);
    if (kind === "point") return { kind, name, at: p[0] };
    if (kind === "line") return { kind, name, through: [p[0], p[1]] };
    return { kind, name, from: p[0], to: p[1] };
  }

  function place(q, free = false) {
    const w = want();
    if (!w) return;
    const s1 = snapped(q, free);
    if (placed.length === 1 && gapOf(placed[0], s1.at) === 0) return; // a line needs two distinct points
    placed.push(s1.at);
    if (placed.length === NEEDS[w.kind]) {
      elements.push(element(w.kind, w.name, placed));
      placed = [];
    }
    changed();
  }

  function undo() {
    if (placed.length) placed.pop();
    else if (elements.length) {
      const last = elements.pop();
      if (NEEDS[last.kind] === 2) placed = [mm(last.kind === "line" ? last.through[0] : last.from)];
    } else return;
    changed();
  }

  function clear() {
    elements = [];
    placed = [];
    changed();
  }

  function drawElement(e, parent, colour, attrs = {}) {
    const common = { stroke: COLOURS[colour], "stroke-width": 0.5, ...attrs };
    if (e.kind === "point") {
      const q = mm(e.at);
      const g = el("g", { "data-name": e.name }, parent);
      el("circle", { cx: q[0], cy: q[1], r: 1.2, fill: "none", ...common }, g);
      el("path", { d: `M${q[0] - 1.6},${q[1]} h3.2 M${q[0]},${q[1] - 1.6} v3.2`, ...common,
        "stroke-width": 0.25 }, g);
      label(e.name, q, g, COLOURS[colour]);
      return g;
    }
    if (e.kind === "line") {
      const [p, q] = e.through;
      const ends = across(p, Math.atan2(q[1] - p[1], q[0] - p[0]), task.view);
      const g = el("g", { "data-name": e.name }, parent);
      if (ends) {
        const [a, b] = ends.map(mm);
        el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], ...common }, g);
      }
      for (const r of [p, q].map(mm)) el("circle", { cx: r[0], cy: r[1], r: 0.6, fill: COLOURS[colour] }, g);
      label(e.name, mm(q), g, COLOURS[colour]);
      return g;
    }
    const [a, b] = [mm(e.from), mm(e.to)];
    const g = el("g", { "data-name": e.name }, parent);
    el("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], ...common, "marker-end": head(colour) }, g);
    label(e.name, [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2], g, COLOURS[colour]);
    return g;
  }

  function render() {
    drawnLayer.replaceChildren();
    rightLayer.replaceChildren();
    const fault = new Set(feedback && feedback.fault ? feedback.fault : []);
    elements.forEach((e, k) => {
      const g = drawElement(e, drawnLayer, fault.has(k) ? "fault" : "drawn");
      g.setAttribute("data-index", k);
      if (fault.has(k)) g.classList.add("gk-fault");
    });
    for (const p of placed) el("circle", { cx: p[0], cy: p[1], r: 0.8, fill: COLOURS.drawn, class: "gk-placed" },
      drawnLayer);
    if (feedback && feedback.right) {
      for (const e of feedback.right) drawElement(e, rightLayer, "right", { "stroke-dasharray": "2 1.2" });
    }
    const w = want();
    todo.textContent = w ? `Draw ${w.kind} ${w.name}` + (NEEDS[w.kind] === 2
      ? (placed.length ? (w.kind === "vector" ? ": its tip" : ": a second point") : (w.kind === "vector"
        ? ": its tail" : ": a first point")) : "") + ` (${elements.length + 1} of ${task.draw.length})`
      : `All ${task.draw.length} drawn`;
    undoButton.disabled = !elements.length && !placed.length;
    clearButton.disabled = undoButton.disabled;
    if (!feedback) message.replaceChildren();
  }

  function showHint(q, free = false) {
    const s1 = snapped(q, free);
    ring.setAttribute("visibility", s1.to ? "visible" : "hidden");
    ring.setAttribute("cx", s1.at[0]);
    ring.setAttribute("cy", s1.at[1]);
    status.textContent = s1.to ? `snaps to ${s1.to}` : "";
    if (placed.length === 1) {
      rubber.setAttribute("visibility", "visible");
      for (const [k, v] of Object.entries({ x1: placed[0][0], y1: placed[0][1], x2: s1.at[0], y2: s1.at[1] })) {
        rubber.setAttribute(k, v);
      }
    } else rubber.setAttribute("visibility", "hidden");
    return s1;
  }

  function showFeedback(fb) {
    feedback = fb;
    render();
    message.replaceChildren();
    if (!fb) return;
    const cls = fb.verdict === "correct" ? "gk-right" : "gk-reason";
    const head1 = html("p", { class: `gk-verdict ${cls}`, "data-verdict": fb.verdict }, message,
      fb.verdict === "correct" ? "Right." : fb.verdict === "slip" ? `A slip: ${(fb.slip || "").replaceAll("_", " ")}.`
        : fb.verdict === "unreadable" ? "Unreadable." : fb.verdict === "missing" ? "Nothing drawn yet." : "Not right.");
    if (fb.score !== undefined && fb.max !== undefined) head1.textContent += ` ${fb.score} of ${fb.max}.`;
    if (fb.feedback) html("p", { class: "gk-words" }, message, fb.feedback);
    if (fb.practice) html("p", { class: "gk-note" }, message, "Practice only: no grade is recorded.");
  }

  function check() {
    if (options.check) return options.check(drawing());
    if (!task.check) return null;
    if (elements.length < task.draw.length) {
      const fb = { verdict: "incomplete", feedback: `Draw all ${task.draw.length} elements first ` +
        `(${elements.length} drawn).`, fault: [], practice: true };
      showFeedback(fb);
      message.querySelector(".gk-verdict").textContent = "Not finished.";
      return fb;
    }
    const fb = { ...verdict(elements, task.check), practice: true };
    showFeedback(fb);
    return fb;
  }

  function load(d) {
    const given = d && Array.isArray(d.elements) ? d.elements : [];
    elements = [];
    for (const [k, e] of given.entries()) {
      const w = task.draw[k];
      if (!w || e.kind !== w.kind) break;
      elements.push({ ...e, name: w.name });
    }
    placed = [];
    feedback = null;
    render();
  }

  // The mouse: a press places a point; a release far from the press places the second point of a line or vector
  // (press, drag, release), a release near it leaves the first placed for a second click.
  const inMM = (event) => {
    const m = sv.getScreenCTM().inverse();
    const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(m);
    return [p.x, p.y];
  };
  let down = null;
  sv.addEventListener("pointerdown", (event) => {
    if (event.button !== 0) return;
    sv.focus();
    sv.setPointerCapture(event.pointerId); // a drag's release counts where it ends, in the drawing or not
    const q = inMM(event);
    const before = elements.length;
    const first = placed.length === 0;
    place(q, event.altKey);
    down = first && placed.length === 1 && elements.length === before ? q : null;
    cursor.setAttribute("visibility", "hidden");
  });
  sv.addEventListener("pointermove", (event) => showHint(inMM(event), event.altKey));
  sv.addEventListener("pointerup", (event) => {
    const q = inMM(event);
    if (down && placed.length === 1 && gapOf(down, q) > DRAG_MM) place(q, event.altKey);
    down = null;
  });
  sv.addEventListener("pointerleave", () => {
    status.textContent = "";
    ring.setAttribute("visibility", "hidden");
    rubber.setAttribute("visibility", "hidden");
  });

  // The keyboard: a cursor moved by the arrows, placed by Enter or Space, sent to the snap points by Tab.
  function moveCursor(q) {
    cursorAt = [Math.min(Math.max(q[0], 0), W), Math.min(Math.max(q[1], 0), H)];
    cursor.setAttribute("visibility", "visible");
    const [x, y] = cursorAt;
    cursor.setAttribute("d", `M${x - 3},${y} h6 M${x},${y - 3} v6`);
    const s1 = showHint(cursorAt);
    const p = space(s1.at);
    status.textContent = `cursor at (${p[0].toPrecision(4)}, ${p[1].toPrecision(4)}) ${task.unit}` +
      (s1.to ? `, snaps to ${s1.to}` : "");
  }
  sv.addEventListener("keydown", (event) => {
    const step = (event.shiftKey ? 10 : 1) * STEP_MM;
    const moves = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, -step], ArrowDown: [0, step] };
    if (moves[event.key]) {
      moveCursor([cursorAt[0] + moves[event.key][0], cursorAt[1] + moves[event.key][1]]);
    } else if (event.key === "Enter" || event.key === " ") {
      place(cursorAt, event.altKey);
      moveCursor(cursorAt);
    } else if ((event.ctrlKey || event.metaKey) && event.key.toLowerCase() === "z") {
      undo();
    } else if (event.key === "Tab" && snapPoints.length) {
      const next = snapIndex + (event.shiftKey ? -1 : 1);
      if (next < 0 || next >= snapPoints.length) { // past the last: the focus leaves as Tab's would
        snapIndex = -1;
        return;
      }
      snapIndex = next;
      moveCursor(mm(snapPoints[snapIndex].at));
    } else return;
    event.preventDefault();
    event.stopPropagation(); // a notebook's own keys stay the notebook's
  });
  undoButton.addEventListener("click", undo);
  clearButton.addEventListener("click", clear);
  if (checkButton) checkButton.addEventListener("click", () => check());
  render();

  return {
    task,
    drawing,
    onChange: (cb) => listeners.push(cb),
    undo,
    clear,
    load,
    showFeedback,
    check,
    toScreen(p) {
      const q = mm(p);
      const r = new DOMPoint(q[0], q[1]).matrixTransform(sv.getScreenCTM());
      return [r.x, r.y];
    },
  };
}
