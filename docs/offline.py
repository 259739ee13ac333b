"""The site asks no other host for anything: the lessons' widgets drawn without a CDN, the README's images local.

A notebook's ipywidgets output is only a reference to a model in the notebook's widget state; a page shows it by
loading require.js and the ipywidgets HTML manager from two CDNs, and even online the result is a frozen copy
with no kernel behind it. Offline it is a blank box. So this extension, as each page is read:

* replaces an explorer (``gk.explore(p)``, with ``p`` a catalog problem the lesson loaded) by the page
  ``graphkin explore NAME -o page.html`` writes (:mod:`graphkin.scene`), in an ``<iframe>``: every position of the
  cycle drawn by the browser, with no kernel and no network (the pages are built by docs/lesson_cache.py);
* draws any other widget statically from its saved state (:func:`static_widget`): the HTML it shows, its image,
  its controls as they were left, disabled, under a line saying that they work in the notebook;
* leaves the widget state and the CDN scripts out of the page (``nb_ipywidgets_js = {}`` in conf.py);
* points the README's links and images at GitHub pages that are on the site to the site's own copies.

:func:`external_references` finds what a page or a style sheet would fetch from another host: tests/docs/ checks
every page of the built site with it.
"""

from __future__ import annotations

import ast
import html
import json
import posixpath
import re
from html.parser import HTMLParser
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

SCENES = "_scenes"
"""The folder of the built site that holds the explorers' pages (``_scenes/NAME.html``)."""

WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"

REPOSITORY = re.compile(r"^https://(?:github\.com/graphkin/graphkin/(?:blob|raw)/main|"
                        r"raw\.githubusercontent\.com/graphkin/graphkin/main)/([^?#]+)(#.*)?$")
"""A file of this repository on GitHub, as the README names it (so that it reads well on GitHub and PyPI)."""


# -- which problem an explorer explores ----------------------------------------------------------------------------

def _calls(tree, name: str):
    """The calls in ``tree`` of a function or method named ``name`` (``explore(…)``, ``gk.explore(…)``)."""
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            f = node.func
            if (isinstance(f, ast.Name) and f.id == name) or (isinstance(f, ast.Attribute) and f.attr == name):
                yield node


def _loaded(value) -> str | None:
    """The catalog name in ``gk.load("NAME")`` (or ``load``, ``catalog.load``), else None."""
    if isinstance(value, ast.Call) and next(_calls(value, "load"), None) is value and len(value.args) == 1 \
            and isinstance(value.args[0], ast.Constant) and isinstance(value.args[0].value, str):
        return value.args[0].value
    return None


def _parse(source: str):
    # A notebook cell may hold IPython's magics and shell escapes: they assign nothing this needs.
    lines = ["" if line.lstrip().startswith(("%", "!")) else line for line in source.splitlines()]
    try:
        return ast.parse("\n".join(lines))
    except SyntaxError:
        return None


def explored_problem(sources: list[str], index: int) -> str | None:
    """The catalog problem that code cell ``index`` explores, if the code says so plainly, else None.

    The cell calls ``explore(p)`` (or ``gk.explore(p)``) on a name ``p`` whose last assignment, in this cell or
    an earlier one, is ``gk.load("NAME")``; or on ``gk.load("NAME")`` itself. A problem made any other way
    (changed, read from text) is not a catalog problem: None, and the widget is drawn from its saved state.

    Parameters
    ----------
    sources : list of str
        The notebook's code cells, in order.
    index : int
        The cell that shows the explorer.

    Returns
    -------
    str or None

    Examples
    --------
    >>> explored_problem(['p = gk.load("strip_cutter")', "ex = gk.explore(p)\\nex"], 1)
    'strip_cutter'
    >>> explored_problem(['p = gk.load("strip_cutter")', "p = p.with_friction(0.1)", "gk.explore(p)"], 2) is None
    True
    """
    tree = _parse(sources[index])
    call = next(_calls(tree, "explore"), None) if tree else None
    if call is None or not call.args:
        return None
    arg = call.args[0]
    if not isinstance(arg, ast.Name):
        return _loaded(arg)
    last = None
    for source in sources[:index + 1]:
        cell = _parse(source)
        for node in ast.walk(cell) if cell else ():
            if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == arg.id for t in node.targets):
                last = node.value
    return _loaded(last)


def explored_problems(path: Path) -> set[str]:
    """Every catalog problem a notebook's cells explore (:func:`explored_problem`): the scene pages it needs."""
    sources, _ = _code_sources(path)
    return {name for i in range(len(sources)) if (name := explored_problem(sources, i))}


# -- a widget drawn from its saved state ---------------------------------------------------------------------------

