"""The worked solution as data: one structure that every renderer (PDF, HTML, Markdown) reads.

:func:`build` returns a dictionary::

    {"title": str, "subtitle": str, "source": str, "version": "key" | "sheet" | "blank",
     "problem": str, "student": str | None, "from_motion": bool,
     "worked": [{"index": int, "q": float, "label": "θ12 = 342°"}],   the positions worked out
     "blocks": [block, ...]}

in the order a textbook solution goes: title and source; the given data
(the file's own units); the sign convention; for each worked position the
mechanism, the kinematics of every link, the inertia loads, the matrix
[A]{x} = {b} and its solution, the graphical route step by step and the
table of both routes; for a whole cycle the torque curve, the flywheel's
energy table (Norton Table 11-1) and the joint-force index.

A block is a dict with a ``"kind"``:

=============  ==================================================================
``heading``    ``level`` (1–3), ``text``
``text``       ``runs``: a paragraph; ``keep``: on the same page as the next block
               (it introduces a figure or ends with a colon)
``list``       ``items``: each a list of runs; ``ordered``
``table``      ``header`` and ``rows``: cells, each a list of runs; ``align``
               (one of ``l c r`` per column); ``caption`` (str or None)
``equation``   ``lines``: math nodes, one displayed line each; ``small``; ``stacked`` (set close, from the left)
``figure``     ``pictures`` (:class:`graphkin.handout.figures.Picture`, side by
               side), ``caption`` (starts ``"Figure k."``), ``label``
``space``      ``height`` [mm] of empty room to draw in by hand, ``label`` and ``math``
               (the equation of what to draw there, or None)
``pagebreak``  a new page (PDF only)
``flush``      every figure before it placed before what follows (PDF only: the others do not float)
=============  ==================================================================

A *run* is a str (plain text) or a math node (a list, see
:mod:`graphkin.handout.maths`). Every number is formatted here, once, with
:func:`graphkin.handout.maths.fmt`: the three renderers print the same digits.
The numbers come from :func:`graphkin.report.solution` (the data of
``graphkin solve --json``) and :func:`graphkin.report.cycle_data` (``graphkin
cycle --json``); nothing is solved twice.
"""

from __future__ import annotations

from graphkin.errors import GraphkinError
from graphkin.graphical.paper import FIGURE_WIDTH, length_scale, mechanism_size
from graphkin.handout import book, compact, scaled
from graphkin.handout import motion as polygons
from graphkin.handout.document import Doc, Subject, subject
from graphkin.handout.sections import (
    convention,
    given,
    inertia,
    kinematics,
    loads,
    mechanism,
    notation,
    own_data,
    questions,
    statement,
)
from graphkin.handout.solution import cycle, forces, graphical, matrix
from graphkin.handout.worksheet import worksheet
from graphkin.notation import citation

VERSIONS = ("key", "sheet", "blank")
"""The versions of a handout: the worked solution, an exercise sheet, a worksheet with room to draw."""
DETAILS = ("compact", "full")
"""How much a key shows: as a textbook prints a solution (the default), or every step walked through."""


