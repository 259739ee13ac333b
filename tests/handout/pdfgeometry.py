"""What a PDF page draws, measured on the page: every painted path in page coordinates, and the figures' captions.

A small interpreter of PDF content streams (ISO 32000-1 §8): it follows the graphics state (``q``/``Q``,
``cm``, line width, stroke and fill colours) through the page and the form XObjects it paints, and records each
painted path with its points in page coordinates [pt], so a test can measure lengths as printed — what a ruler
on the paper would find — and compare them with what the page states ("Scale 1:10", "1 mm = 20 N").
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np
import pypdf
from pypdf.generic import ContentStream

MM = 72 / 25.4
"""Points per millimetre."""



@dataclass
class Path:
    """One painted path: its subpaths (each a list of points [pt], page coordinates) and how it was painted."""

    subpaths: list
    stroke: tuple | None  # RGB in 0–1 when stroked
    fill: tuple | None  # RGB in 0–1 when filled
    width: float  # line width [pt] on the page
    closed: list = field(default_factory=list)  # per subpath: closed with h
    mitre: float = 10.0  # the mitre limit it was stroked with

    @property
    def points(self) -> np.ndarray:
        return np.vstack([np.asarray(s, float) for s in self.subpaths if len(s)]) if self.subpaths else np.zeros((0, 2))


def _mul(a, b):
    """The product of two PDF matrices [a b c d e f] (a first)."""
    return [a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2],
            a[2] * b[1] + a[3] * b[3], a[4] * b[0] + a[5] * b[2] + b[4], a[4] * b[1] + a[5] * b[3] + b[5]]


def _apply(m, x, y):
    return (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5])


def _colour(values):
    v = [float(x) for x in values if isinstance(x, (int, float)) or hasattr(x, "as_numeric")]
    if len(v) == 1:
        return (v[0], v[0], v[0])
    if len(v) == 3:
        return tuple(v)
    if len(v) == 4:  # CMYK, as RGB
        c, m, y, k = v
        return ((1 - c) * (1 - k), (1 - m) * (1 - k), (1 - y) * (1 - k))
    return None


def paths(reader: pypdf.PdfReader, page, parsed: dict | None = None) -> list[Path]:
    """Every path the page paints (stroked or filled), in page coordinates.

    ``parsed``: the operators of the form XObjects read so far, by object (kept between the pages of a document).
    """
    out: list[Path] = []
    _run(reader, page.get_contents(), page.get("/Resources") or {}, [1, 0, 0, 1, 0, 0], out,
         {} if parsed is None else parsed)
    return out


# One token of a content stream (ISO 32000-1 §7.2, §7.3): a number, a name, a delimiter, a hex string, or a
# regular run (an operator, true, false, null). A literal string is read by hand, as its parentheses may nest.
_TOKEN = re.compile(rb"""[\x00\t\n\x0c\r ]*(?:%[^\r\n]*[\x00\t\n\x0c\r ]*)*(?:
    (?P<number>[+-]?(?:\d+\.?\d*|\.\d+))(?![^\x00\t\n\x0c\r ()<>\[\]{}/%])
  | (?P<name>/[^\x00\t\n\x0c\r ()<>\[\]{}/%]*)
  | (?P<open><<|\[|\{)
  | (?P<close>>>|\]|\})
  | (?P<hex><[^>]*>)
  | (?P<string>\()
  | (?P<word>[^\x00\t\n\x0c\r ()<>\[\]{}/%]+)
  | (?P<end>\Z))""", re.VERBOSE)
_STRING = re.compile(rb"\\.|[()]", re.DOTALL)
_NAME_ESCAPE = re.compile(r"#([0-9A-Fa-f]{2})")


def _operations(data: bytes) -> list[tuple[list, str]] | None:
    """The (operands, operator) pairs of a content stream: numbers as floats, names as ``/Name`` strings, arrays
    and dictionaries as lists; strings are skipped over (their text is not drawing). ``None`` when the stream
    holds an inline image (``BI … ID … EI``), whose raw bytes only a full parser reads safely.

    Parsing the content streams of a long handout with :class:`pypdf.generic.ContentStream` takes seconds a page
    (every number an object); the paths need only numbers, names and operators, read here with one expression.
    """
    ops: list[tuple[list, str]] = []
    stack: list[list] = [[]]
    pos, match = 0, _TOKEN.match
    while True:
        m = match(data, pos)
        if m is None:
            raise ValueError(f"unreadable content stream at byte {pos}: {data[pos:pos + 20]!r}")
        pos, kind = m.end(), m.lastgroup
        if kind == "number":
            stack[-1].append(float(m["number"]))
        elif kind == "word":
            word = m["word"].decode("latin-1")
            if word in ("true", "false", "null"):
                stack[-1].append(word)
            elif word == "BI":
                return None
            else:
                ops.append((stack[-1], word))
                stack[-1] = []
        elif kind == "name":
            name = m["name"].decode("latin-1")
            stack[-1].append(_NAME_ESCAPE.sub(lambda e: chr(int(e[1], 16)), name) if "#" in name else name)
        elif kind == "open":
            stack.append([])
        elif kind == "close":
            inner = stack.pop() if len(stack) > 1 else []
            stack[-1].append(inner)
        elif kind == "hex":
            stack[-1].append(m["hex"])
        elif kind == "string":
            depth = 1
            while depth:
                s = _STRING.search(data, pos)
                if s is None:
                    raise ValueError("a content stream's string is not closed")
                pos = s.end()
                depth += {b"(": 1, b")": -1}.get(s[0], 0)
            stack[-1].append(b"")
        else:
            return ops



def _parsed(reader, contents, parsed: dict) -> list:
    """The operations of a content stream (:func:`_operations`, or pypdf's where it holds an inline image), a form
    XObject's parsed once: a form is painted again and again (a figure's marks, on every page of its figure), and
    parsing is most of the reading."""
    ref = getattr(contents, "indirect_reference", None)
    key = (ref.idnum, ref.generation) if ref is not None else None
    if key is not None and key in parsed:
        return parsed[key]
    operations = _operations(contents.get_data())
    if operations is None:
        operations = ContentStream(contents, reader).operations
    if key is not None:
        parsed[key] = operations
    return operations


def _run(reader, contents, resources, ctm, out, parsed):
    if contents is None:
        return
    state = {"ctm": list(ctm), "w": 1.0, "mitre": 10.0, "stroke": (0, 0, 0), "fill": (0, 0, 0)}
    stack = []
    subpaths, current, closed = [], [], []
    for operands, op in _parsed(reader, contents, parsed):
        op = op.decode() if isinstance(op, bytes) else op
        if op == "q":
            stack.append(dict(state, ctm=list(state["ctm"])))
        elif op == "Q":
            state = stack.pop() if stack else state
        elif op == "cm":
            state["ctm"] = _mul([float(x) for x in operands], state["ctm"])
        elif op == "w":
            state["w"] = float(operands[0])
        elif op == "M":
            state["mitre"] = float(operands[0])
        elif op in ("RG", "SC", "SCN", "G", "K"):
            state["stroke"] = _colour(operands) or state["stroke"]
        elif op in ("rg", "sc", "scn", "g", "k"):
            state["fill"] = _colour(operands) or state["fill"]
        elif op == "m":
            if current:
                subpaths.append(current)
                closed.append(False)
            current = [_apply(state["ctm"], float(operands[0]), float(operands[1]))]
        elif op == "l":
            current.append(_apply(state["ctm"], float(operands[0]), float(operands[1])))
        elif op in ("c", "v", "y"):
            # A Bézier curve: its end point, and its control points (enough for extents and ends).
            xs = [float(x) for x in operands]
            for k in range(0, len(xs), 2):
                current.append(_apply(state["ctm"], xs[k], xs[k + 1]))
        elif op == "h":
            if current:
                subpaths.append(current)
                closed.append(True)
                current = []
        elif op == "re":
            x, y, w, h = (float(v) for v in operands)
            if current:
                subpaths.append(current)
                closed.append(False)
            subpaths.append([_apply(state["ctm"], *p) for p in ((x, y), (x + w, y), (x + w, y + h), (x, y + h))])
            closed.append(True)
            current = []
        elif op in ("S", "s", "f", "F", "f*", "B", "B*", "b", "b*", "n"):
            if current:
                subpaths.append(current)
                closed.append(op in ("s", "b", "b*"))
                current = []
            if op != "n" and subpaths:
                m = state["ctm"]
                scale = float(np.sqrt(abs(m[0] * m[3] - m[1] * m[2])))
                stroked = op in ("S", "s", "B", "B*", "b", "b*")
                filled = op in ("f", "F", "f*", "B", "B*", "b", "b*")
                out.append(Path(subpaths, state["stroke"] if stroked else None, state["fill"] if filled else None,
                                state["w"] * scale, closed, state["mitre"]))
            subpaths, closed = [], []
        elif op == "Do":
            xobjects = resources.get("/XObject") or {}
            x = xobjects.get(operands[0])
            x = x.get_object() if x is not None else None
            if x is not None and x.get("/Subtype") == "/Form":
                matrix = [float(v) for v in x.get("/Matrix", [1, 0, 0, 1, 0, 0])]
                _run(reader, x, x.get("/Resources") or resources, _mul(matrix, state["ctm"]), out, parsed)


# -- the figures of a page -----------------------------------------------------------------------------------------
_SCALE = re.compile(r"[Ss]cale (\d+(?:\.\d+)?):(\d+(?:\.\d+)?)")
_FORCE = re.compile(r"1 mm = (\d+(?:\.\d+)?) N")


@dataclass
class Figure:
    """A figure of a page: its caption's number, the scales the caption states, and the paths drawn above it."""

    number: int
    caption: str
    k: float | None  # length scale 1:k (k < 1 for an enlargement)
    X: float | None  # force scale [N per mm]
    paths: list


def figures(path) -> list[Figure]:
    """Every figure of a PDF, with the scales its caption states and the paths drawn between it and the block
    above (a figure stands over its caption)."""
    reader = pypdf.PdfReader(path)
    out = []
    parsed: dict = {}
    for page in reader.pages:
        heads = []

        def visit(t, cm, tm, font, size, heads=heads):
            m = re.match(r"\s*Figure (\d+)\.", t)
            if m:
                heads.append((int(m[1]), tm[4] * cm[1] + tm[5] * cm[3] + cm[5]))

        # The page's text and, as it is read, where each figure's caption begins: the page read once (pypdf's
        # reading of a page's text is most of a figure's measuring).
        text = page.extract_text(visitor_text=visit)
        if not heads:
            continue
        drawn = paths(reader, page, parsed)
        heights = [(p, p.points[:, 1]) for p in drawn]  # each path's points gathered once, not once a figure
        top = float(page.mediabox.top)
        for n, y in sorted(heads, key=lambda h: -h[1]):
            start = text.find(f"Figure {n}. ")
            end = text.find("Figure ", start + 8)
            caption = " ".join(text[start:end if end > 0 else None].split())
            s, f = _SCALE.search(caption), _FORCE.search(caption)
            k = float(s[2]) / float(s[1]) if s else None
            X = float(f[1]) if f else None
            mine = [p for p, ys in heights if len(ys) and ys.min() > y and ys.max() < top]
            out.append(Figure(n, caption, k, X, mine))
            top = y
    return out


# -- what is drawn -------------------------------------------------------------------------------------------------
def arrows(fig: Figure, colours) -> list[float]:
    """The printed lengths [mm] of the straight force arrows of the given colours: from the shaft's start (the
    tail) to the head's point (the tip), for every shaft that meets a head of its colour."""
    def near(c, colour):
        return c is not None and max(abs(a - b) for a, b in zip(c, colour)) < 0.02

    shafts = [p for p in fig.paths if any(near(p.stroke, c) for c in colours) and p.fill is None
              and len(p.subpaths) == 1]
    heads = [p for p in fig.paths if len(p.subpaths) == 1 and p.closed and p.closed[0] and len(p.subpaths[0]) == 3
             and any(near(p.stroke, c) or near(p.fill, c) for c in colours)]
    out = []
    for sh in shafts:
        pts = np.asarray(sh.subpaths[0], float)
        tail, end = pts[0], pts[-1]
        span = np.linalg.norm(end - tail)
        # Straight: every point of the shaft on the segment (a couple's arc is not a force).
        u = (end - tail) / span if span else np.zeros(2)
        if span == 0 or np.max(np.abs((pts - tail) @ np.array([-u[1], u[0]]))) > 0.05:
            continue
        for hd in heads:
            tri = np.asarray(hd.subpaths[0], float)
            d = np.linalg.norm(tri - tail, axis=1)
            apex = tri[int(np.argmax(d))]
            base = np.delete(tri, int(np.argmax(d)), axis=0).mean(axis=0)
            # The shaft runs to the head's point (matplotlib's "-|>"), or to the head's base.
            meets = min(np.linalg.norm(apex - end), np.linalg.norm(base - end)) < 0.3
            if meets and (near(hd.stroke, sh.stroke) or near(hd.fill, sh.stroke)):
                # The ink reaches past the path's point by the stroke's mitre: what a ruler on the paper meets
                # (matplotlib draws the head back by as much, so that the ink's point is the force's tip).
                ext = 0.0
                if hd.stroke is not None:
                    others = np.delete(tri, int(np.argmax(d)), axis=0) - apex
                    cos = np.dot(others[0], others[1]) / np.prod(np.linalg.norm(others, axis=1))
                    half = np.arccos(np.clip(cos, -1, 1)) / 2
                    if 1 / np.sin(half) <= hd.mitre:
                        ext = hd.width / 2 / np.sin(half)
                out.append((float(np.linalg.norm(apex - tail)) + ext) / MM)
                break
    return out


def bars(fig: Figure, width: float, colour) -> list[float]:
    """Printed lengths [mm] of the straight lines ``width`` [pt] wide in ``colour``: the mechanism's links as bars."""
    out = []
    for p in fig.paths:
        if p.stroke is None or abs(p.width - width) > 0.05 or max(abs(a - b) for a, b in zip(p.stroke, colour)) > 0.02:
            continue
        for sub in p.subpaths:
            if len(sub) == 2:
                out.append(float(np.linalg.norm(np.subtract(sub[1], sub[0]))) / MM)
    return out


def text_across_rules(path) -> list[tuple[int, str, float]]:
    """Characters that cross a table's vertical rule: (page, character, x of the rule [pt]).

    A cell whose text is wider than its column runs over the rule into the next cell; read by pypdfium2's
    character boxes against the thin vertical lines the page strokes.
    """
    import pypdfium2 as pdfium

    reader, pdf = pypdf.PdfReader(path), pdfium.PdfDocument(path)
    out = []
    for k, page in enumerate(reader.pages):
        rules = []
        for p in paths(reader, page):
            if p.stroke is None or p.fill is not None or p.width > 1.0:
                continue
            for sub in p.subpaths:
                if len(sub) == 2 and abs(sub[0][0] - sub[1][0]) < 0.01 and abs(sub[0][1] - sub[1][1]) > 3:
                    rules.append((sub[0][0], min(sub[0][1], sub[1][1]), max(sub[0][1], sub[1][1])))
        text = pdf[k].get_textpage()
        for i in range(text.count_chars()):
            left, bottom, right, top = text.get_charbox(i)
            if right - left < 0.3:
                continue
            for x, y0, y1 in rules:
                if left + 0.2 < x < right - 0.2 and bottom < y1 and top > y0:
                    out.append((k, text.get_text_range(i, 1), round(x, 1)))
    return out
