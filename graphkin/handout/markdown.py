"""The handout as Markdown for notebooks: LaTeX mathematics (``$…$``), figures as SVG files beside it.

The figures are files in a folder named after the document
(``handout.md`` → ``handout_figures/step-3.svg``), linked by relative path:
Jupyter, VS Code and GitHub show them, the text stays small and readable
in a diff, and a figure can be reused on its own. (Inline ``data:`` URIs
would keep one file, but GitHub does not show them and they bury the text.)
"""

from __future__ import annotations

import re

from graphkin.handout import maths as M

_ESCAPE = re.compile(r"([\\`*_\[\]<>$|])")


def _text(s: str) -> str:
    return _ESCAPE.sub(r"\\\1", s)


def _inline(runs) -> str:
    return "".join("<br>" if r == "\n" else _text(r) if isinstance(r, str) else f"${M.to_latex(r)}$" for r in runs)


def _block(b: dict, folder: str, files: dict) -> str:
    kind = b["kind"]
    if kind == "heading":
        return "#" * (b["level"] + 1) + " " + _text(b["text"])
    if kind == "text":
        return _inline(b["runs"])
    if kind == "list":
        return "\n".join((f"{k}. " if b["ordered"] else "- ") + _inline(item) for k, item in enumerate(b["items"], 1))
    if kind == "table":
        sep = {"l": ":--", "c": ":-:", "r": "--:"}
        lines = ["| " + " | ".join(_inline(h) for h in b["header"]) + " |",
                 "|" + "|".join(sep[a] for a in b["align"]) + "|"]
        lines += ["| " + " | ".join(_inline(c) for c in row) + " |" for row in b["rows"]]
        if b.get("caption"):
            lines += ["", f"*{_text(b['caption'])}*"]
        return "\n".join(lines)
    if kind == "equation":
        return "\n\n".join(f"$$\n{M.to_latex(line)}\n$$" for line in b["lines"])
    if kind == "figure":
        images = []
        for p in b["pictures"]:
            path = f"{folder}/{p.key}.svg"
            files[path] = p.svg().encode("utf-8")
            images.append(f"![{_text(p.alt)}]({path})")
        return " ".join(images) + f"\n\n*{_inline(b['runs'])}*"
    if kind == "space":
        extra = f" ${M.to_latex(b['math'])}$" if b.get("math") else ""
        return f"> **Draw here** ({b['height']:g} mm): {_text(b['label'])}{extra}\n>\n> &nbsp;"
    if kind == "pagebreak":
        return "---"
    if kind == "flush":
        return ""  # figures do not float here
    raise ValueError(f"unknown block {kind!r}")


def render(doc: dict, folder: str = "figures") -> tuple[str, dict[str, bytes]]:
    """The handout as Markdown, and its figure files.

    Parameters
    ----------
    doc : dict
        From :func:`graphkin.handout.content.build`.
    folder : str
        Where the figures go, relative to the Markdown file.

    Returns
    -------
    text : str
    files : dict of str to bytes
        Each figure's relative path (as linked in the text) and its SVG.
    """
    files: dict[str, bytes] = {}
    parts = [f"# {_text(doc['title'])}", f"**{_text(doc['subtitle'])}**"]
    if doc["source"]:
        parts.append(f"*{_text(doc['source'])}*")
    parts += [_block(b, folder, files) for b in doc["blocks"]]
    return "\n\n".join(parts) + "\n", files