# -- the document ---------------------------------------------------------------------------
def build(source, *, student=None, secret="", at=None, version=None, Cs=None, detail="compact", units=None,
          from_motion=False) -> dict:
    """The worked solution (or a student's sheet) as data, ready for any renderer.

    Parameters
    ----------
    source : str or graphkin.exercises.Variant
        A catalog problem or a problem file; with ``student``, a catalog
        exercise or an exercise file; or a variant already made.
    student : str, optional
        The student's id: the handout is their variant of the exercise.
    secret : str
        The course secret the variants are drawn with.
    at : str or array_like, optional
        Input positions to work out (``"124 deg,140 deg"``, or SI values [rad or m]);
        by default the problem's own (over a whole cycle: the position of
        the largest driving effort, and the cycle itself).
    version : {"key", "sheet", "blank"}, optional
        ``"key"``: the solution (the default for a problem); ``"sheet"``: the
        data and the questions, no answers (the default for an exercise; for
        a problem, the same as ``"blank"``); ``"blank"``: a worksheet, with
        the mechanism and the free bodies to scale and room to draw the polygons.
    Cs : float, optional
        Coefficient of speed fluctuation for the flywheel of a whole cycle
        (default: the exercise's, else :data:`DEFAULT_CS`).
    detail : {"compact", "full"}
        For a key: ``"compact"`` as a textbook prints a solution (the motion,
        the inertia loads, the free bodies, the polygons with their equations,
        the answers boxed); ``"full"`` every step walked through (the kinematics
        loop by loop, the matrix [A]{x} = {b}, each step of the construction with
        its own figure), with the problem's notes on its source.
    units : graphkin.units.systems.UnitSystem, optional
        The answers' units (``--units``; default SI: N, N·m, mm). The working (inertia loads, the matrix, the
        polygons) stays in SI, as it is solved; the given data is as the problem file writes it.
    from_motion : bool
        With ``version="blank"``: the worksheet that starts from the input motion (``--from-motion``): the
        positions, the input's ω and α (or a driving slider's v and a), the mass properties and the external loads
        given; the velocity and acceleration polygons, each link's ω, α, a_G and inertia loads, and the force
        polygons to construct. For a problem only (an exercise's sheet gives what its statement says), and not
        for a key, a static problem or one that gives the book's accelerations.

    Returns
    -------
    dict
        See the module's docstring.
    """
    s = source if isinstance(source, Subject) else subject(source, student=student, secret=secret, at=at, Cs=Cs,
                                                           units=units)
    version = version or ("sheet" if s.variant is not None else "key")
    if version not in VERSIONS:
        raise GraphkinError(f"version must be one of {', '.join(VERSIONS)}, got {version!r}")
    if detail not in DETAILS:
        raise GraphkinError(f"--detail must be one of {', '.join(DETAILS)}, got {detail!r}")
    if version == "sheet" and s.variant is None:
        version = "blank"  # a problem has no questions: its sheet is the blank worksheet
    if from_motion:
        _check_from_motion(s, version)
    return _build(s, version, detail, from_motion)


def _check_from_motion(s: Subject, version: str):
    """A sheet from the input motion needs a blank worksheet and a motion to construct, none of it given."""
    if s.variant is not None:
        # Its statement says what the student is given (double_slider_graphical: "the rod's inertia resultant on
        # its offset line"); a sheet that left it out would contradict it.
        raise GraphkinError(f"--from-motion is for a problem's worksheet; the exercise {s.variant.exercise.id}'s "
                            "sheet gives what its statement says")
    name = s.problem.name
    if version == "key":
        raise GraphkinError("--from-motion is for a blank worksheet (--blank); a key already draws the polygons "
                            "from the input motion")
    if s.static:
        raise GraphkinError(f"--from-motion: {name} is static (no inertia loads): there is no motion to construct; "
                            "leave --from-motion out")
    if s.result.kinematics.given:
        raise GraphkinError(f"--from-motion: {name} gives the book's accelerations in its data, which the sheet "
                            "would print; leave --from-motion out")


def _build(s: Subject, version: str, detail: str, from_motion: bool = False) -> dict:
    doc = Doc()
    v = s.variant
    title = (v.exercise.title if v is not None else s.problem.title) or s.problem.name
    source = (v.exercise.source if v is not None else s.problem.source) or ""
    full = detail == "full" and version == "key"
    if not full:
        # A student's page cites the book in one line; where the catalog read it is the teacher's (--detail full).
        source = (s.problem.cite if v is None and s.problem.cite else "") or citation(source)
    what = {"key": "worked solution", "sheet": "exercise sheet", "blank": "worksheet"}[version]
    if from_motion:
        what += " from the input motion"
    who = f"student {v.student}" if v is not None else ""
    worked = s.worked()
    out = {"title": title, "subtitle": ", ".join(x for x in (what.capitalize(), who) if x), "source": source,
           "version": version, "detail": detail, "problem": v.exercise.id if v is not None else s.problem.name,
           "student": v.student if v is not None else None, "from_motion": from_motion,
           "worked": [{"index": i, "q": float(s.result.kinematics.q[i]), "label": s.where(i)} for i in worked],
           "blocks": doc.blocks}
    if full:
        _full(doc, s, worked)
    elif version == "key":
        _compact(doc, s, worked)
    elif version == "sheet" and not v.exercise.draw:
        _sheet(doc, s, worked)
    else:
        _worksheet(doc, s, worked, from_motion)
    return out


