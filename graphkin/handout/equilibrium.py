"""The analytical route as a textbook prints it: each moving link's equilibrium equations with the numbers in,
group by group in the steps an exercise's feedback names, then the size of [A]{x} = {b} they make and its solution.

Step 1 is the inertia loads (d'Alembert); steps 2, 3, … are the groups' equilibria from the last group located to
the driver (:func:`graphkin.exercises.quantities.equilibrium_steps`), each solved for the unknowns of its own
joints: the rows of a group hold no unknown of a group solved later, so [A] is block triangular in this order.
The coefficients and the known terms are the matrix's own (:func:`graphkin.analytical.matrix.assemble`), so
every equation printed is a row of the system the solver solves.
"""

from __future__ import annotations

import numpy as np

from graphkin.analytical.matrix import assemble
from graphkin.exercises.quantities import equilibrium_steps
from graphkin.graphical.paper import TEXT_WIDTH
from graphkin.handout import maths as M
from graphkin.handout.document import Doc, Subject
from graphkin.kinematics import DriverGroup, GearGroup


def unknown(name: str) -> list:
    """``"F12x"`` → F₁₂ₓ, ``"N14"`` → N₁₄, ``"T12"`` → T₁₂."""
    return M.sym(name[0], name[1:]) if len(name) > 1 else M.i(name)


def system(s: Subject):
    """[A]{x} = {b} of every position (assembled once)."""
    if not hasattr(s, "_system"):
        s._system = assemble(s.result)
    return s._system


def clean(x, scale, rel=1e-12):
    """Values below ``rel`` × ``scale`` set to 0: rounding noise (1e-17 where a lever arm is zero) would hide
    the matrix's structure, as in :meth:`graphkin.analytical.matrix.System.format`."""
    x = np.array(x, dtype=float)
    x[np.abs(x) < rel * max(scale, 1e-300)] = 0.0
    return x + 0.0


def unit_of(name: str) -> str:
    """An unknown's unit: couples of sliding pairs and a crank's torque in N·m, forces in N."""
    return "N·m" if name[0] in "CT" else "N"


def definitions(s: Subject, unknowns, short: bool = False) -> list:
    """What each kind of unknown of the matrix is, as runs of a sentence; ``short``: one clause per kind, naming
    every unknown of the kind (``F23x, F23y, F34x, F34y: the components of the force F_ij of link i on link j at
    their pin``)."""
    out, seen = [], set()
    if short:
        kinds = {}
        for u in unknowns:
            kind = "driver" if u == s.mech.driver.symbol else "pin" if u[0] == "F" and u[-1:] in ("x", "y") else \
                u[0] if u[0] in "NC" else "tooth"
            kinds.setdefault(kind, []).append(u)
        words = {"pin": " the components of the force of link i on link j at their pin",
                 "N": " the normal force of guide i on slider j",
                 "C": " the couple of guide i on slider j",
                 "tooth": " the tooth force of gear i on gear j, along the pressure line",
                 "driver": f" the driving {'torque' if s.crank else 'force along the guide'}"}
        for kind, names in kinds.items():
            listed = [x for k, u in enumerate(names) for x in ([", "] if k else []) + [unknown(u)]]
            out += (["; "] if out else []) + listed + [words[kind]]
        return out + ["."]
    for u in unknowns:
        letter, rest = u[0], u[1:]
        if u == s.mech.driver.symbol:
            text = [M.name(u), f" the driving {'torque [N·m]' if s.crank else 'force along the guide [N]'}"]
        elif letter == "F" and rest[-1:] in ("x", "y"):
            if rest[:-1] in seen:
                continue
            seen.add(rest[:-1])
            i, j = rest[0], rest[1:-1]
            text = [M.sym("F", rest[:-1] + "x"), ", ", M.sym("F", rest[:-1] + "y"),
                    f" the components of the force of link {i} on link {j} at their pin [N]"]
        elif letter == "N":
            text = [M.sym("N", rest), f" the normal force of the sliding pair of links {rest[0]} and {rest[1:]} "
                    f"(across the guide, on link {rest[1:]}) [N]"]
        elif letter == "C":
            text = [M.sym("C", rest), f" the couple link {rest[0]} applies to link {rest[1:]} through their sliding "
                    "pair [N·m]"]
        else:
            text = [M.sym(letter, rest), f" the tooth force of link {rest[0]} on link {rest[1:]}, along the "
                    "pressure line [N]"]
        out += (["; "] if out else []) + text
    return out + ["."]


def _group_name(g) -> str:
    if isinstance(g, DriverGroup):
        return f"the driver, link {g.link}"
    if isinstance(g, GearGroup):
        return f"gear {g.k}"
    return f"the {g.label} (links {g.j} and {g.k})"


def _terms(coefficients, names) -> list[list]:
    """``F23x``, ``− F34x``, ``− 0.1143 N14``: each unknown with its coefficient (±1 printed as its sign only), a
    group of nodes each, so that a long row can be broken between them."""
    out = []
    for a, u in zip(coefficients, names):
        if a == 0:
            continue
        sign = "−" if a < 0 else "+"
        group = [M.op(sign)] if out or sign == "−" else []
        if abs(abs(a) - 1.0) > 1e-9:
            group.append(M.n(abs(a)))
        out.append(group + [unknown(u)])
    return out


def _known(value: float, unit: str, tiny: float) -> list[list]:
    """A known load moved into the row as a number: ``+ 2000 N`` (nothing where it is zero)."""
    if abs(value) <= tiny:
        return []
    return [[M.op("−" if value < 0 else "+"), M.qty(abs(value), unit)]]


def _fits(nodes) -> bool:
    return M.width_bound(M.row(*nodes)) * _SIZE <= _WIDTH


