"""A figure's drawn extent, as ``Figure.get_tightbbox`` finds it, with each text's box laid out once per process.

A handout's figure is saved cropped to what it draws. ``get_tightbbox`` lays out every text of the figure to
find it (a label, a title, a scale bar's reading), although the labels were measured when they were placed
and the same names and titles come back on every student's figures. Here a text's box is the one
:func:`graphkin.draw.text.text_extent` keeps (laid out once, moved to where the text stands), so the extent is
the same to the last bit (``tests/draw/test_extent.py``). Where this matplotlib lacks a private name this needs
(:data:`graphkin.draw.matplotlib_private.FAST_TEXT`), the extent is ``get_tightbbox``'s own.
"""

from __future__ import annotations

import numpy as np
from matplotlib.transforms import Bbox, TransformedBbox

from graphkin.draw import matplotlib_private
from graphkin.draw.labels import measuring_renderer
from graphkin.draw.text import box_kept, text_extent


def _tight(a, renderer):
    """``a.get_tightbbox(renderer)``, a plain text's window extent from :func:`~graphkin.draw.text.text_extent`."""
    if not box_kept(a):
        return a.get_tightbbox(renderer)
    if not a.get_visible() or a.get_text() == "":
        return Bbox.null()
    ax = a.axes
    if ax and a.get_transform() == ax.transData and not ax._point_in_data_domain(*a.get_unitless_position()):
        return Bbox.null()
    bbox = text_extent(a, renderer)
    if a.get_clip_on():
        clip_box = a.get_clip_box()
        if clip_box is not None:
            bbox = Bbox.intersection(bbox, clip_box)
        clip_path = a.get_clip_path()
        if clip_path is not None and bbox is not None:
            bbox = Bbox.intersection(bbox, clip_path.get_fully_transformed_path().get_extents())
    return bbox


def _union(boxes) -> Bbox:
    """``Bbox.union(boxes)`` in plain floats (the same minima and maxima without two numpy reductions a box)."""
    pts = [b.get_points() for b in boxes]
    xs = [float(v) for p in pts for v in (p[0, 0], p[1, 0])]
    ys = [float(v) for p in pts for v in (p[0, 1], p[1, 1])]
    return Bbox.from_extents(min(xs), min(ys), max(xs), max(ys))


def _axes_extent(ax, renderer):
    """``ax.get_tightbbox(renderer)`` for axes with their axis off (else matplotlib's own)."""
    if ax.axison or ax.get_axes_locator() is not None:
        return ax.get_tightbbox(renderer)
    ax.apply_aspect(None)
    ax._update_title_position(renderer)
    bb = [ax.get_window_extent(renderer)]
    for title in (ax.title, ax._left_title, ax._right_title):
        if title.get_visible():
            bb.append(text_extent(title, renderer))
    for a in ax.get_default_bbox_extra_artists():
        box = _tight(a, renderer)
        if box is not None and box._is_finite():
            bb.append(box)
    return _union([b for b in bb if b.width != 0 or b.height != 0])


def drawn_extent(fig) -> Bbox:
    """What ``fig.get_tightbbox(renderer)`` gives [inches], measured with :func:`measuring_renderer`.

    Parameters
    ----------
    fig : matplotlib.figure.Figure

    Returns
    -------
    matplotlib.transforms.BboxBase
        The box around everything the figure draws, in inches from its lower left corner.
    """
    renderer = measuring_renderer(fig)
    if not matplotlib_private.FAST_TEXT:
        return fig.get_tightbbox(renderer)
    bb = [_tight(a, renderer) for a in fig.get_children()
          if a not in fig.axes and a.get_visible() and a.get_in_layout()]
    bb = [b for b in bb if b is not None]
    bb += [_axes_extent(ax, renderer) for ax in fig.axes if ax.get_visible()]
    bb = [b for b in bb if b is not None and np.isfinite(b.width) and np.isfinite(b.height)
          and (b.width != 0 or b.height != 0)]
    if not bb:
        return fig.bbox_inches
    return TransformedBbox(_union(bb), fig.dpi_scale_trans.inverted())
