"""Missions that begin and end at the surface, built here from an analytic truth, for
tests/python/test_surface_logs.py. Nothing here calls gesmi or reuses its simulator or
exporter: the truth, its readings, their errors, the geodesy and the NMEA sentences are
all computed in this file, with numpy.

The truth (local frame about ORIGIN: north, east, down; metres, seconds after EPOCH):

    p(t) = p0 + integral of w(s) ds from 0 to t + env(t) * wave(t)

- w(t) = R(roll, pitch, heading) (u(t), 0, 0) + (0, 0, b(t)): the robot's own motion, a
  forward speed u along its body x axis, rotated body -> world with
  R = Rz(heading) Ry(pitch) Rx(roll) (NED), plus the vertical jerk bursts b(t). Speed,
  pitch and heading follow smooth cosine ramps (C1 rates, bounded jerk), so the submerged
  jerk |w''| stays far below max_jerk = 1 m/s^3 except in the bursts.
- wave(t): the sea's motion at the surface, a sway of amplitude A_s along a horizontal
  direction and a heave of amplitude A_h in quadrature (orbital motion), period T; env(t)
  is 1 at the surface and 0 from before the first DVL reading to after the last one (the
  DVL has no bottom lock in the waves: its readings would break max_acceleration).
- integral of w: 8-point Gauss-Legendre on each 0.1 s between row times; every
  breakpoint of the piecewise definitions falls on a tenth of a second, so each piece is
  smooth (analytic) and the quadrature is exact to rounding.

Readings: a logger's semicolon CSV with ISO 8601 times at whole tenths after EPOCH (a
whole second), attitude in degrees at 10 Hz (heading from true north, in [0, 360)),
depth at 1 Hz (whole seconds), DVL (body frame) and DVL altitude at 10 Hz on the
submerged span only, and NMEA GGA (+ RMC for the date) fixes at whole seconds at the
surface. Each reading's error lies strictly inside the model's bound, the bound taken at
the reading for the relative ones (DVL, depth):

- "adversarial": 99.9 % of the bound, its sign the sign of the truth's second difference
  at that sample (for the DVL, of the world velocity w, mapped to the body components
  through R^T; a zero second difference takes +1, a constant bias): the truth then sits
  on the corner of the boxes where the trapezoid rule is weakest;
- "uniform": uniform in (-99.9 %, 99.9 %) of the bound (seeded);
- "against_motion" (depth only differs from adversarial): each depth reading 99.9 % of
  its bound on the side away from where the truth is heading next (-sign of the depth
  rate), the placement that tests the depth's rate bound between readings.
"""
import dataclasses
import datetime
import math

import numpy as np

UTC = datetime.timezone.utc
EPOCH = datetime.datetime(2026, 5, 14, 8, 0, 0, tzinfo=UTC)  # t = 0 of the truth: a whole second
ORIGIN = (48.0, -4.5)  # latitude, longitude (deg) of the local frame: --origin
RATE = 10  # rows per second

# The sensor model's defaults (docs/formats.md, model keys; the surface keys of the change).
MODEL = {
    "dvl_relative": 0.004, "dvl_absolute": 0.004,
    "roll": 1.75e-4, "pitch": 1.75e-4, "heading": 5.27e-3,
    "depth_absolute": 1.5, "depth_relative": 0.2, "altitude": 0.1,
    "gps_metres": 2.5,
    "max_attitude_rate": 0.05, "max_acceleration": 0.2, "max_depth_rate": 0.5, "max_altitude_rate": 1.0,
    "max_jerk": 1.0, "max_speed": 4.0,
    "surface_layer_depth": 1.0, "surface_max_jerk": 10.0, "surface_max_speed": 6.5,
}
FRACTION = 0.999  # of the bound, for the adversarial errors and the uniform draws' limit

