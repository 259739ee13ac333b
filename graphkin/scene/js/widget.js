// graphkin's scene in a notebook: the anywidget front end of `gk.explore(problem)` (graphkin/widgets/browser.py).
// The kernel sends the scene's JSON in the widget's `scene` trait and the browser draws every position of it; the
// kernel is asked again only for a new scene (a length, a mass, a load changed), which is drawn anew. Setting
// `index` from Python shows that position. Keys are the widget's own (it takes focus when clicked), so arrow keys
// typed in a cell stay the cell's.
import { draw } from "./scene.js";

// What the student chose on the drawing: kept when a new scene comes, so changing a mass from Python does not undo
// the toggles, the units or the position the student dragged to.
function chosen(root, view) {
  const toggles = {};
  for (const box of root.querySelectorAll("[data-toggle]")) toggles[box.dataset.toggle] = box.checked;
  const units = root.querySelector('[data-do="units"]');
  return { index: view.index, n: view.scene.n, toggles, units: units ? units.value : null };
}

// The choices put back through the controls themselves (their own "change" handlers), so the page draws them as
// a student's click would.
function restore(root, kept) {
  for (const box of root.querySelectorAll("[data-toggle]")) {
    const was = kept.toggles[box.dataset.toggle];
    if (was !== undefined && was !== box.checked) {
      box.checked = was;
      box.dispatchEvent(new Event("change"));
    }
  }
  const units = root.querySelector('[data-do="units"]');
  if (units && kept.units !== null && units.value !== kept.units
      && [...units.options].some((o) => o.value === kept.units)) {
    units.value = kept.units;
    units.dispatchEvent(new Event("change"));
  }
}

export default {
  render({ model, el }) {
    let view = null;
    let root = null;
    let index = model.get("index"); // the position last set from Python
    function redraw() {
      const kept = view ? chosen(root, view) : null;
      if (view) view.pause();
      root = document.createElement("div");
      root.tabIndex = 0;
      el.replaceChildren(root);
      const scene = JSON.parse(model.get("scene"));
      view = draw(root, scene, { keys: root });
      if (kept) restore(root, kept);
      // The student's position stays when the new scene has the same positions and Python set no other one.
      const same = kept && kept.n === scene.n && model.get("index") === index;
      index = model.get("index");
      view.show(same ? kept.index : index);
      el.graphkin = view; // for the browser's tests, as the page's window.graphkin.view
    }
    redraw();
    model.on("change:scene", redraw);
    model.on("change:index", () => {
      index = model.get("index");
      view.show(index);
    });
    return () => view.pause();
  },
};
