// A drawn answer matched against the targets a practice page carries (docs/json.md, "Drawn answers"): the grader's
// rule (graphkin/exercises/drawn_grading.py) read the same way, for a page that grades nothing and records nothing.
// A reader's geometry only (distances and angles between what was drawn and what the task gives); no DOM, no
// mechanics. (page.py puts this module, draw.js and drawwidget.js in one ES module.)

const gap = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1]);

// The angle between two directions, modulo π, in [0, π/2].
export function lineGap(a, b) {
  const d = Math.abs(((a - b) % Math.PI + Math.PI) % Math.PI);
  return Math.min(d, Math.PI - d);
}

const direction = (p, q) => Math.atan2(q[1] - p[1], q[0] - p[0]);

// The distance from the point p to the line through a and b (a ≠ b).
function offLine(p, a, b) {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  return Math.abs(dx * (p[1] - a[1]) - dy * (p[0] - a[0])) / Math.hypot(dx, dy);
}

// Whether the drawn element e matches the target element t (same kind) within tolerance {length, angle}.
export function matches(e, t, tol) {
  if (!e || !t || e.kind !== t.kind) return false;
  if (e.kind === "point") return gap(e.at, t.at) <= tol.length;
  if (e.kind === "vector") return gap(e.from, t.from) <= tol.length && gap(e.to, t.to) <= tol.length;
  if (e.kind === "line") {
    const [a, b] = e.through;
    if (gap(a, b) === 0) return false;
    const [p, q] = t.through;
    return lineGap(direction(a, b), direction(p, q)) <= tol.angle && offLine(p, a, b) <= tol.length;
  }
  return false;
}

// A task's words (a phrase, as the grader's feedback puts them after "Correct: " or "Not quite: ") as a sentence.
const sentence = (w) => (w.endsWith(".") ? w : `${w}.`).replace(/^./, (c) => c.toUpperCase());

const all = (elements, target, tol) => elements.length === target.elements.length
  && elements.every((e, k) => matches(e, target.elements[k], tol));

// The verdict of a drawing's elements against check = {targets, tolerance, words}: the first target matched
// ("correct" for the first, whose slip is null; "slip" with its name otherwise), or "wrong" with `fault`, the indices
// of the elements that do not match the right construction.
export function verdict(elements, check) {
  const tol = check.tolerance;
  const hit = check.targets.find((t) => all(elements, t, tol));
  const words = check.words || {};
  if (hit && hit.slip === null) {
    return { verdict: "correct", slip: null, fault: [], feedback: sentence(words.right || "this is the construction") };
  }
  if (hit) {
    return { verdict: "slip", slip: hit.slip, fault: faults(elements, check.targets[0], tol),
      feedback: sentence(words[hit.slip] || `a known slip: ${hit.slip.replaceAll("_", " ")}`) };
  }
  return { verdict: "wrong", slip: null, fault: faults(elements, check.targets[0], tol),
    feedback: sentence(words.wrong
      || "this matches neither the construction nor a known slip: the marked elements are off") };
}

function faults(elements, right, tol) {
  const out = [];
  elements.forEach((e, k) => { if (!matches(e, right.elements[k], tol)) out.push(k); });
  return out;
}
