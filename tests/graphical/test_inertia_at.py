"""The construction's inertia loads, found from plain numbers, are bit for bit those of analytical.loads.inertia."""

import math
import types

import numpy as np
import pytest

from graphkin import catalog
from graphkin.analytical.loads import inertia
from graphkin.graphical import construct_forces
from graphkin.graphical.build import _inertia_at


class _Motion:
    """What ``inertia`` reads of a Kinematics, for one link: given arrays of a_G, α and G."""

    def __init__(self, m, I_G, a_G, alpha, G):
        body = types.SimpleNamespace(mass=m, I_G=I_G)
        self.mechanism = types.SimpleNamespace(link=lambda link: body)
        self.static = False
        self._a, self._al, self._G = a_G, alpha, G

    def z_a_G(self, link):
        return self._a

    def al(self, link):
        return self._al

    def z_G(self, link):
        return self._G


def _expected(inn, i):
    h = float(inn.h[i])
    return {"F": tuple(map(float, inn.F[i])), "T": float(inn.T[i]), "h": None if math.isnan(h) else h,
            "line_point": None if math.isnan(h) else tuple(map(float, inn.line_point[i]))}


def _numbers(rng, n, lo, hi):
    """Sizes from 10^lo to 10^hi, with zeros of both signs and whole numbers among them."""
    x = rng.normal(size=n) * 10.0 ** rng.integers(lo, hi, size=n)
    pick = rng.random(n)
    x[pick < 0.03] = 0.0
    x[(pick >= 0.03) & (pick < 0.06)] = -0.0
    whole = (pick >= 0.06) & (pick < 0.09)
    x[whole] = np.round(x[whole])
    return x


@pytest.mark.parametrize("seed", range(6))
def test_same_bits_as_inertia_on_random_motion(seed):
    rng = np.random.default_rng(seed)
    n = 2000
    # Both branches of the complex division, forces and torques from 1e-12 to 1e12, a link without mass or I_G.
    m = 0.0 if seed == 4 else float(abs(_numbers(rng, 1, -3, 4)[0]))
    I_G = 0.0 if seed == 5 else float(abs(_numbers(rng, 1, -6, 3)[0]))
    a_G = _numbers(rng, n, -12, 12) + 1j * _numbers(rng, n, -12, 12)
    alpha = _numbers(rng, n, -6, 8)
    G = _numbers(rng, n, -3, 1) + 1j * _numbers(rng, n, -3, 1)
    inn = inertia(_Motion(m, I_G, a_G, alpha, G), 3)
    for i in range(n):
        found = _inertia_at(m, I_G, complex(a_G[i]), float(alpha[i]), complex(G[i]))
        # repr tells 0.0 from −0.0, which == does not.
        assert repr(found) == repr(_expected(inn, i)), (m, I_G, a_G[i], alpha[i], G[i])


def test_not_finite_is_left_to_inertia():
    assert _inertia_at(1.0, 1.0, complex(math.inf, 0.0), 1.0, 0j) is None
    assert _inertia_at(1.0, 1.0, 1j, math.nan, 0j) is None


@pytest.mark.parametrize("name", catalog.names())
def test_construction_inertia_is_inertias(name):
    kin = catalog.load(name).kinematics()
    for i in range(0, kin.n, max(1, kin.n // 6)):
        if not kin.valid[i]:
            continue
        c = construct_forces(kin, i)
        for link, found in c.inertia.items():
            assert repr(found) == repr(_expected(inertia(kin, link), i))
