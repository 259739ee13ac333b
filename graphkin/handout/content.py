"""The worked solution as data: one structure that every renderer (PDF, HTML, Markdown) reads.

:func:`build` returns a dictionary::

    {"title": str, "subtitle": str, "source": str, "version": "key" | "sheet" | "blank",
     "problem": str, "student": str | None,
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
``equation``   ``lines``: math nodes, one displayed line each; ``small``
``figure``     ``pictures`` (:class:`graphkin.handout.figures.Picture`, side by
               side), ``caption`` (starts ``"Figure k."``), ``label``
``space``      ``height`` [mm] of empty room to draw in by hand, ``label`` and ``math``
               (the equation of what to draw there, or None)
``pagebreak``  a new page (PDF only)
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
from graphkin.handout.document import Doc, Subject, subject
from graphkin.handout.sections import convention, given, inertia, kinematics, loads, mechanism, questions, statement
from graphkin.handout.solution import blank, cycle, forces, graphical, matrix

VERSIONS = ("key", "sheet", "blank")
"""The versions of a handout: the worked solution, an exercise sheet, a worksheet with room to draw."""


# -- the document ---------------------------------------------------------------------------
def build(source, *, student=None, secret="", at=None, version=None, Cs=None) -> dict:
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
        ``"key"``: everything (the default for a problem); ``"sheet"``: the
        data and the questions, no answers (the default for an exercise; for
        a problem, the same as ``"blank"``); ``"blank"``: the sheet with the
        free bodies drawn to the force scale and room to draw the polygons.
    Cs : float, optional
        Coefficient of speed fluctuation for the flywheel of a whole cycle
        (default: the exercise's, else :data:`DEFAULT_CS`).

    Returns
    -------
    dict
        See the module's docstring.
    """
    s = source if isinstance(source, Subject) else subject(source, student=student, secret=secret, at=at, Cs=Cs)
    version = version or ("sheet" if s.variant is not None else "key")
    if version not in VERSIONS:
        raise GraphkinError(f"version must be one of {', '.join(VERSIONS)}, got {version!r}")
    if version == "sheet" and s.variant is None:
        version = "blank"  # a problem has no questions: its sheet is the blank worksheet
    return _build(s, version)


def _build(s: Subject, version: str) -> dict:
    doc = Doc()
    v = s.variant
    title = (v.exercise.title if v is not None else s.problem.title) or s.problem.name
    source = (v.exercise.source if v is not None else s.problem.source) or ""
    what = {"key": "worked solution", "sheet": "exercise sheet", "blank": "worksheet"}[version]
    who = f"student {v.student}" if v is not None else ""
    worked = s.worked()
    out = {"title": title, "subtitle": ", ".join(x for x in (what.capitalize(), who) if x), "source": source,
           "version": version, "problem": v.exercise.id if v is not None else s.problem.name,
           "student": v.student if v is not None else None,
           "worked": [{"index": i, "q": float(s.result.kinematics.q[i]), "label": s.where(i)} for i in worked],
           "blocks": doc.blocks}
    key = version == "key"
    data = s.data()
    statement(doc, s, version)
    given(doc, s)
    if v is not None:
        questions(doc, s, answers=key)
    convention(doc, s)
    for i in worked:
        entry = data["positions"][i]
        c = s.construction(i)
        doc.heading(1, f"{'Solution' if key else 'The position'} at {s.where(i)}"
                    if len(worked) > 1 or s.whole_cycle else ("Solution" if key else "The position"))
        if not entry["valid"]:
            doc.text(f"The linkage has no solution here: {entry['reason']}.")
            continue
        drawn = version == "blank" or (v is not None and v.exercise.draw)
        if key or not drawn:  # the blank's figure of the free bodies shows the mechanism too
            mechanism(doc, s, c, i)
        if key:
            kinematics(doc, s, entry, i)
            if not s.static:
                inertia(doc, s, entry, c, i)
            loads(doc, s, entry)
            matrix(doc, s, entry, i)
            forces(doc, s, entry)
            graphical(doc, s, entry, c)
        else:
            blank(doc, s, c, drawn=drawn)
    if s.whole_cycle and s.crank and key:
        cycle(doc, s)
    elif s.whole_cycle and not key:
        doc.heading(1, "Over the whole cycle")
        doc.text(f"Solve every position of the file ({len(s.problem.q)} positions) and plot the driving "
                 f"{'torque' if s.crank else 'force'} against the input; read off its extremes and mean.")
    return out