# ----------------------------------------------------------------------------------------
# Geodesy (WGS84): the tangent plane at the origin, as docs/formats.md describes gesmi's
# frame (the projection on the plane tangent at the origin of the sea-surface point),
# written here independently; to_geodetic inverts it by Newton's method.

WGS84_A = 6378137.0
WGS84_F = 1.0 / 298.257223563
WGS84_E2 = WGS84_F * (2.0 - WGS84_F)


def ecef(lat_deg, lon_deg, h=0.0):
    lat, lon = np.radians(lat_deg), np.radians(lon_deg)
    n = WGS84_A / np.sqrt(1.0 - WGS84_E2 * np.sin(lat) ** 2)
    return np.stack([(n + h) * np.cos(lat) * np.cos(lon), (n + h) * np.cos(lat) * np.sin(lon),
                     (n * (1.0 - WGS84_E2) + h) * np.sin(lat)], axis=-1)


class Frame:
    def __init__(self, lat0, lon0):
        self.lat0, self.lon0 = lat0, lon0
        p, l = math.radians(lat0), math.radians(lon0)
        self.o = ecef(lat0, lon0)
        self.e = np.array([-math.sin(l), math.cos(l), 0.0])
        self.n = np.array([-math.sin(p) * math.cos(l), -math.sin(p) * math.sin(l), math.cos(p)])

    def to_local(self, lat, lon):
        d = ecef(lat, lon) - self.o
        return d @ self.n, d @ self.e

    def to_geodetic(self, north, east):
        north, east = np.asarray(north, float), np.asarray(east, float)
        p0 = math.radians(self.lat0)
        m0 = WGS84_A * (1 - WGS84_E2) / (1 - WGS84_E2 * math.sin(p0) ** 2) ** 1.5
        n0 = WGS84_A / math.sqrt(1 - WGS84_E2 * math.sin(p0) ** 2)
        lat = self.lat0 + np.degrees(north / m0)
        lon = self.lon0 + np.degrees(east / (n0 * math.cos(p0)))
        step = 1e-6  # deg, for the Jacobian
        for _ in range(8):
            n_, e_ = self.to_local(lat, lon)
            rn, re = north - n_, east - e_
            if np.max(np.abs(np.concatenate([np.ravel(rn), np.ravel(re)]))) < 1e-10:
                break
            nl, el = self.to_local(lat + step, lon)
            no, eo = self.to_local(lat, lon + step)
            a, b = (nl - n_) / step, (no - n_) / step
            c, d = (el - e_) / step, (eo - e_) / step
            det = a * d - b * c
            lat = lat + (d * rn - b * re) / det
            lon = lon + (-c * rn + a * re) / det
        return lat, lon

    def convergence(self, lat, lon):
        """The heading, in the frame, of true north at (lat, lon): a heading from true
        north there is the frame heading minus this angle."""
        p, l = np.radians(lat), np.radians(lon)
        north_there = np.stack([-np.sin(p) * np.cos(l), -np.sin(p) * np.sin(l), np.cos(p)], axis=-1)
        return np.arctan2(north_there @ self.e, north_there @ self.n)


FRAME = Frame(*ORIGIN)

# ----------------------------------------------------------------------------------------
# Smooth pieces: a cosine ramp 0 -> 1 over [t0, t0 + d] (C1) and its integral.


def ramp(t, t0, d):
    x = np.clip((np.asarray(t, float) - t0) / d, 0.0, 1.0)
    return 0.5 - 0.5 * np.cos(np.pi * x)


def ramp_integral(t, t0, d):
    t = np.asarray(t, float)
    x = np.clip((t - t0) / d, 0.0, 1.0)
    inside = d * (0.5 * x - np.sin(np.pi * x) / (2 * np.pi))
    return np.where(t <= t0 + d, inside, d / 2 + (t - t0 - d))