def _broken(label: list, groups: list[list]) -> list:
    """One equation's line, or several where it is wider than the page: broken before a term, each line after the
    first indented under the first term, as a book breaks a long equation (never scaled down to fit)."""
    lines, line = [], list(label)
    for group in groups:
        if len(line) > len(label) and not _fits(line + group):
            lines.append(M.row(*line))
            line = [M.t("        ")]
        line += group
    return lines + [M.row(*line)]


def _rows(s: Subject, entry: dict, link: int, A, b, names, tiny: float) -> list:
    """Link ``link``'s three rows, ΣFx = 0, ΣFy = 0 and ΣM about G = 0, with the numbers in: the unknowns with
    their coefficients (moment arms in m), the external loads as numbers and the inertia terms −m a_G and −I_G α."""
    d = entry["links"][str(link)]
    body = s.mech.link(link)
    inertial = not s.static and body.mass > 0
    r = 3 * s.mech.moving.index(link)
    a_G = clean(d["a_G"], np.abs(d["a_G"]).max(), 1e-9)  # a component of rounding noise (1e-16) is 0
    rows = []
    for k, (what, sub) in enumerate((("F", "x"), ("F", "y"), ("M", f"G{link}"))):
        known = -b[r + k]  # the known loads on the link, as the row adds them to the unknowns' terms
        if k < 2:
            inertia = d["inertia_force"][k] if inertial else 0.0
            term = ([[M.op("−"), M.paren(M.qty(body.mass, "kg")), M.paren(M.qty(a_G[k], "m/s²"))]]
                    if inertial else [])
            unit = "N"
        else:
            inertia = d["inertia_torque"] if inertial else 0.0
            term = ([[M.op("−"), M.paren(M.qty(body.I_G, "kg·m²")), M.paren(M.qty(d["alpha"], "rad/s²"))]]
                    if inertial and body.I_G > 0 else [])
            unit = "N·m"
        groups = _terms(A[r + k], names) + _known(known - inertia, unit, tiny) + term
        groups[-1] = groups[-1] + [M.op("="), M.n(0)]
        rows.append([[M.op("Σ"), M.sym(what, sub), M.op("=")] + groups[0]] + groups[1:])
    label = [M.t(f"link {link}:"), M.SP]
    # A link's rows on one line where they fit it (a massless slider's: ΣFx = F34x − N14 = 0; …), else ΣFx and ΣFy
    # on one and ΣM on the next, else a line each, each broken where it is wider than the page.
    for split in ((3,), (2, 1)):
        out, k = [], 0
        for n in split:
            out.append(label + [x for j, row in enumerate(rows[k:k + n])
                                for x in ([M.op(";"), M.SP, M.SP] if j else []) + [x for g in row for x in g]])
            k += n
        if all(_fits(line) for line in out):
            return [M.row(*line) for line in out]
    return [line for row in rows for line in _broken(label, row)]


_SIZE, _WIDTH = 9.0, (TEXT_WIDTH - 10.0) * 72 / 25.4
"""The rows' type size [pt] (:mod:`graphkin.handout.typst` sets a stacked equation at 9 pt) and the width a line
of them may take [pt] (the text's, less their indent)."""


def analytical(doc: Doc, s: Subject, entry: dict, i: int, inertia=None, free_bodies=None):
    """The analytical route at position ``i``: step 1 the inertia loads (``inertia``, a section writer, for a
    dynamic problem), the free bodies (``free_bodies``, a figure's writer: the equations are theirs), then each
    group's equations and what they give."""
    sysm = system(s)
    names = sysm.unknowns
    A = clean(sysm.A[i], np.abs(sysm.A[i]).max())
    b = clean(sysm.b[i], np.abs(sysm.b[i]).max())
    x = sysm.solve()[i]
    x = clean(x, np.abs(x).max(), 1e-9)
    tiny = 1e-9 * max(np.abs(b).max(), 1e-300)
    doc.heading(2, "The analytical solution")
    m = len(names)
    loads = "its external loads" if s.static else "its external loads and (d'Alembert) its inertia loads"
    doc.text(f"Each moving link is in equilibrium under the joint forces, {loads}: ΣFx = 0, ΣFy = 0 and ΣM about "
             f"its centre of mass G = 0 (moment arms in m). These {m} equations are [A]{{x}} = {{b}} of the matrix "
             f"method, [A] {m} × {m}, solved here group by group for {{x}}: ", *definitions(s, names, short=True))
    if inertia is not None:
        doc.heading(3, "Step 1. The inertia loads")
        inertia()
        if free_bodies is not None:
            free_bodies()
            free_bodies = None
    else:
        doc.heading(3, "Step 1. The inertia loads: none, a static analysis")
    solved: set[int] = set()
    for n, g in equilibrium_steps(s.mech):
        rows = [3 * s.mech.moving.index(link) + k for link in g.links for k in range(3)]
        columns = [c for c in range(len(names)) if c not in solved and np.any(A[rows, c] != 0)]
        own = (f"{len(rows)} equations in its {len(columns)} unknowns" if len(columns) == len(rows) else
               f"{len(rows)} equations")
        doc.heading(3, f"Step {n}. The equilibrium of {_group_name(g)}: {own}")
        lines = [line for link in g.links for line in _rows(s, entry, link, A, b, names, tiny)]
        found = [x_ for c in columns for x_ in ([M.op(","), M.SP] if c != columns[0] else []) +
                 [unknown(names[c]), M.op("="), M.qty(x[c], unit_of(names[c]))]]
        doc.equation(*lines, M.row(M.op("⇒"), M.SP, *found), stacked=True)
        solved.update(columns)
        if free_bodies is not None:
            # After the first group's equations, not straight after a heading: the float would take the heading.
            free_bodies()
            free_bodies = None