NOTE = ("A still copy of an interactive widget: the controls work when the notebook runs "
        "(JupyterLab, or <code>graphkin lessons DIR</code> for a copy of the lessons).")


def _attrs(**kv) -> str:
    """HTML attributes: ``True`` is a bare attribute (``disabled``), ``None`` and ``False`` none."""
    return "".join(f' {k}' if v is True else f' {k}="{html.escape(str(v), quote=True)}"'
                   for k, v in kv.items() if v is not None and v is not False)


def _label(state: dict) -> str:
    text = state.get("description") or ""
    return f"<span class=\"gk-label\">{html.escape(text)}</span> " if text else ""


def _image(model: dict) -> str:
    state = model["state"]
    data = next((b["data"] for b in model.get("buffers", ()) if b.get("path") == ["value"]), None)
    if data is None:
        value = state.get("value")
        data = value if isinstance(value, str) else None
    if not data:
        return ""
    fmt = state.get("format") or "png"
    kind = "svg+xml" if fmt == "svg" else fmt
    attrs = _attrs(src=f"data:image/{kind};base64,{data}", alt=state.get("tooltip") or "", width=state.get("width") or None)
    return f"<img{attrs}>"


def _output(outputs: list) -> str:
    out = []
    for o in outputs:
        data = o.get("data", {}) if o.get("output_type") != "stream" else {"text/plain": o.get("text", "")}
        if "text/html" in data:
            out.append("".join(data["text/html"]) if isinstance(data["text/html"], list) else data["text/html"])
        elif "image/png" in data:
            out.append(f'<img src="data:image/png;base64,{data["image/png"]}" alt="">')
        elif "text/plain" in data:
            text = "".join(data["text/plain"]) if isinstance(data["text/plain"], list) else data["text/plain"]
            out.append(f"<pre>{html.escape(text)}</pre>")
    return "".join(out)


def _widget(models: dict, ref: str) -> str:
    model = models.get(ref.removeprefix("IPY_MODEL_"))
    if model is None:
        return ""
    name, state = model["model_name"], model["state"]
    if name in ("VBoxModel", "HBoxModel", "BoxModel", "GridBoxModel", "AccordionModel", "TabModel", "StackModel"):
        inner = "".join(_widget(models, child) for child in state.get("children", ()))
        return f'<div class="gk-{"hbox" if name == "HBoxModel" else "vbox"}">{inner}</div>'
    if name in ("HTMLModel", "HTMLMathModel"):
        return f'<div class="gk-html">{state.get("value", "")}</div>' if state.get("value") else ""
    if name == "LabelModel":
        return f'<span class="gk-text">{html.escape(state.get("value", ""))}</span>'
    if name == "ImageModel":
        return _image(model)
    if name.endswith("SliderModel") and "value" in state and not isinstance(state["value"], list):
        rng = _attrs(type="range", min=state.get("min"), max=state.get("max"), step=state.get("step"),
                     value=state["value"], disabled=True)
        return f"<label class=\"gk-control\">{_label(state)}<input{rng}> <output>{html.escape(str(state['value']))}" \
               "</output></label>"
    if name.endswith(("TextModel", "TextareaModel")):
        box = _attrs(type="text", value=state.get("value", ""), placeholder=state.get("placeholder") or None,
                     disabled=True)
        return f"<label class=\"gk-control\">{_label(state)}<input{box}></label>"
    if name == "CheckboxModel":
        return f"<label class=\"gk-control\"><input{_attrs(type='checkbox', checked=bool(state.get('value')), disabled=True)}> " \
               f"{html.escape(state.get('description', ''))}</label>"
    if name in ("ButtonModel", "ToggleButtonModel"):
        return f"<button disabled>{html.escape(state.get('description', ''))}</button>"
    if name in ("DropdownModel", "SelectModel", "RadioButtonsModel", "ToggleButtonsModel"):
        labels, i = state.get("_options_labels", []), state.get("index")
        shown = labels[i] if isinstance(i, int) and 0 <= i < len(labels) else ""
        return f"<label class=\"gk-control\">{_label(state)}<select disabled><option>{html.escape(shown)}</option>" \
               "</select></label>"
    if name == "OutputModel":
        return _output(state.get("outputs", []))
    return ""  # a widget with no look of its own (a layout, a style, a probe of the screen)


