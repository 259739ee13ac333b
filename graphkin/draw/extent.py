"""A figure's drawn extent, as ``Figure.get_tightbbox`` finds it, with each text's box laid out once per process.

A handout's figure is saved cropped to what it draws. ``get_tightbbox`` lays out every text of the figure to
find it (a label, a title, a scale bar's reading), although the labels were measured when they were placed
and the same names and titles come back on every student's figures. Here a text's box around its anchor is
kept per string, font, alignment, rotation and resolution, as :func:`graphkin.draw.labels.text_size` keeps its
size, and only moved to where the text stands: the same numbers, added in the same order as matplotlib adds
them, so the extent is the same to the last bit (``tests/draw/test_extent.py``).
"""

from __future__ import annotations

import numpy as np
from matplotlib.text import Text
from matplotlib.transforms import Bbox, TransformedBbox

from graphkin.draw.labels import measuring_renderer

_BOXES: dict = {}
_LIMIT = 8192


def _plain(t) -> bool:
    """Whether a text's box is kept here: not wrapped, rotated with its transform, in TeX, or an annotation (which
    moves as it is measured)."""
    return type(t) is Text and not (t.get_wrap() or t.get_transform_rotates_text() or t.get_usetex())


def _window_extent(t: Text, renderer) -> Bbox:
    """``t.get_window_extent(renderer)`` for a plain (:func:`_plain`), visible text with something in it."""
    dpi = t.get_figure(root=True).dpi
    t._renderer = renderer
    # A copy of the font: FontProperties can be changed in place, and hashes by its state.
    key = (t.get_text(), t.get_fontproperties().copy(), t.get_rotation(), t.get_rotation_mode(), t.get_ha(),
           t.get_va(), t._get_multialignment(), t.get_linespacing(), t.get_parse_math(), type(renderer), dpi)
    box = _BOXES.get(key)
    if box is None:
        if len(_BOXES) >= _LIMIT:
            _BOXES.clear()
        box = _BOXES[key] = t._get_layout(renderer)[0].frozen()
    x, y = t.get_unitless_position()
    x, y = t.get_transform().transform((x, y))
    return box.translated(x, y)


def _tight(a, renderer):
    """``a.get_tightbbox(renderer)``, a plain text's window extent from :func:`_window_extent`."""
    if not _plain(a):
        return a.get_tightbbox(renderer)
    if not a.get_visible() or a.get_text() == "":
        return Bbox.null()
    ax = a.axes
    if ax and a.get_transform() == ax.transData and not ax._point_in_data_domain(*a.get_unitless_position()):
        return Bbox.null()
    bbox = _window_extent(a, renderer)
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
            plain = _plain(title) and title.get_text() != ""
            bb.append(_window_extent(title, renderer) if plain else title.get_window_extent(renderer))
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
    bb = [_tight(a, renderer) for a in fig.get_children()
          if a not in fig.axes and a.get_visible() and a.get_in_layout()]
    bb = [b for b in bb if b is not None]
    bb += [_axes_extent(ax, renderer) for ax in fig.axes if ax.get_visible()]
    bb = [b for b in bb if b is not None and np.isfinite(b.width) and np.isfinite(b.height)
          and (b.width != 0 or b.height != 0)]
    if not bb:
        return fig.bbox_inches
    return TransformedBbox(_union(bb), fig.dpi_scale_trans.inverted())
