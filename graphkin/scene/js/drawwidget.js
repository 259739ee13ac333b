// The drawn answer in a notebook: the anywidget front end of `gk.draw_answer(...)` (graphkin/widgets/drawing.py).
// The kernel sends the task's JSON in `task`; every change of the drawing is sent back in `drawing` (JSON text, the
// answer as docs/json.md gives it); Check asks the kernel, which grades and answers in `feedback`. The answer line
// `question = '<json>'` is shown with a Copy button, for the answer cell the platforms' reader reads.
import { drawTask } from "./draw.js";

export default {
  render({ model, el }) {
    const root = document.createElement("div");
    el.replaceChildren(root);
    const task = JSON.parse(model.get("task"));
    const view = drawTask(root, task, {
      check: () => {
        model.set("asked", model.get("asked") + 1);
        model.save_changes();
      },
    });
    const saved = model.get("drawing");
    if (saved) view.load(JSON.parse(saved));
    const line = document.createElement("div");
    line.className = "gk-draw-controls";
    const text = document.createElement("code");
    text.className = "gk-answer-line";
    const copy = document.createElement("button");
    copy.type = "button";
    copy.textContent = "Copy answer line";
    copy.dataset.do = "copy";
    copy.title = "Copy the line to paste into your answer cell";
    line.append(copy, text);
    root.appendChild(line);
    const show = () => { text.textContent = model.get("line"); };
    copy.addEventListener("click", () => {
      if (navigator.clipboard) navigator.clipboard.writeText(model.get("line")).catch(() => {});
    });
    view.onChange((d) => {
      model.set("drawing", JSON.stringify(d));
      model.save_changes();
    });
    const feedback = () => {
      const fb = model.get("feedback");
      view.showFeedback(fb ? JSON.parse(fb) : null);
    };
    show();
    if (model.get("feedback") && saved) feedback();
    model.on("change:feedback", feedback);
    model.on("change:line", show);
    el.graphkin = view; // for the browser's tests
  },
};
