"""The names the drawing layer's helpers had before they were split by what they do (kept for old imports).

Import from the modules instead: :mod:`.axes` (Drawn, PanelAxes, line,
markers, limits), :mod:`.text` (sub, num, polar_text, halo), :mod:`.arrows`,
:mod:`.labels` (Labeler, :func:`~.labels.measuring_renderer`) and
:mod:`.scales` (dimension lines, scale bars).
"""

from .arrows import arc_points, arrow, moment_arrow, perp, unit  # noqa: F401
from .axes import (MM, Drawn, PanelAxes, had_content, line, markers, new_axes, points_per_unit, put,  # noqa: F401
                   set_limits, setup_axes)
from .labels import (Labeler, arrow_label_candidates, offset_text, point_label_candidates,  # noqa: F401
                     segment_hits_box, text_box, text_size)
from .labels import measuring_renderer as renderer_of  # noqa: F401
from .scales import dimension, nice_round, scale_bar  # noqa: F401
from .text import SUBSCRIPTS as _SUB  # noqa: F401
from .text import halo, input_text, num, plain, polar_text, sub  # noqa: F401
