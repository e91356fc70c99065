"""The harness's metrics (scenarios/README.md, Metrics), computed on a pymunk space.

Same definitions, same channels, same sampling as harness/.../metrics/*.java. Energy is computed here
from mass, moment and velocity: pymunk's Body.kinetic_energy omits the factor 1/2.
"""

from __future__ import annotations

import math

import pymunk

from .build import Built, flatten, local_aabb
from .scene import LANDSCAPE, group_matches

_TYPE_ORDER = {pymunk.Circle: 0, pymunk.Segment: 1, pymunk.Poly: 2}

try:  # Chipmunk's C functions through pymunk's cffi module: 3x faster than the properties
    from pymunk._chipmunk import lib as _cp

    def _read(body):
        h = body._body
        p = _cp.cpBodyGetPosition(h)
        v = _cp.cpBodyGetVelocity(h)
        return (p.x, p.y, _cp.cpBodyGetAngle(h), v.x, v.y, _cp.cpBodyGetAngularVelocity(h))

    def _collide_distances(a, b):
        found = _cp.cpShapesCollide(a._shape, b._shape)
        return [found.points[i].distance for i in range(found.count)]
except (ImportError, AttributeError):  # pragma: no cover - other pymunk builds
    def _read(body):
        p, v = body.position, body.velocity
        return (p.x, p.y, body.angle, v.x, v.y, body.angular_velocity)

    def _collide_distances(a, b):
        try:
            return [p.distance for p in a.shapes_collide(b).points]
        except AssertionError:  # pymunk asserts when the shapes do not touch
            return []


class Snapshot:
    """The state (x, y, angle, vx, vy, ω) of every dynamic body, read once per tick for all metrics."""

    def __init__(self, built: Built):
        self.built = built
        dyn = built.dynamic()
        self.names = [n for n, _ in dyn]
        self.bodies = [b for _, b in dyn]
        self.index = {n: i for i, n in enumerate(self.names)}
        self.mass = [b.mass for b in self.bodies]
        self.moment = [b.moment for b in self.bodies]
        self.rotatable = [built.specs[n].state.rotatable for n in self.names]
        self.gravity = [built.specs[n].state.gravity for n in self.names]
        self.tick = None
        self.states = []

    def at(self, tick):
        if tick != self.tick:
            self.states = [_read(b) for b in self.bodies]
            self.tick = tick
        return self.states


def _distance(a, b):
    """|b - a|, inf rather than an OverflowError once a run has blown up (pymunk's Vec2d.length squares
    with **, which raises on overflow, so a stability map would read "error" instead of the blow-up)."""
    return math.hypot(b.x - a.x, b.y - a.y)


def create(spec, built: Built, snapshot: Snapshot):
    return {"energy": Energy, "linearMomentum": LinearMomentum, "angularMomentum": AngularMomentum,
            "penetration": Penetration, "constraintError": ConstraintError, "tunnelling": Tunnelling,
            "stability": Stability, "particles": Particles, "sleeping": Sleeping,
            "jointLimits": JointLimits}[spec.kind](built, spec, snapshot)


class Metric:
    def after_tick(self, tick):
        pass

    def sample(self, tick):
        raise NotImplementedError