def static_widget(state: dict, model_id: str) -> str:
    """The widget ``model_id`` as plain HTML, from the notebook's saved widget state: what it showed, disabled.

    Parameters
    ----------
    state : dict
        The notebook's ``application/vnd.jupyter.widget-state+json`` ``state`` (model id → model).
    model_id : str
        The model an output shows (its ``application/vnd.jupyter.widget-view+json``).

    Returns
    -------
    str
        A ``<div class="graphkin-static-widget">``: the widget's HTML, images and controls, then :data:`NOTE`;
        a widget that saved nothing to show says so, rather than leaving a blank box.

    Examples
    --------
    >>> models = {"a": {"model_name": "VBoxModel", "state": {"children": ["IPY_MODEL_b", "IPY_MODEL_c"]}},
    ...           "b": {"model_name": "HTMLModel", "state": {"value": "<h4>Flywheel</h4>"}},
    ...           "c": {"model_name": "ButtonModel", "state": {"description": "Check"}}}
    >>> print(static_widget(models, "a").replace("><", ">\\n<"))  # doctest: +ELLIPSIS
    <div class="graphkin-static-widget">
    <div class="gk-vbox">
    <div class="gk-html">
    <h4>Flywheel</h4>
    </div>
    <button disabled>Check</button>
    </div>
    <p class="gk-note">A still copy...</p>
    </div>
    """
    body = _widget(state, model_id)
    if not re.sub(r"<[^>]*>", "", body).strip() and "<img" not in body and "<input" not in body:
        body = "<p>(an interactive widget that saved nothing to show: run the notebook to see it)</p>"
    return f'<div class="graphkin-static-widget">{body}<p class="gk-note">{NOTE}</p></div>'


def scene_frame(name: str, docname: str) -> str:
    """The ``<iframe>`` that shows problem ``name``'s scene page in page ``docname``, with a line on what it is."""
    src = posixpath.relpath(f"{SCENES}/{name}.html", posixpath.dirname(docname) or ".")
    return (f'<div class="graphkin-scene"><iframe src="{html.escape(src)}" title="{html.escape(name)}: every position '
            f'of the cycle" loading="lazy"></iframe><p class="gk-note">On this page your browser draws the cycle, '
            f'solved once when the site was built (<code>graphkin explore {html.escape(name)} --motion -o page.html</code> '
            f'writes this page; <a href="{html.escape(src)}">open it whole</a>). In the notebook, the explorer is '
            f'this drawing, and Python answers a new length, mass or load with a new scene.</p></div>')


# -- what a page would fetch from another host ---------------------------------------------------------------------

_FOREIGN = re.compile(r"^\s*(?:[a-z][a-z0-9+.-]*:)?//", re.I)
_CSS_URL = re.compile(r"""url\(\s*(['"]?)([^'")]*)\1\s*\)|@import\s+(['"])([^'"]+)\3""", re.I)


def foreign(url: str) -> bool:
    """Whether a page asking for ``url`` asks another host: ``https://…``, ``//host/…`` (a ``data:`` URL, a
    relative or a site-absolute path does not)."""
    return bool(_FOREIGN.match(url))


def css_references(text: str) -> list[str]:
    """Every ``url(…)`` and ``@import`` of a style sheet (or a ``style`` attribute), in order."""
    return [m.group(2) if m.group(2) is not None else m.group(4) for m in _CSS_URL.finditer(text)]


class _Fetches(HTMLParser):
    """The URLs a browser fetches to show a page: scripts, style sheets, fonts, images, frames, media."""

    ATTRS = {"script": ("src",), "img": ("src", "srcset"), "iframe": ("src",), "frame": ("src",),
             "embed": ("src",), "object": ("data",), "source": ("src", "srcset"), "video": ("src", "poster"),
             "audio": ("src",), "track": ("src",), "input": ("src",), "image": ("href", "xlink:href"),
             "use": ("href", "xlink:href")}
    LINKS = {"stylesheet", "icon", "preload", "prefetch", "modulepreload", "preconnect", "dns-prefetch",
             "manifest", "apple-touch-icon", "mask-icon", "shortcut"}

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.found: list[tuple[str, str]] = []
        self._style = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for name in self.ATTRS.get(tag, ()):
            # a srcset is "URL WIDTH, URL WIDTH"; any other attribute one URL (a data: URL holds commas)
            urls = [u.split()[0] for u in re.split(r",\s+", a.get(name) or "") if u.strip()] if name == "srcset" \
                else [a[name].strip()] if (a.get(name) or "").strip() else []
            self.found += [(f"<{tag} {name}>", url) for url in urls]
        if tag == "link" and self.LINKS & set((a.get("rel") or "").lower().split()) and a.get("href"):
            self.found.append((f"<link rel={a.get('rel')}>", a["href"]))
        if a.get("style"):
            self.found += [(f"<{tag} style>", url) for url in css_references(a["style"])]
        self._style = tag == "style"

    def handle_endtag(self, tag):
        self._style = False

    def handle_data(self, data):
        if self._style:
            self.found += [("<style>", url) for url in css_references(data)]


