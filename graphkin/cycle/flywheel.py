"""Flywheel sizing from a turning-moment diagram (Norton, *Design of Machinery*, §11.11).

A shaft carries a driving torque T_d(θ) and a resisting torque T_r(θ). A
linkage driven at constant speed demands a torque T(θ) that swings far above
and below its average T_avg; a motor delivers about T_avg (T_d constant,
T_r = T). An engine's torque swings with the firing of its cylinders against
a steady load (T_d = the engine's curve, T_r constant at its mean, or a curve
of its own). With a flywheel of system inertia I_s on the shaft,
I_s α = T_d − T_r: where the resistance exceeds the drive the flywheel gives up
kinetic energy and slows, elsewhere it takes energy back and speeds up.
Norton's procedure:

1. the average torque T_avg = (1/period) ∮ T dθ (the same for both torques in a steady state);
2. the crossings of T_r with T_d (linear interpolation between samples);
3. the area of each pulse of T_r − T_d from crossing to crossing
   (trapezoidal rule), accumulated from the first crossing (Table 11-1);
4. the largest energy swing E = max − min of the accumulated energy;
5. the system inertia I_s = E / (C_s ω_avg²), C_s = (ω_max − ω_min)/ω_avg, or,
   for a given inertia, the fluctuation C_s = E / (I_s ω_avg²) it leaves.

Torques are CCW positive for a shaft turning CCW (θ increasing with time) at ω_avg > 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.cycle._sampling import peak_of
from graphkin.cycle.turn import TURN, closing_step, steps
from graphkin.errors import GraphkinError
from graphkin.ranges import complaint


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


def _torque(value, what, theta):
    """A torque over the cycle: an array (n,) as given, a constant [N·m], or ``"mean"`` (None until the other is known)."""
    if isinstance(value, str):
        if value != "mean":
            raise GraphkinError(f'{what} must be an array of torques [N·m], one number [N·m] or "mean", got {value!r}')
        return None
    if np.ndim(value) == 0:
        x = _numbers(value, what)
        if not np.isfinite(x):
            raise GraphkinError(f"{what} must be finite, got {value!r}")
        why = complaint(float(x), "torque")
        if why:
            raise GraphkinError(f"{what} = {float(x):g} N·m {why}")
        return np.full(len(theta), float(x))
    T = _numbers(value, what)
    if T.shape != theta.shape:
        raise GraphkinError(f"theta and {what} must be 1-D arrays of the same length, got shapes {theta.shape} and "
                            f"{T.shape}")
    if not np.all(np.isfinite(T)):
        raise GraphkinError(f"{what} is not finite at θ = {np.degrees(theta[~np.isfinite(T)])[:5].round(3).tolist()} deg")
    return T


MEANS_RTOL = 5e-3
"""How far apart (relative to the largest torque) the driving and resisting torques' means may be.

