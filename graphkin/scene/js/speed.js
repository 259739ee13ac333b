// The speed of a scene's input changed in the browser (docs/json.md, "speed"): the one module of graphkin's pages
// that computes with the mechanics' numbers, and only as the scene says it may. Where the forces are linear in the
// square of the input rate, F(ω) = F_rest + ω² F_ω² with both parts presolved by Python; elsewhere it picks a
// presolved speed. No DOM: scene.js draws what it gives. (page.py puts this module and scene.js in one.)

// What the drawing reads is a copy of the scene whose speed-dependent values the speed box replaces (the parts drawn
// hold its objects); the scene itself stays as Python gave it.
export function live(scene) {
  return { ...scene, scales: { ...scene.scales }, effort: { ...scene.effort }, input: { ...scene.input },
    forces: scene.forces.map((f) => ({ ...f })), inertia: scene.inertia.map((x) => ({ ...x })) };
}

function largest(scene) {
  let top = 0;
  for (const f of scene.forces) {
    for (let k = 0; k < f.analytical.length; k += 2) {
      if (f.analytical[k] !== null) top = Math.max(top, Math.hypot(f.analytical[k], f.analytical[k + 1]));
    }
  }
  return top;
}

const superposed = (rest, omega2, r2) => rest.map((v, k) => (v === null ? null : v + r2 * omega2[k]));

// A polygon's extent over the cycle [xmin, ymin, xmax, ymax] from its vertices (the page draws each at its own scale),
// or `box` where it has none.
function extent(flat, box) {
  const out = [Infinity, Infinity, -Infinity, -Infinity];
  for (let k = 0; k < flat.length; k += 2) {
    if (flat[k] === null) continue;
    out[0] = Math.min(out[0], flat[k]);
    out[1] = Math.min(out[1], flat[k + 1]);
    out[2] = Math.max(out[2], flat[k]);
    out[3] = Math.max(out[3], flat[k + 1]);
  }
  return out[0] <= out[2] ? out : box;
}

// The graphical route at the live speed: the scene's own, a presolved speed's, or each polygon's vertices
// rest + ω² omega2 (speed.superpose.graphical); null where the scene has none at that speed.
function graphicalAt(base, own, chosen, r2) {
  const g = base.graphical;
  const sg = base.speed.superpose ? base.speed.superpose.graphical : null;
  if (own || !g) return g;
  if (chosen) return chosen.graphical || null;
  if (!sg) return null;
  return { valid: sg.valid, invalid: sg.invalid, polygons: g.polygons.map((p, k) => {
    const vertices = superposed(sg.polygons[k].rest, sg.polygons[k].omega2, r2);
    return { ...p, vertices, box: extent(vertices, p.box) };
  }) };
}
const scaled = (flat, c) => flat.map((v) => (v === null ? null : c * v));

// Set the live scene `view` to the input rate `rate` [rad/s or m/s] of `base`: at its own speed, its own values;
// otherwise F_rest + rate² F_ω² and each inertia resultant times (rate/rate₀)², its line unmoved (speed.kind
// "superpose"), or the presolved speed's values ("presolved"). The graphical route follows the same way, from its own
// presolved parts (its joint forces, effort and every polygon's vertices) or the presolved speed's construction; the
// motion polygons are presolved at the own speed only. At one constant speed a position is reached at its
// time × rate₀/rate. The force scale grows, never shrinks, so that the largest arrow stays as long as the scene drew
// it.
export function setRate(view, base, rate) {
  const sp = base.speed;
  const own = rate === sp.value;
  const r2 = rate * rate;
  const chosen = sp.kind === "presolved" ? sp.presolved.find((p) => p.value === rate) : null;
  if (!own && !chosen && sp.kind !== "superpose") throw new Error(`graphkin scene: no forces at ${rate}`);
  const graphical = graphicalAt(base, own, chosen, r2);
  const sg = sp.superpose && !own && !chosen ? sp.superpose.graphical : null;
  view.forces.forEach((f, j) => {
    const part = sp.superpose ? sp.superpose.forces[j] : null;
    f.analytical = own ? base.forces[j].analytical : chosen ? chosen.forces[j]
      : superposed(part.rest, part.omega2, r2);
    if (base.forces[j].couple) {
      f.couple = own ? base.forces[j].couple : chosen ? chosen.couples[j]
        : superposed(part.couple.rest, part.couple.omega2, r2);
    }
    f.graphical = own ? base.forces[j].graphical : !graphical ? undefined : chosen ? chosen.graphical.forces[j]
      : superposed(sg.forces[j].rest, sg.forces[j].omega2, r2);
  });
  view.inertia.forEach((inn, j) => {
    const b = base.inertia[j];
    const c = r2 / (sp.value * sp.value);
    Object.assign(inn, own ? b : chosen ? chosen.inertia[j] : { force: scaled(b.force, c), torque: scaled(b.torque, c) });
  });
  const T = own ? base.effort.analytical : chosen ? chosen.effort
    : superposed(sp.superpose.effort.rest, sp.superpose.effort.omega2, r2);
  const finite = T.filter((v) => v !== null);
  const lo = Math.min(0, ...finite);
  const hi = Math.max(0, ...finite);
  const Tg = own ? base.effort.graphical : !graphical ? undefined : chosen ? chosen.graphical.effort
    : superposed(sg.effort.rest, sg.effort.omega2, r2);
  Object.assign(view.effort, { analytical: T, graphical: Tg,
    range: own ? base.effort.range : hi > lo ? [lo, hi] : [-1, 1] });
  view.graphical = graphical;
  view.motion = own ? base.motion : null;
  if (base.input.time) {
    const c = sp.value / rate;
    Object.assign(view.input, { time: base.input.time.map((t) => t * c), period: base.input.period * c });
  }
  view.scales.force = own ? base.scales.force : base.scales.force * Math.max(1, largest(view) / largest(base));
  view.rate = rate;
}