class Energy(Metric):
    """kinetic Σ ½m|v|² + ½Iω² (no rotational term for non-rotatable bodies); potential Σ −m(g·r) over
    gravity-affected dynamic bodies; total = kinetic + potential + spring potential Σ ½k(d − d₀)²."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.built = built
        self.snap = snapshot

    def sample(self, tick):
        gx, gy = self.built.space.gravity
        kinetic = potential = 0.0
        s = self.snap
        for (x, y, _, vx, vy, w), m, inertia, rot, grav in zip(s.at(tick), s.mass, s.moment, s.rotatable,
                                                               s.gravity):
            kinetic += 0.5 * m * (vx * vx + vy * vy)
            if rot and w != 0:
                kinetic += 0.5 * inertia * w * w
            if grav:
                potential -= m * (gx * x + gy * y)
        springs = 0.0
        for s in self.built.springs:
            d = _distance(s.a.local_to_world(s.anchor_a), s.b.local_to_world(s.anchor_b))
            stretch = d - s.rest  # x * x gives inf on overflow where x ** 2 raises OverflowError
            springs += 0.5 * s.stiffness * stretch * stretch
        return [kinetic, potential, kinetic + potential + springs]


class LinearMomentum(Metric):
    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.snap = snapshot

    def sample(self, tick):
        px = py = 0.0
        for st, m in zip(self.snap.at(tick), self.snap.mass):
            px += m * st[3]
            py += m * st[4]
        return [px, py]


class AngularMomentum(Metric):
    """Σ Iω + m((x − px)vy − (y − py)vx) about spec.about; positive toward growing angles."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.snap = snapshot
        self.px, self.py = spec.about

    def sample(self, tick):
        total = 0.0
        s = self.snap
        for (x, y, _, vx, vy, w), m, inertia, rot in zip(s.at(tick), s.mass, s.moment, s.rotatable):
            spin = inertia * w if rot and w != 0 else 0.0
            total += spin + m * ((x - self.px) * vy - (y - self.py) * vx)
        return [total]


class Penetration(Metric):
    """For every pair the space holds a contact (arbiter) for, the narrow phase is run again on the
    current poses; points = contact points with distance < 0, max = the deepest, mean = their mean.

    The pairs are those between a `begin` and a `separate` callback (Chipmunk's touching arbiters).

    Each overlapping point also goes to its pair of bodies, named by the scene (the landscape is the party
    `landscape`, numbered after every body): the run's figures per pair (`pairs()`, harness PairPenetration)
    and the channels of the scene's pair filters (`between`)."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.pairs = {}
        names = list(built.bodies)
        self.names = names + [LANDSCAPE]
        self.party = {}
        for i, n in enumerate(names):
            for shape in built.shapes.get(n, ()):
                self.party[id(shape)] = i
        for shape in built.shapes.get("$landscape", ()):
            self.party[id(shape)] = len(names)
        self.filters = [([group_matches(a, n) for n in self.names], [group_matches(b, n) for n in self.names])
                        for a, b in getattr(spec, "pairs", ())]
        self.run = {}  # (party, party) -> [deepest, sum of depths, points, samples]

        def begin(arbiter, space, data):
            a, b = arbiter.shapes
            # shapes_collide gets the distance's sign wrong unless the shapes come in Chipmunk's type
            # order (circle, segment, polygon): Chipmunk flips the normal but not the points.
            if _TYPE_ORDER[type(a)] > _TYPE_ORDER[type(b)]:
                a, b = b, a
            self.pairs[(id(a), id(b))] = (a, b)

        def separate(arbiter, space, data):
            a, b = arbiter.shapes
            self.pairs.pop((id(a), id(b)), None)
            self.pairs.pop((id(b), id(a)), None)

        built.space.on_collision(None, None, begin=begin, separate=separate)

    def sample(self, tick):
        deepest = total = 0.0
        points = 0
        sample = {}
        for a, b in self.pairs.values():
            pa, pb = self.party.get(id(a)), self.party.get(id(b))
            key = (min(pa, pb), max(pa, pb)) if pa is not None and pb is not None else None
            for d in _collide_distances(a, b):
                if d < 0:
                    points += 1
                    total -= d
                    if -d > deepest:
                        deepest = -d
                    if key is not None:
                        s = sample.setdefault(key, [0.0, 0.0, 0])
                        s[0] = max(s[0], -d)
                        s[1] -= d
                        s[2] += 1
        for key, s in sample.items():
            r = self.run.setdefault(key, [0.0, 0.0, 0, 0])
            r[0] = max(r[0], s[0])
            r[1] += s[1]
            r[2] += s[2]
            r[3] += 1
        out = [deepest, total / points if points else 0.0, float(points)]
        for in_a, in_b in self.filters:
            fmax = fsum = 0.0
            fpoints = 0
            for (pa, pb), s in sample.items():
                if (in_a[pa] and in_b[pb]) or (in_b[pa] and in_a[pb]):
                    fmax = max(fmax, s[0])
                    fsum += s[1]
                    fpoints += s[2]
            out.extend([fmax, fsum / fpoints if fpoints else 0.0, float(fpoints)])
        return out

    def pair_figures(self):
        """Every pair that overlapped at a sample, deepest first (then by name), as the trace writes them."""
        out = [{"a": self.names[pa], "b": self.names[pb], "max": r[0], "mean": r[1] / r[2], "samples": r[3]}
               for (pa, pb), r in self.run.items()]
        out.sort(key=lambda p: (-p["max"], p["a"], p["b"]))
        return out


def penetration_pairs(metrics):
    """The penetration metric's pairs (for the trace's penetrationPairs), or None without one."""
    for m in metrics:
        if isinstance(m, Penetration):
            return m.pair_figures()
    return None


class ConstraintError(Metric):
    """Distance between the two anchors of each pin and revolute joint, |d − d₀| of each rigid link or rigid
    distance joint, and how far a rope or ranged distance joint lies outside its range (px)."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.links = built.links

    def sample(self, tick):
        errors = []
        for link in self.links:
            if link.kind == "line":
                # How far b's anchor lies off the axis through a's (the wheel and prismatic rows).
                pa, pb = link.a.local_to_world(link.anchor_a), link.b.local_to_world(link.anchor_b)
                axis = pymunk.Vec2d(*link.axis).rotated(link.a.angle)
                errors.append(abs((pb - pa).cross(axis)))
                continue
            d = _distance(link.a.local_to_world(link.anchor_a), link.b.local_to_world(link.anchor_b))
            if link.kind == "range":
                errors.append(max(0.0, link.rest - d, d - link.upper))
            else:
                errors.append(d if link.kind == "pin" else abs(d - link.rest))
        if not errors:
            return [0.0, 0.0]
        return [max(errors), sum(errors) / len(errors)]