@dataclasses.dataclass
class Pulse:
    """amplitude * (ramp up over [t0, t0+d], hold h, ramp down over d)."""
    t0: float
    d: float
    h: float
    amplitude: float

    @property
    def end(self):
        return self.t0 + 2 * self.d + self.h

    def value(self, t):
        return self.amplitude * (ramp(t, self.t0, self.d) - ramp(t, self.t0 + self.d + self.h, self.d))

    def integral(self, t):
        return self.amplitude * (ramp_integral(t, self.t0, self.d) - ramp_integral(t, self.t0 + self.d + self.h, self.d))


def _burst_shape(x):
    """sin(2 pi x) sin^2(pi x) on [0, 1], 0 elsewhere: zero value, slope and curvature at
    both ends (bounded jerk), zero mean (no net depth change)."""
    x = np.asarray(x, float)
    inside = (x >= 0.0) & (x <= 1.0)
    return np.where(inside, np.sin(2 * np.pi * x) * np.sin(np.pi * x) ** 2, 0.0)


def _burst_shape_second_derivative_max():
    x = np.linspace(0.0, 1.0, 200001)
    # b = (sin 2 pi x - sin(4 pi x) / 2) / 2, so b'' = 2 pi^2 (2 sin 4 pi x - sin 2 pi x).
    return float(np.max(np.abs(2 * np.pi ** 2 * (2 * np.sin(4 * np.pi * x) - np.sin(2 * np.pi * x)))))


BURST_SHAPE_JERK = _burst_shape_second_derivative_max()

# ----------------------------------------------------------------------------------------
# Scenarios


@dataclasses.dataclass(frozen=True)
class Waves:
    name: str
    sway: float  # m, amplitude of the horizontal motion
    heave: float  # m, amplitude of the vertical motion
    period: float  # s
    direction: float = math.radians(30.0)  # of the sway, from north

    @property
    def omega(self):
        return 2 * math.pi / self.period

    @property
    def jerk(self):
        return math.hypot(self.sway, self.heave) * self.omega ** 3


# Waves of height H (crest to trough, amplitude H/2). The heave keeps its rate below
# max_depth_rate (0.5 m/s: the depth is read at 1 Hz and enclosed between readings with
# it); the harsh sway keeps the speed below surface_max_speed (6.5 m/s) with a jerk 8.5
# times the surface regime's bound (3 m of sway at 2 s would be 9.4 m/s).
CALM = Waves("calm_H0.30m_T2s", sway=0.15, heave=0.15, period=2.0)  # jerk 4.7 m/s^3, heave 0.47 m/s
HARSH = Waves("harsh_sway1.4m_T1.6s", sway=1.4, heave=0.08, period=1.6)  # jerk 85 m/s^3, 5.5 m/s
# A heave faster than max_depth_rate (0.97 m/s at 2 s, jerk 9.6 m/s^3): inside the
# surface regime's jerk bound, outside the depth channel's rate bound.
FAST_HEAVE = Waves("heave0.31m_T2s", sway=0.15, heave=0.31, period=2.0)  # about a surface depth of 0.45 m


@dataclasses.dataclass(frozen=True)
class Scenario:
    name: str
    profile: str  # "long", "short_tail", "edge_fixes"
    waves: Waves
    errors: str  # "adversarial", "uniform", "against_motion"
    burst_jerk: float = 0.0  # m/s^3; 0: no burst
    seed: int = 1
    surface_depth: float = 0.3


