// Two small DOM helpers shared by graphkin's drawings (scene.js, the mechanism over its cycle; draw.js, a student's
// drawn answer). No mechanics. (page.py joins this module first into each drawing's one ES module.)

const SVG = "http://www.w3.org/2000/svg";

// An SVG element `tag` with the attributes `attrs`, appended to `parent` when given.
export function el(tag, attrs, parent) {
  const node = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

// An HTML element `tag` with the attributes `attrs` and the text `text`, appended to `parent` when given.
export function html(tag, attrs, parent, text) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  if (parent) parent.appendChild(node);
  return node;
}