def fetched(page: str) -> list[tuple[str, str]]:
    """(what, URL) for everything an HTML page fetches to be shown (see :class:`_Fetches`)."""
    parser = _Fetches()
    parser.feed(page)
    parser.close()
    return parser.found


def external_references(text: str, css: bool = False) -> list[tuple[str, str]]:
    """What an HTML page (or, with ``css``, a style sheet) fetches from another host: (what, URL) pairs.

    Examples
    --------
    >>> external_references('<script src="https://cdn.jsdelivr.net/x.js"></script><img src="_images/a.png">')
    [('<script src>', 'https://cdn.jsdelivr.net/x.js')]
    >>> external_references("@import url(//fonts.example.com/a.css); b { background: url(data:image/png;base64,AA) }",
    ...                     css=True)
    [('css', '//fonts.example.com/a.css')]
    """
    found = [("css", url) for url in css_references(text)] if css else fetched(text)
    return [(what, url) for what, url in found if foreign(url)]


# -- Sphinx --------------------------------------------------------------------------------------------------------

def _code_sources(path: Path) -> tuple[list[str], dict[int, int]]:
    """A notebook's code cells' sources, and each cell's index among them by its index in the notebook."""
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    sources, position = [], {}
    for i, cell in enumerate(cells):
        if cell["cell_type"] == "code":
            position[i] = len(sources)
            source = cell["source"]
            sources.append("".join(source) if isinstance(source, list) else source)
    return sources, position


def is_explorer(models: dict, ref: str) -> bool:
    """Whether the widget is an explorer's (:func:`graphkin.widgets.explore`): an anywidget whose state holds a scene.

    Examples
    --------
    >>> is_explorer({"w": {"model_name": "AnyModel", "state": {"_esm": "...", "scene": "{}", "index": 0}}}, "IPY_MODEL_w")
    True
    >>> is_explorer({"w": {"model_name": "AnyModel", "state": {"_esm": "..."}}}, "w")
    False
    """
    model = models.get(ref.removeprefix("IPY_MODEL_"))
    if model is None:
        return False
    state = model["state"]
    return ("_esm" in state and "scene" in state) or any(is_explorer(models, c) for c in state.get("children", ()))


def replace_widgets(app, doctree) -> None:
    """``doctree-read``: each widget output of a notebook drawn without a CDN, and the widget state dropped."""
    from docutils import nodes

    env = app.env
    docname = env.docname
    meta = getattr(env, "nb_metadata", {}).get(docname, {})
    js = meta.get("js_files", {})
    saved = js.pop("ipywidgets_state", None)  # the state is put in the page below, as HTML, not as a script
    views = [n for n in doctree.findall(nodes.container) if n.get("mime_type") == WIDGET_VIEW]
    if not views:
        return
    models = json.loads(saved[1]["body"])["state"] if saved else {}
    sources, position = _code_sources(Path(env.doc2path(docname)))
    for view in views:
        raw = next(iter(view.findall(nodes.raw)))
        model_id = json.loads(re.sub(r"^<script[^>]*>|</script>$", "", raw.astext()).replace("<\\/", "</"))["model_id"]
        cell = view
        while cell is not None and cell.get("nb_element") != "cell_code":
            cell = cell.parent
        problem = None
        if cell is not None and is_explorer(models, model_id):
            problem = explored_problem(sources, position[cell["cell_index"]])
        text = scene_frame(problem, docname) if problem else static_widget(models, model_id)
        raw.replace_self(nodes.raw("", text, format="html"))


def local_repository_links(app, doctree) -> None:
    """``doctree-read``: a README link to a page of this site, or image of this repository, made local.

    Runs before Sphinx collects the images, so that the image is copied into the site like any other.
    """
    from docutils import nodes

    env = app.env
    here = posixpath.dirname(env.docname)
    for node in doctree.findall(nodes.image):
        m = REPOSITORY.match(node.get("uri", ""))
        if m and (ROOT / m.group(1)).is_file():
            node["uri"] = "/" + m.group(1)  # relative to the source folder: the repository
    for node in doctree.findall(nodes.reference):
        m = REPOSITORY.match(node.get("refuri", ""))
        if not m:
            continue
        path, anchor = m.group(1), m.group(2) or ""
        docname = path.rsplit(".", 1)[0]
        if docname in env.found_docs:
            node["refuri"] = posixpath.relpath(docname, here or ".") + app.builder.out_suffix + anchor


def setup(app):
    app.connect("doctree-read", local_repository_links, priority=100)  # before the image collector (500)
    app.connect("doctree-read", replace_widgets)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
