"""The layout holds: layers, no import circles, no private names across packages, small modules, a leaf CLI.

The contract itself is in ``pyproject.toml`` ([tool.importlinter]) and
explained in ``docs/architecture.md``; these tests run it and the checks
import-linter has no contract for.
"""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from pathlib import Path

import grimp
import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "graphkin"
HEAVY = ("matplotlib", "ipywidgets", "IPython", "pint", "typst", "PIL", "nbformat", "tqdm", "orjson")
"""Third-party packages that cost an import or need a screen, a notebook or a compiler: loaded only where used."""


def _modules():
    """Every module of the package: (dotted name, path, whether it is a package's __init__)."""
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        init = parts[-1] == "__init__"
        yield ".".join(parts[:-1] if init else parts), path, init


MODULES = {name: (path, init) for name, path, init in _modules()}


def _package_of(module: str) -> str:
    """The package a module belongs to (a package's __init__ belongs to the package itself)."""
    return module if MODULES[module][1] else module.rsplit(".", 1)[0]


def test_the_layers_contract_is_kept():
    """import-linter's contract (pyproject.toml): every module imports only from layers below its own."""
    r = subprocess.run([str(Path(sys.executable).with_name("lint-imports")), "--no-cache"], cwd=ROOT,
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "0 broken" in r.stdout and "ignore" not in Path(ROOT / "pyproject.toml").read_text().split(
        "[tool.importlinter]")[1].split("\n[tool.")[0]


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one node (Tarjan): each is an import circle."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(max(sys.getrecursionlimit(), 10_000))
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_no_import_circles_in_the_package():
    """Module by module, imports inside functions included (grimp counts them)."""
    g = grimp.build_graph("graphkin", cache_dir=None, exclude_type_checking_imports=True)
    graph = {m: set(g.find_modules_directly_imported_by(m)) for m in g.modules}
    assert _cycles(graph) == []


def _imported(tree: ast.AST, here: str) -> set[str]:
    """The names of local modules an AST imports (``import x``, ``from x import y``)."""
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            out |= {node.module} | {f"{node.module}.{a.name}" for a in node.names}
    return out


@pytest.mark.parametrize("folder", ["benchmarks", "figures"])
def test_no_import_circles_among_the_scripts(folder):
    scripts = {p.stem: p for p in (ROOT / folder).glob("*.py")}
    graph = {name: {m for m in _imported(ast.parse(p.read_text()), name) if m in scripts} for name, p in scripts.items()}
    assert _cycles(graph) == []


def _private(module: str) -> bool:
    """Whether a dotted module name has a private part (``graphkin.cycle._sampling``)."""
    return any(part.startswith("_") and not part.startswith("__") for part in module.split("."))


SCRIPTS = sorted(p for folder in ("benchmarks", "figures") for p in (ROOT / folder).glob("*.py"))


def test_no_module_imports_another_packages_private_name():
    """``from graphkin.x import _y``, ``x._y``, or a private module ``graphkin.x._y`` across packages: a private
    name is its own package's. The scripts of benchmarks/ and figures/ are outside every package: they use the
    public names only."""
    found = []
    for name, (path, init) in [*MODULES.items(), *((f"scripts.{p.stem}", (p, False)) for p in SCRIPTS)]:
        tree = ast.parse(path.read_text())
        here = _package_of(name) if name in MODULES else "scripts"
        aliases = {}
        for node in ast.walk(tree):
            modules = ([node.module] if isinstance(node, ast.ImportFrom) and node.module and not node.level else
                       [a.name for a in node.names] if isinstance(node, ast.Import) else [])
            for module in modules:
                if module.startswith("graphkin") and _private(module) and (
                        module not in MODULES or _package_of(module) != here):
                    found.append(f"{path.relative_to(ROOT)}:{node.lineno}: imports {module}")
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("graphkin"):
                for a in node.names:
                    full = f"{node.module}.{a.name}"
                    if full in MODULES:
                        aliases[a.asname or a.name] = full
                    elif a.name.startswith("_") and not a.name.startswith("__") and (
                            node.module not in MODULES or _package_of(node.module) != here):
                        found.append(f"{path.relative_to(ROOT)}:{node.lineno}: from {node.module} import {a.name}")
            elif isinstance(node, ast.Import):
                aliases.update({a.asname: a.name for a in node.names if a.asname and a.name in MODULES})
        for node in ast.walk(tree):
            if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in aliases
                    and node.attr.startswith("_") and not node.attr.startswith("__")
                    and _package_of(aliases[node.value.id]) != here):
                found.append(f"{path.relative_to(ROOT)}:{node.lineno}: {node.value.id}.{node.attr}")
    assert found == []


def _function_level_imports(tree: ast.AST):
    for fn in ast.walk(tree):
        if isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
            for node in ast.walk(fn):
                if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("graphkin"):
                    yield node.lineno, [f"{node.module}.{a.name}" for a in node.names]
                elif isinstance(node, ast.Import):
                    names = [a.name for a in node.names if a.name.startswith("graphkin")]
                    if names:
                        yield node.lineno, names


