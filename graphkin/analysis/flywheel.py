"""Flywheel sizing from the driving-torque curve (Norton, *Design of Machinery*, §11.11).

The linkage demands a torque T(θ) that swings far above and below its
average T_avg. A motor that delivers T_avg, with a flywheel of system inertia
I_s on the crank shaft, drives it at a nearly steady speed: where T > T_avg
the flywheel gives up kinetic energy and slows, where T < T_avg it takes
energy back and speeds up. Norton's procedure:

1. the average torque T_avg = (1/2π) ∮ T dθ;
2. the crossings of T with T_avg (linear interpolation between samples);
3. the area of each pulse of T − T_avg from crossing to crossing
   (trapezoidal rule), accumulated from the first crossing (Table 11-1);
4. the largest energy swing E = max − min of the accumulated energy;
5. the system inertia I_s = E / (C_s ω_avg²), C_s = (ω_max − ω_min)/ω_avg.

Throughout, T is the torque the driver applies to the crank (T12, CCW
positive) for a crank turning CCW (θ increasing with time) at ω_avg > 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import GraphkinError
from ..model.ranges import complaint
from ._turn import TURN, closing_step, steps


@dataclass(frozen=True)
class Pulse:
    """One row of the energy table (Norton Table 11-1).

    Attributes
    ----------
    start, end : float
        Crossings of T with T_avg that bound the pulse [rad]; ``end`` of the
        last pulse is the first crossing one turn on.
    area : float
        ∫ (T − T_avg) dθ from start to end [J]: > 0 where the linkage takes
        energy from the shaft (the shaft slows), < 0 where it returns energy.
    accumulated : float
        Sum of the areas from the first crossing to ``end`` [J].
    """

    start: float
    end: float
    area: float
    accumulated: float


@dataclass(frozen=True)
class Disk:
    """A solid disk flywheel: I = ½ m r², m = ρ π r² t.

    Attributes
    ----------
    radius, thickness : float
        [m].
    density : float
        [kg/m³].
    mass : float
        [kg].
    I : float
        Moment of inertia about its axis [kg·m²].
    """

    radius: float
    thickness: float
    density: float
    mass: float
    I: float


@dataclass(frozen=True)
class Rim:
    """A rim flywheel: an annulus of mean radius R, radial width w and axial thickness t.

    I = ½ ρ π t (r_o⁴ − r_i⁴) = ρ π t R w (2R² + w²/2), with r_o, r_i = R ± w/2.
    The hub and spokes are left out, which errs on the safe side (they add inertia).

    Attributes
    ----------
    mean_radius, width, thickness, inner_radius, outer_radius : float
        [m].
    density : float
        [kg/m³].
    mass : float
        [kg].
    I : float
        Moment of inertia about its axis [kg·m²].
    """

    mean_radius: float
    width: float
    thickness: float
    inner_radius: float
    outer_radius: float
    density: float
    mass: float
    I: float


def check_Cs(Cs, what: str = "Cs") -> float:
    """The coefficient of speed fluctuation as a float, if 0 < C_s < 2; a clear error naming ``what`` if not."""
    Cs = _positive(Cs, what)
    if Cs >= 2:
        # ω_min = ω_avg (1 − Cs/2): at Cs = 2 the crank would stop once a turn.
        raise GraphkinError(f"{what} {Cs:g}: the coefficient of speed fluctuation must be below 2, where the slowest "
                            "speed ω_avg (1 − Cs/2) reaches zero (machines use 0.002 to 0.2)")
    return Cs


def _positive(value, what) -> float:
    # A string ("0.05") is refused like any other non-number: float() would quietly accept "1e5" or " 5 ".
    if isinstance(value, (str, bytes, bool, np.bool_)) or np.ndim(value) != 0:
        raise GraphkinError(f"{what} must be a number, got {value!r}")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise GraphkinError(f"{what} must be a number, got {value!r}") from None
    if not (math.isfinite(x) and x > 0):
        raise GraphkinError(f"{what} must be > 0, got {value!r}")
    return x


def _numbers(values, what) -> np.ndarray:
    """``values`` as a float array, or a plain error naming ``what`` (not numpy's "could not convert")."""
    if isinstance(values, (str, bytes)):
        raise GraphkinError(f"{what} must be an array of numbers, got {values!r:.60}")
    try:
        out = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise GraphkinError(f"{what} must be a 1-D array of numbers, got {values!r:.60}") from None
    return out


def size_flywheel(theta, T, *, omega_avg: float, Cs: float) -> "Flywheel":
    """Size a flywheel for a torque curve over one turn (Norton §11.11).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Crank angles θ [rad], increasing, covering one turn: the step from the
        last back to the first (plus 2π) closes the cycle, e.g. 0°, 2°, …, 358°
        (a repeated end point, 0° … 360°, is also accepted).
    T : array_like, shape (n,)
        Driving torque T12 [N·m] at those angles.
    omega_avg : float
        Average crank speed ω_avg = (ω_max + ω_min)/2 [rad/s], > 0 (CCW).
    Cs : float
        Coefficient of speed fluctuation C_s = (ω_max − ω_min)/ω_avg, > 0
        (Norton suggests 0.01 to 0.05 for most machinery).

    Returns
    -------
    Flywheel

    Raises
    ------
    GraphkinError
        If θ is not one increasing turn, T has non-finite values, or ω_avg, C_s are not > 0.

    Examples
    --------
    >>> theta = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    >>> f = size_flywheel(theta, 10 + 5 * np.sin(theta), omega_avg=100.0, Cs=0.05)
    >>> round(f.T_avg, 12), round(f.E, 3)       # ∫ 5 sin θ dθ over a half turn = 10 J
    (10.0, 10.0)
    >>> round(f.I_s, 4)                          # E / (Cs ω²)
    0.02
    """
    theta, T = _numbers(theta, "theta"), _numbers(T, "T")
    if theta.ndim != 1 or theta.shape != T.shape:
        raise GraphkinError(f"theta and T must be 1-D arrays of the same length, got shapes {theta.shape} and {T.shape}")
    if not np.all(np.isfinite(T)):
        raise GraphkinError(f"T is not finite at θ = {np.degrees(theta[~np.isfinite(T)])[:5].round(3).tolist()} deg")
    gap = closing_step(theta)
    if gap is None or not np.all(np.diff(theta) > 0):
        raise GraphkinError("theta must increase through one full turn of the crank (e.g. 0°, 2°, …, 358° in radians)")
    omega_avg = _positive(omega_avg, "omega_avg")
    why = complaint(omega_avg, "angular_velocity")
    if why:
        # Cs ω² would underflow to 0 (or overflow) and the inertia I_s = E / (Cs ω²) with it.
        raise GraphkinError(f"omega_avg = {omega_avg:g} rad/s {why}")
    Cs = check_Cs(Cs)

    h = steps(theta, gap)
    T_next = np.roll(T, -1)
    T_avg = float(np.sum(0.5 * (T + T_next) * h) / TURN)
    D, D_next = T - T_avg, T_next - T_avg
    # Energy U(θ) = ∫ (T − T_avg) dθ from θ0, at each sample and one turn on.
    U = np.concatenate([[0.0], np.cumsum(0.5 * (D + D_next) * h)])
    # A crossing wherever the sign of T − T_avg changes from one sample to the
    # next (the last segment closes the turn); zero counts as positive.
    k = np.flatnonzero((D >= 0) != (D_next >= 0))
    frac = D[k] / (D[k] - D_next[k])
    crossings = theta[k] + frac * h[k]
    # T is linear across the segment, so the area up to the crossing is a triangle.
    U_c = U[k] + 0.5 * D[k] * frac * h[k]
    areas = np.diff(np.append(U_c, U_c[:1] + U[-1]))
    accumulated = np.cumsum(areas)
    E = float(max(accumulated.max(initial=0.0), 0.0) - min(accumulated.min(initial=0.0), 0.0))
    return Flywheel(theta, T, gap, omega_avg, Cs, T_avg, crossings, areas, accumulated, E, E / (Cs * omega_avg**2),
                    U[:-1], float(U_c.min(initial=0.0)))


@dataclass(frozen=True)
class Flywheel:
    """A flywheel sized for a torque curve (made by :func:`size_flywheel`).

    Attributes
    ----------
    theta : ndarray, shape (n,)
        Crank angles [rad], one increasing turn.
    T : ndarray, shape (n,)
        Driving torque without the flywheel [N·m].
    gap : float
        Width of the interval that closes the turn, last angle to first + 2π [rad].
    omega_avg : float
        Average crank speed [rad/s].
    Cs : float
        Coefficient of speed fluctuation.
    T_avg : float
        Average torque (1/2π) ∮ T dθ [N·m] (periodic trapezoidal rule).
    crossings : ndarray, shape (m,)
        Angles where T crosses T_avg [rad], in increasing order.
    areas : ndarray, shape (m,)
        Pulse areas ∫ (T − T_avg) dθ from each crossing to the next, the last
        one wrapping round to the first [J]; they sum to zero (to rounding),
        because T_avg is the same trapezoidal mean.
    accumulated : ndarray, shape (m,)
        Running sum of the areas from the first crossing [J] (Table 11-1).
    E : float
        Largest energy swing, max − min of the accumulated energy (0 included) [J].
    I_s : float
        Required system inertia on the crank shaft E / (C_s ω_avg²) [kg·m²];
        the flywheel itself may be smaller by the inertia of other rotors on the shaft.
    U : ndarray, shape (n,)
        Energy ∫ (T − T_avg) dθ from theta[0] to each sample [J].
    U_min : float
        Lowest value of that energy over the turn (at a crossing) [J].
    """

    theta: np.ndarray
    T: np.ndarray
    gap: float
    omega_avg: float
    Cs: float
    T_avg: float
    crossings: np.ndarray
    areas: np.ndarray
    accumulated: np.ndarray
    E: float
    I_s: float
    U: np.ndarray
    U_min: float

    def table(self) -> tuple[Pulse, ...]:
        """The energy table, one row per pulse from the first crossing (Norton Table 11-1)."""
        ends = np.append(self.crossings[1:], self.crossings[:1] + TURN)
        return tuple(Pulse(float(a), float(b), float(c), float(d))
                     for a, b, c, d in zip(self.crossings, ends, self.areas, self.accumulated))

    # -- the physical flywheel ------------------------------------------------
    def disk(self, density: float, thickness: float) -> Disk:
        """The solid disk of the given material and thickness with I = I_s.

        Parameters
        ----------
        density : float
            ρ [kg/m³] (steel ≈ 7850, cast iron ≈ 7200).
        thickness : float
            Axial thickness t [m].

        Returns
        -------
        Disk
            With radius r = (2 I_s / (π ρ t))^(1/4) [m].
        """
        rho, t = _positive(density, "density"), _positive(thickness, "thickness")
        r = (2 * self.I_s / (math.pi * rho * t)) ** 0.25
        m = rho * math.pi * r * r * t
        return Disk(r, t, rho, m, 0.5 * m * r * r)

    def rim(self, density: float, mean_radius: float, thickness: float) -> Rim:
        """The rim (annulus) of the given mean radius and axial thickness with I = I_s.

        The radial width w solves ρ π t R (2R² w + w³/2) = I_s, a cubic with
        one real root (Cardano). A thin rim of large radius uses the least
        material for a given inertia (Norton §11.11).

        Parameters
        ----------
        density : float
            ρ [kg/m³].
        mean_radius : float
            R, the mean of the inner and outer radii [m].
        thickness : float
            Axial thickness t [m].

        Raises
        ------
        GraphkinError
            If the rim would need a width w > 2R (no hole left): choose a larger R or t.
        """
        rho = _positive(density, "density")
        R = _positive(mean_radius, "mean_radius")
        t = _positive(thickness, "thickness")
        # w³ + p w − q = 0 with p = 4R² > 0 has exactly one real root.
        p, q = 4 * R * R, 2 * self.I_s / (rho * math.pi * t * R)
        s = math.sqrt(q * q / 4 + p**3 / 27)
        w = math.cbrt(q / 2 + s) + math.cbrt(q / 2 - s)
        if w > 2 * R:
            raise GraphkinError(
                f"a rim of mean radius {R * 1e3:.4g} mm and thickness {t * 1e3:.4g} mm would need a width of"
                f" {w * 1e3:.4g} mm (more than its diameter): choose a larger radius or thickness, or a disk"
            )
        ri, ro = R - w / 2, R + w / 2
        m = rho * math.pi * (ro * ro - ri * ri) * t
        return Rim(R, w, t, ri, ro, rho, m, 0.5 * m * (ro * ro + ri * ri))

    # -- with the flywheel in place --------------------------------------------
    def speed(self) -> np.ndarray:
        """Crank speed ω(θ) [rad/s] with the flywheel, driven by a constant motor torque T_avg.

        Energy balance on the shaft (I_s includes everything on it):
        ½ I_s ω² = ½ I_s ω_max² − (U(θ) − U_min), U = ∫ (T − T_avg) dθ,
        so the shaft slows while the linkage takes more than the average. With
        I_s = E/(C_s ω_avg²), ω runs from ω_min = ω_avg (1 − C_s/2) to
        ω_max = ω_avg (1 + C_s/2) exactly. T itself is the constant-speed
        kinetostatic torque, the approximation Norton's sizing also makes.
        """
        w_max = self.omega_avg * (1 + self.Cs / 2)
        if self.E == 0:
            return np.full(len(self.theta), self.omega_avg)
        return np.sqrt(w_max**2 - 2 * (self.U - self.U_min) / self.I_s)

    def smoothed_torque(self, slip: float = 0.05) -> np.ndarray:
        """Torque the motor delivers [N·m], shape (n,), with the flywheel on the shaft.

        Model. A flywheel smooths the motor's torque only because the motor
        lets its speed droop under load (Norton Fig. 11-9). The motor is taken
        with a linear speed–torque line through its operating point,
        T_m = T_avg − k_m (ω − ω_avg), with k_m = T_avg (1 − s)/(s ω_avg): the
        line of an induction motor that runs at ω_avg with slip s, i.e. whose
        synchronous (no-load) speed is ω_avg/(1 − s). The shaft obeys
        I_s ω dω/dθ = T_m − T(θ). Linearised about ω_avg (|ω − ω_avg| ≤ C_s ω_avg/2),
        x = T_m − T_avg obeys

            τ dx/dθ + x = T − T_avg,   τ = ω_avg I_s / k_m  [rad],

        a first-order low-pass filter of the torque the linkage demands
        (harmonic k per turn passes as 1/(1 + i k τ)). It shows what Norton's
        Fig. 11-12 shows: with the flywheel the motor's torque stays near the
        average. Its swing is at most about k_m (ω_max − ω_min) ≈ T_avg C_s (1 − s)/s,
        and the motor sees all of T (no smoothing) as s → 0 (a motor that
        cannot slow down) or I_s → 0.

        The periodic solution is exact for T linear between samples (any
        spacing, so the jumps a switched load makes, sampled either side by
        :func:`graphkin.analysis.sweep`, pass through without ringing).

        Parameters
        ----------
        slip : float
            Motor slip s at the average torque, 0 < s < 1 (0.05 is a high-slip
            motor of the kind used with flywheels on presses and shears).

        Raises
        ------
        GraphkinError
            If T_avg ≤ 0 (the linkage delivers energy on average: no motor
            line passes through it).
        """
        s = _positive(slip, "slip")
        if s >= 1:
            raise GraphkinError(f"slip must be < 1, got {slip!r}")
        if self.T_avg <= 0:
            raise GraphkinError(f"the average torque is {self.T_avg:.4g} N·m ≤ 0: a motor model needs a positive average torque")
        if self.E == 0:
            return self.T.copy()
        k_m = self.T_avg * (1 - s) / (s * self.omega_avg)
        return self.T_avg + _periodic_lag(self.theta, self.T - self.T_avg, self.gap, self.omega_avg * self.I_s / k_m)


def _periodic_lag(theta, u, gap: float, tau: float) -> np.ndarray:
    """Periodic solution x(θ) of τ x′ + x = u over one turn, u linear between the samples.

    Over a step of width h with slope σ = Δu/h the solution is exactly
    x_b = E x_a + (u_b − τσ) − E (u_a − τσ), E = e^{−h/τ}; going once round
    from x = 0 and asking x(2π) = x(0) fixes the start: x_0 = x_N / (1 − ΠE).
    """
    h = steps(theta, gap)
    u_next = np.roll(u, -1)
    with np.errstate(divide="ignore", invalid="ignore"):
        sigma = np.where(h > 0, (u_next - u) / h, 0.0)
    E = np.exp(-h / tau)
    g = (u_next - tau * sigma) - E * (u - tau * sigma)
    x = np.empty(len(u) + 1)
    x[0] = 0.0
    for k in range(len(u)):  # a linear recurrence with varying steps: no vectorised form that cannot overflow
        x[k + 1] = E[k] * x[k] + g[k]
    decay = np.exp(-np.concatenate([[0.0], np.cumsum(h / tau)]))
    x = x + x[-1] / (1 - decay[-1]) * decay
    # With a repeated end point (0° … 360°) the closing step is 0 and x[-2] = x[-1] = x[0].
    return x[:-1]