class Mission:
    """The truth of a scenario, its rows and readings, and the files that log them."""

    def __init__(self, sc):
        self.sc = sc
        wv = sc.waves
        profile = sc.profile
        if profile == "long":
            dvl0, pre_fixes = 45.0, [float(s) for s in range(2, 46)]  # the last one on the first DVL row
        elif profile == "short_tail":
            dvl0, pre_fixes = 20.0, [float(s) for s in range(1, 20)]
        elif profile == "edge_fixes":
            dvl0, pre_fixes = 10.0, [7.0]  # the first fix 3 s before the first DVL row
        else:
            raise ValueError(profile)
        self.dvl0 = dvl0
        self.heading0 = 5.9  # rad (338 deg): the first turn crosses north
        self.p0 = np.array([120.0, -80.0, sc.surface_depth])
        # The robot's own motion, relative to the first DVL row D.
        D = dvl0
        self.speed_up = (D + 1.0, 15.0)  # 0.1 -> 1.5 m/s
        self.dive = Pulse(D + 17.0, 8.0, 18.7, -0.22)  # pitch (rad): down 0.33 m/s
        s0 = self.dive.end + 0.3
        s0 = round(s0 * RATE) / RATE
        self.survey0 = s0
        self.turns = [Pulse(s0 + 15.0, 4.0, 19.3, 0.045), Pulse(s0 + 62.3, 4.0, 19.3, -0.045)]
        c0 = round((self.turns[1].end + 15.0) * RATE) / RATE
        self.climb = Pulse(c0, 8.0, 18.7, 0.22)
        self.speed_down = (self.climb.end + 1.0, 15.0)  # 1.5 -> 0.1 m/s
        self.dvl1 = float(math.ceil(self.speed_down[0] + self.speed_down[1] + 2.0))  # the last DVL row
        # Bursts: one on a line, one in a turn.
        self.bursts = []
        if sc.burst_jerk > 0:
            self.bursts = [s0 + 6.3, self.turns[0].t0 + 10.2]
        self.burst_amplitude = sc.burst_jerk / BURST_SHAPE_JERK
        # The surface phases and their fixes.
        if profile == "long":
            post_fixes = [self.dvl1 + s for s in range(1, 31)]
            self.last_row = post_fixes[-1] + 0.5
            self.env_down = (dvl0 - 9.0, 7.0)
        elif profile == "short_tail":
            post_fixes = [self.dvl1 + 1.0, self.dvl1 + 2.0]  # the last fix 2 s after the last DVL row
            self.last_row = post_fixes[-1] + 0.3
            self.env_down = (dvl0 - 9.0, 7.0)
        else:
            last_depth = self.dvl1 + 2.0
            # A fix 0.9 s after the last depth reading, 0.4 s after the last row of the log.
            post_fixes = [self.dvl1 + 1.0, self.dvl1 + 2.0, last_depth + 0.9]
            self.last_row = last_depth + 0.5
            self.env_down = (1.0, 7.0)
        self.env_up = (self.dvl1 + 0.5, 7.0)
        self.fix_times = np.array(pre_fixes + post_fixes)
        self.rows = np.arange(int(round(self.last_row * RATE)) + 1) / RATE  # whole tenths
        self.omega = wv.omega
        self.wave_phase = 0.7
        # The integral of the robot's own velocity at every tenth (the knots).
        self._knots = self.rows.copy()
        if self.fix_times[-1] > self._knots[-1]:
            extra = np.arange(int(round(self._knots[-1] * RATE)) + 1, int(round(self.fix_times[-1] * RATE)) + 3) / RATE
            self._knots = np.concatenate([self._knots, extra])
        seg = self._gauss(self._knots[:-1], self._knots[1:])
        self._cum = np.concatenate([np.zeros((1, 3)), np.cumsum(seg, axis=0)])
        self.rng = np.random.default_rng(sc.seed)
        self._readings()

    # -- the truth -----------------------------------------------------------------
    def speed(self, t):
        (a, d), (b, e) = self.speed_up, self.speed_down
        return 0.1 + 1.4 * ramp(t, a, d) - 1.4 * ramp(t, b, e)

    def env(self, t):
        (a, d), (b, e) = self.env_down, self.env_up
        return (1.0 - ramp(t, a, d)) + ramp(t, b, e)

    def roll(self, t):
        return 0.015 + 0.01 * self.env(t) * np.sin(self.omega * t + 0.3)

    def pitch(self, t):
        return self.dive.value(t) + self.climb.value(t) + 0.006 * self.env(t) * np.sin(self.omega * t + 1.0)

    def heading(self, t):
        """Heading in the local frame (rad, unwrapped)."""
        return (self.heading0 + sum(p.integral(t) for p in self.turns)
                + 0.02 * self.env(t) * np.sin(2 * np.pi * np.asarray(t, float) / 25.0))

    def burst(self, t):
        t = np.asarray(t, float)
        out = np.zeros_like(t)
        for tb in self.bursts:
            out = out + self.burst_amplitude * _burst_shape(t - tb)
        return out

    def velocity_world(self, t):
        """w(t): the robot's own velocity over ground, N x 3 (without the waves)."""
        t = np.asarray(t, float)
        u, th, ps = self.speed(t), self.pitch(t), self.heading(t)
        return np.stack([u * np.cos(ps) * np.cos(th), u * np.sin(ps) * np.cos(th), -u * np.sin(th) + self.burst(t)], axis=-1)

    def wave(self, t):
        t = np.asarray(t, float)
        w = self.sc.waves
        s = w.sway * np.sin(self.omega * t + self.wave_phase)
        h = w.heave * np.cos(self.omega * t + self.wave_phase)
        env = self.env(t)
        return np.stack([env * s * math.cos(w.direction), env * s * math.sin(w.direction), env * h], axis=-1)

    _GL_X, _GL_W = np.polynomial.legendre.leggauss(8)

    def _gauss(self, a, b):
        a, b = np.asarray(a, float), np.asarray(b, float)
        mid, half = (a + b) / 2, (b - a) / 2
        nodes = mid[:, None] + half[:, None] * self._GL_X[None, :]
        w = self.velocity_world(nodes.ravel()).reshape(nodes.shape + (3,))
        return half[:, None] * np.einsum("j,ijk->ik", self._GL_W, w)

    def position(self, t):
        """The true position (north, east, down) at times t (s after EPOCH), N x 3."""
        t = np.atleast_1d(np.asarray(t, float))
        k = np.clip(np.floor(t * RATE + 1e-9).astype(int), 0, len(self._knots) - 2)
        return self.p0 + self._cum[k] + self._gauss(self._knots[k], t) + self.wave(t)

    def rotation(self, t):
        """R = Rz(heading) Ry(pitch) Rx(roll), body -> local frame, N x 3 x 3."""
        t = np.asarray(t, float)
        ph, th, ps = self.roll(t), self.pitch(t), self.heading(t)
        cph, sph, cth, sth, cps, sps = np.cos(ph), np.sin(ph), np.cos(th), np.sin(th), np.cos(ps), np.sin(ps)
        r = np.empty(t.shape + (3, 3))
        r[..., 0, 0] = cps * cth
        r[..., 0, 1] = cps * sth * sph - sps * cph
        r[..., 0, 2] = cps * sth * cph + sps * sph
        r[..., 1, 0] = sps * cth
        r[..., 1, 1] = sps * sth * sph + cps * cph
        r[..., 1, 2] = sps * sth * cph - cps * sph
        r[..., 2, 0] = -sth
        r[..., 2, 1] = cth * sph
        r[..., 2, 2] = cth * cph
        return r

    def floor_depth(self, north, east):
        return 25.0 + 0.01 * (north - 120.0) - 0.005 * (east + 80.0)

    # -- rows and readings --------------------------------------------------------
    def _readings(self):
        m = MODEL
        t = self.rows
        n = len(t)
        k = np.round(t * RATE).astype(int)
        self.has_dvl = (t >= self.dvl0 - 1e-9) & (t <= self.dvl1 + 1e-9)
        self.has_depth = (k % RATE) == 0
        pos = self.position(t)
        self.truth_rows = pos
        lat, lon = FRAME.to_geodetic(pos[:, 0], pos[:, 1])
        gamma = FRAME.convergence(lat, lon)
        true_att = np.stack([self.roll(t), self.pitch(t), self.heading(t) - gamma], axis=1)
        rot = self.rotation(t)
        w = self.velocity_world(t)
        body = np.einsum("nji,nj->ni", rot, w)  # R^T w
        self.true_body = body
        self.true_attitude = true_att
        altitude = self.floor_depth(pos[:, 0], pos[:, 1]) - pos[:, 2]
        depth = pos[:, 2]
        mode = self.sc.errors

        def second_difference_sign(x):
            x = np.asarray(x, float)
            d2 = np.zeros_like(x)
            d2[1:-1] = x[:-2] - 2 * x[1:-1] + x[2:]
            d2[0], d2[-1] = d2[1], d2[-2]
            tol = 1e-10
            return np.where(np.abs(d2) > tol, np.sign(d2), 1.0)

        def fractions(sign, count):
            if mode == "uniform":
                return self.rng.uniform(-FRACTION, FRACTION, count)
            return FRACTION * sign

        # Attitude: absolute bounds.
        att_err = np.empty((n, 3))
        for i, key in enumerate(("roll", "pitch", "heading")):
            att_err[:, i] = fractions(second_difference_sign(true_att[:, i]), n) * m[key]
        self.attitude_reading = true_att + att_err
        # DVL: world second difference's signs, mapped to the body components.
        sw = np.zeros((n, 3))
        for j in range(3):
            d2 = np.zeros(n)
            d2[1:-1] = w[:-2, j] - 2 * w[1:-1, j] + w[2:, j]
            d2[0], d2[-1] = d2[1], d2[-2]
            sw[:, j] = np.where(np.abs(d2) > 1e-10, np.sign(d2), 0.0)
        sb = np.einsum("nji,nj->ni", rot, sw)
        sb = np.where(np.abs(sb) > 1e-12, np.sign(sb), 1.0)
        f = np.stack([fractions(sb[:, i], n) for i in range(3)], axis=1)
        self.dvl_error = relative_error(body, f, m["dvl_absolute"], m["dvl_relative"])
        self.dvl_reading = body + self.dvl_error
        # Altitude: absolute.
        self.altitude_error = fractions(second_difference_sign(altitude), n) * m["altitude"]
        self.altitude_reading = altitude + self.altitude_error
        self.true_altitude = altitude
        # Depth: relative to the reading.
        if mode == "against_motion":
            rate = (self.position(t + 1e-3)[:, 2] - self.position(t - 1e-3)[:, 2]) / 2e-3
            fd = FRACTION * np.where(rate > 0, -1.0, 1.0)
        else:
            fd = fractions(second_difference_sign(depth), n)
        self.depth_error = relative_error(depth, fd, m["depth_absolute"], m["depth_relative"])
        self.depth_reading = depth + self.depth_error
        self.true_depth = depth
        # GPS fixes: per axis, the sign of the second difference about the fix time.
        ft = self.fix_times
        around = self.position(np.concatenate([ft - 0.1, ft, ft + 0.1]))
        g = len(ft)
        fix_truth = around[g:2 * g, :2]
        d2 = around[:g, :2] - 2 * fix_truth + around[2 * g:, :2]
        sg = np.where(np.abs(d2) > 1e-10, np.sign(d2), 1.0)
        fg = np.stack([fractions(sg[:, i], g) for i in range(2)], axis=1)
        self.fix_truth = fix_truth
        self.fix_error = fg * m["gps_metres"]
        self.fix_local = fix_truth + self.fix_error
        self.fix_lat, self.fix_lon = FRAME.to_geodetic(self.fix_local[:, 0], self.fix_local[:, 1])

    # -- what a test needs --------------------------------------------------------
    @property
    def first_reading(self):
        return float(min(self.rows[0], self.fix_times[0]))

    @property
    def last_reading(self):
        return float(max(self.rows[-1], self.fix_times[-1]))

    @property
    def dvl_rows(self):
        return self.rows[self.has_dvl]

    def burst_windows(self):
        return [(tb, tb + 1.0) for tb in self.bursts]

    # -- files ----------------------------------------------------------------------
    def write(self, folder):
        """log.csv, map.yaml and gps.nmea in folder; returns their paths."""
        log, map_, nmea = (str(folder / name) for name in ("log.csv", "map.yaml", "gps.nmea"))
        cols = ["timestamp", "hdg_deg", "depth_m", "status", "dvl_x", "dvl_y", "dvl_z", "pitch_deg", "alt_m", "roll_deg"]
        lines = [";".join(cols)]
        for i, t in enumerate(self.rows):
            roll, pitch, heading = self.attitude_reading[i]
            dvl = [repr(float(x)) for x in self.dvl_reading[i]] if self.has_dvl[i] else ["", "", ""]
            lines.append(";".join([
                iso_tenth(t),
                repr(math.degrees(heading) % 360.0),
                repr(float(self.depth_reading[i])) if self.has_depth[i] else "",
                "SURFACE" if not self.has_dvl[i] else "SURVEY",
                *dvl,
                repr(math.degrees(pitch)),
                repr(float(self.altitude_reading[i])) if self.has_dvl[i] else "",
                repr(math.degrees(roll)),
            ]))
        with open(log, "w") as f:
            f.write("\n".join(lines) + "\n")
        with open(map_, "w") as f:
            f.write("# column map written by surface_motion.py\n"
                    "delimiter: \";\"\n"
                    "time:     {column: timestamp, format: iso8601}\n"
                    "roll:     {column: roll_deg,  unit: deg}\n"
                    "pitch:    {column: pitch_deg, unit: deg}\n"
                    "heading:  {column: hdg_deg,   unit: deg}\n"
                    "vx:       {column: dvl_x, unit: m/s}\n"
                    "vy:       {column: dvl_y, unit: m/s}\n"
                    "vz:       {column: dvl_z, unit: m/s}\n"
                    "altitude: {column: alt_m}\n"
                    "depth:    {column: depth_m}\n")
        with open(nmea, "w", newline="") as f:
            for t, lat, lon in zip(self.fix_times, self.fix_lat, self.fix_lon):
                when = EPOCH + datetime.timedelta(milliseconds=int(round(t * 1000)))
                f.write(rmc(when, float(lat), float(lon)) + "\r\n")
                f.write(gga(when, float(lat), float(lon)) + "\r\n")
        return log, map_, nmea