def test_graphkin_modules_are_imported_at_the_top():
    """Inside a function only where it saves a heavy import: the drawing layer (matplotlib), and the
    command line, which imports what a command runs when it runs (start-up time)."""
    found = []
    for name, (path, _) in MODULES.items():
        if name.startswith("graphkin.cli"):
            continue
        for line, targets in _function_level_imports(ast.parse(path.read_text())):
            if not all(t == "graphkin.draw" or t.startswith("graphkin.draw.") for t in targets):
                found.append(f"{path.relative_to(ROOT)}:{line}: {', '.join(targets)}")
    assert found == []


def test_the_drawing_layer_is_heavy_and_the_rest_is_not():
    """Why graphkin.draw may be imported inside functions: importing it loads matplotlib; nothing else does."""
    code = ("import importlib, sys\n"
            f"heavy = {HEAVY!r}\n"
            "names = sys.argv[1:]\n"
            "for name in names:\n"
            "    before = {m for m in sys.modules if m.split('.')[0] in heavy}\n"
            "    importlib.import_module(name)\n"
            "    new = sorted({m.split('.')[0] for m in sys.modules if m.split('.')[0] in heavy} - "
            "{m.split('.')[0] for m in before})\n"
            "    print(name, *new)\n")
    light = [m for m in MODULES if not m.startswith(("graphkin.draw", "graphkin.__main__"))]
    r = subprocess.run([sys.executable, "-c", code, *light], capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert r.returncode == 0, r.stderr
    assert [line for line in r.stdout.splitlines() if len(line.split()) > 1] == []
    r = subprocess.run([sys.executable, "-c", "import sys, graphkin.draw; print('matplotlib' in sys.modules)"],
                       capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.stdout.strip() == "True", r.stderr


def test_nothing_imports_the_command_line():
    """The command line is a leaf: only ``python -m graphkin`` (graphkin/__main__.py) starts it."""
    found = []
    for name, (path, _) in MODULES.items():
        if name.startswith("graphkin.cli") or name == "graphkin.__main__":
            continue
        for target in _imported(ast.parse(path.read_text()), name):
            if target == "graphkin.cli" or target.startswith("graphkin.cli."):
                found.append(f"{path.relative_to(ROOT)}: {target}")
    assert found == []


def _long_modules_named_in_the_docs() -> set[str]:
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    section = text.split("## Modules over 600 lines", 1)[1].split("\n## ", 1)[0]
    return set(re.findall(r"`(graphkin/[\w/]+\.py)`", section))


def test_no_module_is_over_600_lines_unless_docs_architecture_names_it():
    long = {str(path.relative_to(ROOT)) for path, _ in MODULES.values() if len(path.read_text().splitlines()) > 600}
    named = _long_modules_named_in_the_docs()
    assert long <= named, f"over 600 lines and not named in docs/architecture.md: {sorted(long - named)}"
    assert named <= {str(p.relative_to(ROOT)) for p, _ in MODULES.values()}, "docs/architecture.md names a module " \
        "that is not there"


def _unguarded_writes(tree: ast.AST) -> list[int]:
    """Lines that save a file (``.save(…)``, ``.savefig(…)``, ``.write_bytes(…)``, ``.write_text(…)``) outside a
    ``with replacing(…)`` block: a write a person could find half done."""
    guarded = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.With) and any(
                isinstance(item.context_expr, ast.Call) and getattr(item.context_expr.func, "id",
                                                                    getattr(item.context_expr.func, "attr", "")) ==
                "replacing" for item in node.items):
            guarded |= {id(n) for n in ast.walk(node)}
    return [node.lineno for node in ast.walk(tree)
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            and node.func.attr in ("save", "savefig", "write_bytes", "write_text") and id(node) not in guarded]


def test_the_handout_figures_are_written_whole():
    """figures/handouts/build.py writes its page images through graphkin.files.replacing, as graphkin writes."""
    path = ROOT / "figures" / "handouts" / "build.py"
    assert _unguarded_writes(ast.parse(path.read_text())) == []
    assert _unguarded_writes(ast.parse("from PIL import Image\nImage.new('L', (1, 1)).save('x.png')\n")) == [2]


def test_every_module_is_named_on_the_architecture_page():
    """A newcomer finds every module on docs/architecture.md: in its package's row of "What each package holds"
    (by its name, or its path below the package), or by its path among the long modules."""
    doc = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    rows = {}
    for line in doc.splitlines():
        m = re.match(r"\| `([a-z_]+)/?`(?:, `([a-z_]+)`)? \|", line)
        if m:
            rows.update(dict.fromkeys(filter(None, m.groups()), line))
    unnamed = []
    for name, (path, init) in MODULES.items():
        parts = name.split(".")[1:]
        if init or parts == ["__main__"] or f"`{path.relative_to(ROOT).as_posix()}`" in doc:
            continue
        row = rows.get(parts[0], "")
        named = bool(row) if len(parts) == 1 else any(f"`{x}`" in row for x in (parts[-1], "/".join(parts[1:])))
        if not named:
            unnamed.append(path.relative_to(ROOT).as_posix())
    assert unnamed == []
