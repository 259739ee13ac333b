// graphkin's scene in a notebook: the anywidget front end of `gk.explore(problem, browser=True)`
// (graphkin/widgets/browser.py). The kernel sends the scene's JSON in the widget's `scene` trait and the browser
// draws every position of it; the kernel is asked again only for a new scene (a length, a mass, a load changed),
// which is drawn anew. Setting `index` from Python shows that position. Keys are the widget's own (it takes focus
// when clicked), so arrow keys typed in a cell stay the cell's.
import { draw } from "./scene.js";

export default {
  render({ model, el }) {
    let view = null;
    function redraw() {
      if (view) view.pause();
      const root = document.createElement("div");
      root.tabIndex = 0;
      el.replaceChildren(root);
      view = draw(root, JSON.parse(model.get("scene")), { keys: root });
      view.show(model.get("index"));
      el.graphkin = view; // for the browser's tests, as the page's window.graphkin.view
    }
    redraw();
    model.on("change:scene", redraw);
    model.on("change:index", () => view.show(model.get("index")));
    return () => view.pause();
  },
};