In a steady state the shaft gains over a cycle exactly the energy it loses,
so the two means are equal; a book that rounds a constant load torque may
differ in the fourth digit, anything more is a slip (the shaft would speed
up or slow down every cycle)."""


def size_flywheel(theta, T=None, *, driving=None, resisting=None, omega_avg: float, Cs: float | None = None,
                  I: float | None = None, period: float = TURN) -> "Flywheel":
    """Size a flywheel for a turning-moment diagram (Norton §11.11), or find the fluctuation a given one leaves.

    The shaft carries a driving torque T_d(θ) (an engine, or a motor) and a
    resisting torque T_r(θ) (the load, or the torque a linkage demands); with
    the system inertia I_s on the shaft, I_s α = T_d − T_r. Over a cycle the
    shaft loses the energy ∫ (T_r − T_d) dθ where the resistance exceeds the
    drive and gains it back elsewhere; E is the largest swing of that energy.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Shaft angles θ [rad], increasing, covering one cycle: the step from the
        last back to the first (plus ``period``) closes it, e.g. 0°, 2°, …, 358°
        (a repeated end point, 0° … 360°, is also accepted).
    T : array_like, shape (n,), optional
        The torque a machine demands at constant speed [N·m] (a linkage's driving
        torque T12), driven by a motor whose torque is constant at T's mean:
        the same as ``resisting=T, driving="mean"``. Give either ``T`` or
        ``driving`` and ``resisting``.
    driving, resisting : array_like, shape (n,), float or "mean", optional
        The driving and the resisting torque [N·m] at those angles, each a
        curve, a constant, or ``"mean"`` (constant at the other's mean: a
        load that takes the engine's average torque, or a motor that gives the
        machine's). With only ``driving`` given, the resistance is its mean.
        An engine's torque passed as ``T`` would be taken for a load: the energy
        swing is the same, but the shaft's fastest and slowest angles swap.
    omega_avg : float
        Average shaft speed ω_avg = (ω_max + ω_min)/2 [rad/s], > 0 (CCW).
    Cs : float, optional
        Coefficient of speed fluctuation C_s = (ω_max − ω_min)/ω_avg, 0 < C_s < 2
        (Norton suggests 0.01 to 0.05): the inertia I_s = E/(C_s ω_avg²) is found.
    I : float, optional
        The system inertia on the shaft [kg·m²], > 0, instead of ``Cs``: the
        fluctuation C_s = E/(I ω_avg²) it leaves is found.
    period : float, optional
        Length of one cycle [rad]: 2π (one turn, the default), 4π for a
        four-stroke engine's cycle.

    Returns
    -------
    Flywheel
        The energy swing E, the system inertia I_s (or the C_s a given one leaves), the table of pulses
        between the crossings, and the speed and acceleration over the cycle.

    Raises
    ------
    GraphkinError
        If θ is not one increasing cycle, a torque has non-finite values,
        ω_avg is not > 0, not exactly one of C_s and I is given, the roles of
        the torques are unclear, or the two torques' means differ (beyond
        :data:`MEANS_RTOL`): in a steady state they are equal.

    Examples
    --------
    >>> theta = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    >>> f = size_flywheel(theta, 10 + 5 * np.sin(theta), omega_avg=100.0, Cs=0.05)
    >>> round(f.T_avg, 12), round(f.E, 3)       # ∫ 5 sin θ dθ over a half turn = 10 J
    (10.0, 10.0)
    >>> round(f.I_s, 4)                          # E / (Cs ω²)
    0.02
    >>> e = size_flywheel(theta, driving=10 + 5 * np.sin(theta), resisting=10.0, omega_avg=100.0, I=0.02)
    >>> round(e.Cs, 4), round(float(np.degrees(e.speed_extremes().at_max)), 3)   # fastest where the drive stops gaining
    (0.05, 180.0)
    """
    theta = _numbers(theta, "theta")
    if theta.ndim != 1:
        raise GraphkinError(f"theta must be a 1-D array of shaft angles [rad], got shape {theta.shape}")
    period = _positive(period, "period")
    gap = closing_step(theta, period)
    if gap is None or not np.all(np.diff(theta) > 0):
        raise GraphkinError("theta must increase through one full "
                            + ("turn of the crank" if period == TURN else f"cycle of {math.degrees(period):g}°")
                            + " (e.g. 0°, 2°, …, 358° in radians)")
    name_r = "resisting"
    if T is not None:
        if driving is not None or resisting is not None:
            raise GraphkinError("give either T (a machine's torque demand, driven at its mean) or driving and resisting,"
                                " not both")
        driving, resisting, name_r = "mean", T, "T"
    if driving is None and resisting is None:
        raise GraphkinError("give the torque curve: T, or driving (and resisting)")
    driving = "mean" if driving is None else driving
    resisting = "mean" if resisting is None else resisting
    T_d, T_r = _torque(driving, "driving", theta), _torque(resisting, name_r, theta)
    if T_d is None and T_r is None:
        raise GraphkinError('driving and resisting cannot both be "mean": give at least one of them as a torque')
    omega_avg = _positive(omega_avg, "omega_avg")
    why = complaint(omega_avg, "angular_velocity")
    if why:
        # Cs ω² would underflow to 0 (or overflow) and the inertia I_s = E / (Cs ω²) with it.
        raise GraphkinError(f"omega_avg = {omega_avg:g} rad/s {why}")
    if (Cs is None) == (I is None):
        raise GraphkinError("give exactly one of Cs (to find the inertia) and I (to find the speed fluctuation)")
    if Cs is not None:
        Cs = check_Cs(Cs)
    else:
        I = _positive(I, "I")
        why = complaint(I, "moment_of_inertia")
        if why:
            raise GraphkinError(f"I = {I:g} kg·m² {why}")

    h = steps(theta, gap)

    def mean(x):
        return float(np.sum(0.5 * (x + np.roll(x, -1)) * h) / period)

    if T_d is None:
        T_d = np.full(len(theta), mean(T_r))
    if T_r is None:
        T_r = np.full(len(theta), mean(T_d))
    T_avg, r_avg = mean(T_d), mean(T_r)
    scale = max(float(np.max(np.abs(T_d))), float(np.max(np.abs(T_r))), 1e-300)
    if abs(T_avg - r_avg) > MEANS_RTOL * scale:
        raise GraphkinError(f"resisting: the driving torque averages {T_avg:.6g} N·m over the cycle and the resisting torque "
                            f"{r_avg:.6g} N·m: in a steady state they are equal (else the shaft speeds up or slows "
                            'down every cycle); for a load that takes the average, give resisting = "mean"')
    D = T_r - T_d
    D_next = np.roll(D, -1)
    # Energy U(θ) = ∫ (T_r − T_d) dθ taken from the shaft, from θ0, at each sample and one cycle on.
    U = np.concatenate([[0.0], np.cumsum(0.5 * (D + D_next) * h)])
    # A crossing wherever the sign of T_r − T_d changes from one sample to the
    # next (the last segment closes the cycle); zero counts as positive.
    k = np.flatnonzero((D >= 0) != (D_next >= 0))
    frac = D[k] / (D[k] - D_next[k])
    crossings = theta[k] + frac * h[k]
    # T is linear across the segment, so the area up to the crossing is a triangle.
    U_c = U[k] + 0.5 * D[k] * frac * h[k]
    # A crossing at the very end of the closing step is the first angle, one cycle on: report it there (0°, not
    # 360°), with the energy it has one cycle earlier.
    wrap = crossings >= theta[0] + period * (1 - 1e-12)
    crossings = np.where(wrap, crossings - period, crossings)
    U_c = np.where(wrap, U_c - U[-1], U_c)
    order = np.argsort(crossings, kind="stable")
    crossings, U_c = crossings[order], U_c[order]
    areas = np.diff(np.append(U_c, U_c[:1] + U[-1]))
    accumulated = np.cumsum(areas)
    E = float(max(accumulated.max(initial=0.0), 0.0) - min(accumulated.min(initial=0.0), 0.0))
    if Cs is not None:
        I_s = E / (Cs * omega_avg**2)
    else:
        I_s, Cs = I, E / (I * omega_avg**2)
        if Cs >= 2:
            raise GraphkinError(f"I: with I = {I:g} kg·m² the speed would swing by C_s = {Cs:.4g} of ω_avg, enough to stop "
                                "the shaft (C_s ≥ 2): the inertia is far too small for this torque")
    return Flywheel(theta, T_avg + D, gap, omega_avg, Cs, T_avg, crossings, areas, accumulated, E, I_s, U[:-1],
                    float(U_c.min(initial=0.0)), T_d, T_r, period, U_c)


@dataclass(frozen=True)
class SpeedExtremes:
    """The fastest and slowest shaft speeds over a cycle and where they occur.

    Attributes
    ----------
    omega_max, omega_min : float
        ω_avg (1 ± C_s/2) [rad/s].
    at_max, at_min : float
        Shaft angles [rad] where they occur: crossings of the driving and
        resisting torques (nan if the torques never cross: then ω is constant).
    """

    omega_max: float
    at_max: float
    omega_min: float
    at_min: float


@dataclass(frozen=True)
class Flywheel:
    """A flywheel sized for a turning-moment diagram (made by :func:`size_flywheel`).

    Attributes
    ----------
    theta : ndarray, shape (n,)
        Shaft angles [rad], one increasing cycle.
    T : ndarray, shape (n,)
        The net torque the shaft must supply about the mean, T_avg + (T_r − T_d) [N·m]:
        for a machine driven at a constant torque (a linkage's T12 with a
        motor) it is the machine's own torque curve.
    gap : float
        Width of the interval that closes the cycle, last angle to first + period [rad].
    omega_avg : float
        Average shaft speed [rad/s].
    Cs : float
        Coefficient of speed fluctuation (ω_max − ω_min)/ω_avg: given, or left by a given inertia.
    T_avg : float
        Average torque over the cycle [N·m] (periodic trapezoidal rule), driving and resisting alike.
    crossings : ndarray, shape (m,)
        Angles where the driving and resisting torques cross [rad], in
        increasing order from theta[0] (a crossing at theta[0] itself is
        reported there, not one cycle on).
    areas : ndarray, shape (m,)
        Pulse areas ∫ (T_r − T_d) dθ from each crossing to the next, the last
        one wrapping round to the first [J]: > 0 where the load takes more
        than the drive gives (the shaft slows), < 0 where it speeds up; they
        sum to zero (to rounding).
    accumulated : ndarray, shape (m,)
        Running sum of the areas from the first crossing [J] (Table 11-1).
    E : float
        Largest energy swing, max − min of the accumulated energy (0 included) [J].
    I_s : float
        System inertia on the shaft [kg·m²]: required, E / (C_s ω_avg²), or given;
        the flywheel itself may be smaller by the inertia of other rotors on the shaft.
    U : ndarray, shape (n,)
        Energy ∫ (T_r − T_d) dθ taken from the shaft from theta[0] to each sample [J].
    U_min : float
        Lowest value of that energy over the cycle (at a crossing) [J].
    driving, resisting : ndarray, shape (n,)
        The driving torque T_d and the resisting torque T_r [N·m].
    period : float
        Length of the cycle [rad] (2π, or 4π for a four-stroke engine).
    U_crossings : ndarray, shape (m,)
        The energy U at each crossing [J].
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
    driving: np.ndarray | None = None
    resisting: np.ndarray | None = None
    period: float = TURN
    U_crossings: np.ndarray | None = None

    def table(self) -> tuple[Pulse, ...]:
        """The energy table, one row per pulse from the first crossing (Norton Table 11-1)."""
        ends = np.append(self.crossings[1:], self.crossings[:1] + self.period)
        return tuple(Pulse(float(a), float(b), float(c), float(d))
                     for a, b, c, d in zip(self.crossings, ends, self.areas, self.accumulated))

    def speed_extremes(self) -> SpeedExtremes:
        """The fastest and slowest speeds and where they occur (Norton §11.11).

        The shaft is slowest after the largest energy has been taken from it
        (where U is largest) and fastest where U is smallest, each at a
        crossing of the two torques.
        """
        w_max, w_min = self.omega_avg * (1 + self.Cs / 2), self.omega_avg * (1 - self.Cs / 2)
        if not len(self.crossings) or self.E == 0:
            return SpeedExtremes(self.omega_avg, math.nan, self.omega_avg, math.nan)
        U = self.U_crossings if self.U_crossings is not None else self.U_min - np.min(
            np.concatenate([[0.0], self.accumulated[:-1]])) + np.concatenate([[0.0], self.accumulated[:-1]])
        # Equal extremes (a multi-cylinder engine repeats its pulses) differ only by rounding: take the first.
        tol = 1e-9 * self.E
        fast = int(np.flatnonzero(U <= U.min() + tol)[0])
        slow = int(np.flatnonzero(U >= U.max() - tol)[0])
        return SpeedExtremes(w_max, float(self.crossings[fast]), w_min, float(self.crossings[slow]))

    def acceleration(self) -> np.ndarray:
        """Angular acceleration of the shaft with the flywheel, α = (T_d − T_r)/I_s [rad/s²], shape (n,).

        The torques are the constant-speed ones, the approximation the sizing
        itself makes (the speed varies by C_s/2 either way).
        """
        if self.I_s == 0:
            return np.zeros(len(self.theta))
        return -(self.T - self.T_avg) / self.I_s

    def acceleration_extremes(self):
        """Largest and smallest angular acceleration [rad/s²] and where, as two :class:`Peak` (index into theta).

        The torques are linear between samples, so the extremes lie at samples.
        """
        a = self.acceleration()
        return peak_of(a, self.theta), peak_of(a, self.theta, lowest=True)

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
        :func:`graphkin.cycle.sweep`, pass through without ringing).

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