def _heading(doc: Doc, s: Subject, worked, i: int, word: str):
    several = len(worked) > 1 or s.whole_cycle
    doc.heading(1, f"{word} at {s.where(i)}" if several else word)


def _compact(doc: Doc, s: Subject, worked):
    statement(doc, s, "key", full=False, at=worked)
    notation(doc, s)
    given(doc, s, worked[0] if len(worked) == 1 else None)
    if s.variant is not None:
        questions(doc, s, answers=True)
    data = s.data()
    for i in worked:
        entry = data["positions"][i]
        _heading(doc, s, worked, i, "Solution")
        if not entry["valid"]:
            doc.text(f"The linkage has no solution here: {entry['reason']}.")
            continue
        compact.solution(doc, s, entry, s.construction(i), i)
    if s.cycle_asked:
        cycle(doc, s)


def _full(doc: Doc, s: Subject, worked):
    statement(doc, s, "key", full=True, at=worked)
    given(doc, s, worked[0] if len(worked) == 1 else None)
    if s.variant is not None:
        questions(doc, s, answers=True)
    convention(doc, s)
    data = s.data()
    for i in worked:
        entry = data["positions"][i]
        c = s.construction(i)
        _heading(doc, s, worked, i, "Solution")
        if not entry["valid"]:
            doc.text(f"The linkage has no solution here: {entry['reason']}.")
            continue
        mechanism(doc, s, c, i)
        kinematics(doc, s, entry, i)
        polygons.key(doc, s, i, steps=True)
        if not s.static:
            inertia(doc, s, entry, c, i)
        loads(doc, s, entry)
        matrix(doc, s, entry, i)
        forces(doc, s, entry)
        book.asked(doc, s, entry, i)
        graphical(doc, s, entry, c, i)
    if s.cycle_asked:
        cycle(doc, s)


def _sheet(doc: Doc, s: Subject, worked):
    """An exercise's sheet: the statement, the student's data and their mechanism on the first page, then the
    questions with room for the answers, then the rest of the data."""
    statement(doc, s, "sheet", full=False, at=worked)
    v = s.variant
    own_data(doc, s)
    for i in worked or [0]:
        c = s.construction(i)
        if c is not None and c.valid:
            k = length_scale(mechanism_size(c), (FIGURE_WIDTH, 80.0))
            doc.figure([scaled.mechanism(s, c, i, k)], f"Your mechanism at {s.where(i)}, drawn from your data. "
                       + scaled.statement(k))
    questions(doc, s, answers=False)
    given(doc, s, worked[0] if len(worked) == 1 else None, own=False)
    if s.whole_cycle and v.exercise.cycle:
        doc.heading(1, "Over the whole cycle")
        n = s.cycle_positions or s.n
        doc.text(f"Solve every position of the cycle ({n} positions) and plot the driving "
                 f"{'torque' if s.crank else 'force'} against the input; read off what the questions ask.")


def _worksheet(doc: Doc, s: Subject, worked, from_motion: bool = False):
    v = s.variant
    statement(doc, s, "blank", full=False, at=worked, from_motion=from_motion)
    if v is not None:
        own_data(doc, s)
        questions(doc, s, answers=False)
    given(doc, s, worked[0] if len(worked) == 1 else None, own=False)
    data = s.data()
    for i in worked:
        entry = data["positions"][i]
        _heading(doc, s, worked, i, "The position")
        if not entry["valid"]:
            doc.text(f"The linkage has no solution here: {entry['reason']}.")
            continue
        worksheet(doc, s, entry, s.construction(i), i, find=v is None, from_motion=from_motion)
