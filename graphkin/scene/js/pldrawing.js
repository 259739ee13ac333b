// A PrairieLearn question page (`graphkin exercise export NAME --to prairielearn`): each drawn question's box,
// drawn by draw.js. In the question panel the box writes the drawing into the hidden input inside it, which
// PrairieLearn's form submits (the answer as data: docs/json.md, "Drawn answers"); in a submission panel it shows
// what was submitted with the grader's feedback drawn back on it (the elements at fault, the right construction
// where the teacher reveals answers). PrairieLearn grades on its server with graphkin's grader (server.py):
// nothing here decides a grade, and the task a graded page carries has no targets.
import { drawTask } from "./draw.js";

function parsed(text) {
  if (!text) return null;
  try {
    return JSON.parse(text);
  } catch (e) {
    return null; // what the box cannot read it does not show; the server reads the submission itself
  }
}

// Every box of the page not yet drawn: `data-task` (the task's JSON), `data-drawing` (a drawing to show again),
// `data-feedback` (the grader's feedback on it); a hidden input inside the box receives the drawing.
export function mountDrawings(doc = document) {
  const views = [];
  for (const box of doc.querySelectorAll(".graphkin-drawing:not([data-mounted])")) {
    box.dataset.mounted = "1";
    const task = parsed(box.dataset.task);
    if (!task) continue;
    const host = doc.createElement("div");
    box.appendChild(host);
    const view = drawTask(host, task);
    const saved = parsed(box.dataset.drawing);
    if (saved) view.load(saved);
    const input = box.querySelector('input[type="hidden"]');
    if (input) view.onChange((d) => { input.value = JSON.stringify(d); });
    const fb = parsed(box.dataset.feedback);
    if (fb) view.showFeedback(fb);
    box.graphkin = view; // for the browser's tests
    views.push(view);
  }
  return views;
}

mountDrawings();
