"""The input link: a crank driven by an unknown torque, or a slider driven by an unknown force."""

from __future__ import annotations

import numbers
from dataclasses import dataclass
from typing import Literal

from graphkin.errors import ModelError


@dataclass(frozen=True)
class Driver:
    """The link whose motion is known.

    Parameters
    ----------
    link : int
        The input link. It is joined to the frame by a revolute joint
        (``kind="crank"``: input θ, ω, α; unknown torque ``T1j``) or by a
        prismatic joint (``kind="slider"``: input s, v, a along the guide;
        unknown force ``F1j`` along the guide).
    kind : {"crank", "slider"}
    frame : int
        The frame's number, 1 or 0; it only names the unknown (``T12`` or
        ``T01``). A :class:`Mechanism` sets it to its own ``frame``.
    """

    link: int
    kind: Literal["crank", "slider"] = "crank"
    frame: int = 1

    def __post_init__(self):
        # int("2") or int(2.5) would quietly turn a slip into another link.
        if isinstance(self.link, bool) or not isinstance(self.link, numbers.Integral):
            raise ModelError(f"driver link must be a link number, e.g. 2, got {self.link!r}")
        object.__setattr__(self, "link", int(self.link))
        if self.kind not in ("crank", "slider"):
            raise ModelError(f"driver kind must be 'crank' or 'slider', got {self.kind!r}")

    @property
    def symbol(self) -> str:
        """Name of the unknown driving effort: ``T12`` or ``F12`` (``T01`` with the frame numbered 0)."""
        return f"{'T' if self.kind == 'crank' else 'F'}{self.frame}{self.link}"

    @property
    def crank(self) -> bool:
        """Whether the input is a crank's angle θ (else a slider's position s along its guide)."""
        return self.kind == "crank"

    @property
    def input_symbol(self) -> str:
        """The input's symbol as the reports print it: ``θ12`` for a crank (``θ01`` with the frame 0), ``s``."""
        return f"θ{self.frame}{self.link}" if self.crank else "s"