def relative_error(x, f, absolute, relative):
    """The error e with e = f (absolute + relative |x + e|): a fraction f of the bound
    taken at the reading x + e (|f| < 1, relative < 1)."""
    x, f = np.asarray(x, float), np.asarray(f, float)
    positive = f * (absolute + relative * x) / (1.0 - f * relative)  # when x + e >= 0
    negative = f * (absolute - relative * x) / (1.0 + f * relative)  # when x + e < 0
    e = np.where(x + positive >= 0.0, positive, negative)
    reading = x + e
    assert np.all(np.abs(e) < absolute + relative * np.abs(reading)), "error outside its bound"
    return e


def iso_tenth(t):
    """An ISO 8601 UTC time at a whole tenth of a second after EPOCH."""
    tenths = int(round(t * RATE))
    whole, tenth = divmod(tenths, RATE)
    return (EPOCH + datetime.timedelta(seconds=whole)).strftime("%Y-%m-%dT%H:%M:%S") + ".%dZ" % tenth


# NMEA 0183, written here: checksum = XOR of the characters between '$' and '*'.

def nmea_checksum(body):
    total = 0
    for c in body:
        total ^= ord(c)
    return "%02X" % total


def sentence(body):
    return "$" + body + "*" + nmea_checksum(body)


def nmea_angle(degrees, degree_digits, positive, negative):
    minutes = abs(degrees) * 60.0
    whole = int(minutes // 60)
    rest = minutes - 60 * whole
    return "%0*d%010.7f,%s" % (degree_digits, whole, rest, negative if degrees < 0 else positive)


def nmea_time(dt):
    return dt.strftime("%H%M%S.") + "%03d" % (dt.microsecond // 1000)


def gga(dt, lat, lon, quality=1):
    return sentence("GPGGA,%s,%s,%s,%d,09,0.8,0.0,M,50.1,M,," % (
        nmea_time(dt), nmea_angle(lat, 2, "N", "S"), nmea_angle(lon, 3, "E", "W"), quality))


def rmc(dt, lat, lon):
    return sentence("GPRMC,%s,A,%s,%s,0.2,30.0,%s,,,A" % (
        nmea_time(dt), nmea_angle(lat, 2, "N", "S"), nmea_angle(lon, 3, "E", "W"), dt.strftime("%d%m%y")))


# ----------------------------------------------------------------------------------------
# What the truth does, measured on a fine grid: the promise's envelope is checked against it


def motion_extremes(mission, h=0.01):
    """Largest speeds, jerks and rates of the truth, by regime, from finite differences
    of the position on a grid of step h. A time counts as "surface" where the true depth
    is within the surface layer (then the solver's possible depths reach it as well)."""
    m = mission
    t = np.arange(m.first_reading, m.last_reading + h / 2, h)
    p = m.position(np.concatenate([t - 2 * h, t - h, t, t + h, t + 2 * h])).reshape(5, len(t), 3)
    velocity = (p[3] - p[1]) / (2 * h)
    jerk = (p[4] - 2 * p[3] + 2 * p[1] - p[0]) / (2 * h ** 3)
    depth = p[2][:, 2]
    surface = depth <= MODEL["surface_layer_depth"]
    in_burst = np.zeros(len(t), dtype=bool)
    for a, b in m.burst_windows():
        in_burst |= (t >= a - 2 * h) & (t <= b + 2 * h)
    dvl_on = (t >= m.dvl0) & (t <= m.dvl1)
    speed = np.linalg.norm(velocity, axis=1)
    jerk_norm = np.linalg.norm(jerk, axis=1)
    # Rates of the attitude (as read: heading from true north) and of the DVL components.
    def rate(f):
        return (f(t + h) - f(t - h)) / (2 * h)

    def attitude(tt):
        pos = m.position(tt)
        lat, lon = FRAME.to_geodetic(pos[:, 0], pos[:, 1])
        return np.stack([m.roll(tt), m.pitch(tt), m.heading(tt) - FRAME.convergence(lat, lon)], axis=1)

    def body(tt):
        return np.einsum("nji,nj->ni", m.rotation(tt), m.velocity_world(tt))

    def altitude(tt):
        pos = m.position(tt)
        return m.floor_depth(pos[:, 0], pos[:, 1]) - pos[:, 2]

    att_rate = np.abs(rate(attitude)).max(axis=0)
    dvl_rate = np.abs(rate(body))
    alt_rate = np.abs(rate(altitude))
    depth_rate = np.abs(velocity[:, 2])

    def peak(x, mask):
        return float(np.max(x[mask])) if np.any(mask) else 0.0

    return {
        "speed_surface": peak(speed, surface),
        "speed_submerged": peak(speed, ~surface),
        "jerk_surface": peak(jerk_norm, surface & ~in_burst),
        "jerk_submerged": peak(jerk_norm, ~surface & ~in_burst),
        "jerk_burst": peak(jerk_norm, in_burst),
        "attitude_rate": float(att_rate.max()),
        "dvl_rate": peak(dvl_rate.max(axis=1), dvl_on & ~in_burst),
        "depth_rate": float(depth_rate.max()),
        "altitude_rate": peak(alt_rate, dvl_on),
        "min_depth": float(depth.min()),
        "max_depth": float(depth.max()),
    }