class JointLimits(Metric):
    """jointLimits.angle: how far the worst limited revolute joint lies outside its limits (rad);
    .translation: how far the worst limited prismatic joint lies outside its limits (px). A prismatic
    joint with a motor is not mapped (unsupported, so such a scene is not judged)."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.hinges = built.hinges
        self.slides = built.slides

    def sample(self, tick):
        worst = 0.0
        for h in self.hinges:
            angle = h.b.angle - h.a.angle - h.ref
            worst = max(worst, h.lower - angle, angle - h.upper)
        farthest = 0.0
        for link, lower, upper in self.slides:
            pa, pb = link.a.local_to_world(link.anchor_a), link.b.local_to_world(link.anchor_b)
            t = (pb - pa).dot(pymunk.Vec2d(*link.axis).rotated(link.a.angle))
            farthest = max(farthest, lower - t, t - upper)
        return [worst, farthest]


def _orient(ax, ay, bx, by, cx, cy):
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


def crosses(px, py, qx, qy, ax, ay, bx, by):
    """Whether the path p→q strictly crosses the segment a→b (harness Segments.cross)."""
    d1 = _orient(ax, ay, bx, by, px, py)
    d2 = _orient(ax, ay, bx, by, qx, qy)
    if not ((d1 < 0 and d2 > 0) or (d1 > 0 and d2 < 0)):
        return False
    d3 = _orient(px, py, qx, qy, ax, ay)
    d4 = _orient(px, py, qx, qy, bx, by)
    return (d3 <= 0 and d4 >= 0) or (d3 >= 0 and d4 <= 0)


def _side(ax, ay, bx, by, px, py):
    o = _orient(ax, ay, bx, by, px, py)
    return (o > 0) - (o < 0)


class Tunnelling(Metric):
    """Times, so far, the centre of a watched body crossed a wall line within one tick. A wall body's
    line is the long axis of its shape's bounding box (at angle 0) through the box centre, moving with
    the body; a centre landing on the line counts as still on its previous side."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.snap = snapshot
        watched = list(spec.bodies) if spec.bodies else [n for n, _ in built.dynamic()]
        self.walls = []
        for w in spec.walls:
            if isinstance(w, str):
                x0, y0, x1, y1 = local_aabb(flatten(built.specs[w].shape))
                cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
                line = ((x0, cy), (x1, cy)) if x1 - x0 >= y1 - y0 else ((cx, y0), (cx, y1))
                self.walls.append((built.bodies[w], line))
                if w in watched:
                    watched.remove(w)
            else:
                self.walls.append((None, w))
        # Watched bodies by index in the snapshot (a static body never moves: its own position). With
        # points: shape, each body's polygon vertices (and off-centre circle centres) too, as (body, local point).
        self.watched = []
        self.owner = []
        for n in watched:
            self.watched.append(snapshot.index.get(n, built.bodies[n]))
            self.owner.append(n)
            if spec.whole_shape:
                for piece in flatten(built.specs[n].shape):
                    points = piece[1] if piece[0] == "poly" else ([piece[1]] if tuple(piece[1]) != (0.0, 0.0) else [])
                    for v in points:
                        self.watched.append((built.bodies[n], tuple(v)))
                        self.owner.append(n)
        self.previous = [[self.position(w, None) for w in self.watched] for _ in self.walls]
        self.count = 0

    def position(self, w, states):
        if isinstance(w, tuple):
            p = w[0].local_to_world(w[1])
            return p.x, p.y
        if isinstance(w, int):
            st = states[w] if states is not None else _read(self.snap.bodies[w])
            return st[0], st[1]
        return tuple(w.position)

    def after_tick(self, tick):
        states = self.snap.at(tick)
        for k, (body, line) in enumerate(self.walls):
            if body is None:
                (ax, ay), (bx, by) = line
            else:
                ax, ay = body.local_to_world(line[0])
                bx, by = body.local_to_world(line[1])
            prev = self.previous[k]
            counted = None  # one count per body and tick, however many of its points crossed
            for i, w in enumerate(self.watched):
                x, y = self.position(w, states)
                px, py = prev[i]
                if crosses(px, py, x, y, ax, ay, bx, by) and counted != self.owner[i]:
                    self.count += 1
                    counted = self.owner[i]
                if _side(ax, ay, bx, by, x, y) != 0:
                    prev[i] = (x, y)

    def sample(self, tick):
        return [float(self.count)]


