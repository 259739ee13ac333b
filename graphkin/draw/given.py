"""What a student is given for a graphical exercise: the mechanism and free bodies with the known loads only."""

from __future__ import annotations

from matplotlib.figure import Figure

from graphkin.draw.axes import PanelAxes
from graphkin.draw.fbd import draw_free_body
from graphkin.draw.mechanism import draw_mechanism


def draw_given(construction, links=None, *, figsize=None, **style) -> Figure:
    """The mechanism and the free bodies of ``links`` to scale, without the forces the student finds.

    Each free body shows the link, its inertia resultant on its offset line
    (with h), its external loads and a force scale bar; the joint forces and
    the driver's effort are left out, for the student to find by drawing the
    polygons at that scale.

    Parameters
    ----------
    construction : graphkin.graphical.Construction
        E.g. ``graphkin.exercises.variant(name, student).construction``.
    links : sequence of int, optional
        Which free bodies (default: every moving link that carries an inertia
        resultant or an external load).
    figsize : (float, float), optional
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    matplotlib.figure.Figure
    """
    c = construction
    if links is None:
        links = [k for k in c.mechanism.moving
                 if (k in c.inertia and any(c.inertia[k]["F"])) or c.external.get(k)] or list(c.mechanism.moving)
    n = 1 + len(links)
    # Fixed margins, not a layout engine: the labels are placed for the axes as they are drawn.
    fig = Figure(figsize=figsize or (4.5 * n, 4.5))
    axes = fig.subplots(1, n, squeeze=False, subplot_kw={"axes_class": PanelAxes},
                        gridspec_kw={"left": 0.02, "right": 0.98, "bottom": 0.03, "top": 0.9, "wspace": 0.1})[0]
    draw_mechanism(c, ax=axes[0], **style)
    for ax, link in zip(axes[1:], links):
        draw_free_body(c, link, ax=ax, unknowns=False, **style)
    return fig