def _finite(x, y, a, vx, vy, w):
    return math.isfinite(x + y + a + vx + vy + w) or all(map(math.isfinite, (x, y, a, vx, vy, w)))


class Stability(Metric):
    """Worst values since the previous sample: largest |v|, largest |ω|, most non-finite bodies."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.snap = snapshot
        self.max_speed = self.max_angular = 0.0
        self.non_finite = 0
        self.after_tick(0)

    def after_tick(self, tick):
        bad = 0
        speed2 = self.max_speed * self.max_speed
        angular = self.max_angular
        for st in self.snap.at(tick):
            if not _finite(*st):
                bad += 1
                continue
            v2 = st[3] * st[3] + st[4] * st[4]
            if v2 > speed2:
                speed2 = v2
            if abs(st[5]) > angular:
                angular = abs(st[5])
        self.max_speed = math.sqrt(speed2)
        self.max_angular = angular
        self.non_finite = max(self.non_finite, bad)

    def sample(self, tick):
        out = [self.max_speed, self.max_angular, float(self.non_finite)]
        self.max_speed = self.max_angular = 0.0
        self.non_finite = 0
        self.after_tick(tick)
        return out


class Particles(Metric):
    """particles.count and particles.outside: pymunk has no particle emitters (MAPPING.md, Particles), so
    both columns are null (NaN) here; the channels exist so the two traces still line up, and the
    comparison has no figure for them."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        pass

    def sample(self, tick):
        return [math.nan, math.nan]


class Sleeping(Metric):
    """sleeping.count = dynamic bodies pymunk has put to sleep (Body.is_sleeping); sleeping.fraction = that
    over the dynamic bodies (0 without any). Both 0 while the scene's world.sleeping is off."""

    def __init__(self, built: Built, spec, snapshot: Snapshot):
        self.bodies = snapshot.bodies

    def sample(self, tick):
        n = sum(1 for b in self.bodies if b.is_sleeping)
        return [float(n), n / len(self.bodies) if self.bodies else 0.0]
