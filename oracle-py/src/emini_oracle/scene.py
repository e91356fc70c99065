"""Reads a scenario file (YAML or JSON, scenarios/scenario.schema.json) into a Scene.

This mirrors the harness's loader (harness/.../load/ScenarioReader.java): the same defaults (the
original manual's), the same generator expansion, the same rules for which bodies are recorded and
which metrics exist. A scene read here and one read by the harness describe the same world; the
tests check that body by body against the harness's `expand` command.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

import yaml
from jsonschema import Draft202012Validator

from . import generators

ELEMENT_SECTIONS = ("joints", "springs", "motors", "landscape", "particles")

METRIC_CHANNELS = {
    "energy": ["energy.kinetic", "energy.potential", "energy.total"],
    "linearMomentum": ["momentum.x", "momentum.y"],
    "angularMomentum": ["angularMomentum"],
    "penetration": ["penetration.max", "penetration.mean", "penetration.points"],
    "constraintError": ["constraintError.max", "constraintError.mean"],
    "tunnelling": ["tunnelling.count"],
    "stability": ["stability.maxSpeed", "stability.maxAngularSpeed", "stability.nonFinite"],
    "particles": ["particles.count", "particles.outside"],
    "sleeping": ["sleeping.count", "sleeping.fraction"],
    "jointLimits": ["jointLimits.angle", "jointLimits.translation"],
}
BODY_QUANTITIES = ("x", "y", "angle", "vx", "vy", "omega", "speed", "displacement", "turn")
LANDSCAPE = "landscape"  # the landscape as one party of a penetration pair
PAIR_QUANTITIES = ("max", "mean", "points")


def pair_channel(quantity, a, b):
    """penetration.Q narrowed to the pairs between a and b (harness Channels.pair)."""
    return f"penetration.{quantity}({a}, {b})"


def base_channel(channel):
    """A channel without its pair filter (harness Channels.base)."""
    open_at = channel.find("(")
    if channel.startswith("penetration.") and open_at > 0 and channel.endswith(")"):
        return channel[:open_at]
    return channel


class SceneError(Exception):
    """The file cannot be read, is invalid against the schema, or breaks a rule the schema cannot state."""


@dataclass
class Shape:
    kind: str  # circle, rectangle, regularPolygon, polygon, multiShape
    radius: float = 0.0
    width: float = 0.0
    height: float = 0.0
    sides: int = 0
    vertices: list = field(default_factory=list)  # [[x, y], ...]
    parts: list = field(default_factory=list)  # [(Shape, ox, oy, angle), ...]
    mass: float = 1.0
    friction: float = 0.25
    elasticity: float = 0.0
    name: Optional[str] = None

    def size(self):
        """Bounding box size at angle 0, as the generators' default spacing uses it."""
        if self.kind in ("circle", "regularPolygon"):
            return [2 * self.radius, 2 * self.radius]
        if self.kind == "rectangle":
            return [self.width, self.height]
        if self.kind == "polygon":
            xs = [v[0] for v in self.vertices]
            ys = [v[1] for v in self.vertices]
            return [max(xs) - min(xs), max(ys) - min(ys)]
        return None

    def to_json(self):
        out = {"type": self.kind, "mass": self.mass, "friction": self.friction, "elasticity": self.elasticity}
        if self.kind in ("circle", "regularPolygon"):
            out["radius"] = self.radius
        if self.kind == "regularPolygon":
            out["sides"] = self.sides
        if self.kind == "rectangle":
            out["width"] = self.width
            out["height"] = self.height
        if self.kind == "polygon":
            out["vertices"] = [list(v) for v in self.vertices]
        if self.kind == "multiShape":
            out["parts"] = [{"shape": s.to_json(), "offset": [ox, oy], "angle": a} for s, ox, oy, a in self.parts]
        return out


@dataclass
class BodyState:
    static: bool = False
    angle: float = 0.0
    vx: float = 0.0
    vy: float = 0.0
    angular_velocity: float = 0.0
    rotatable: bool = True
    interacting: bool = True
    gravity: bool = True
    layers: tuple = ()
    kinematic: bool = False
    # Box2D's filter, as unsigned 32-bit sets: category bit 0, every mask bit, group 0 by default.
    categories: int = 1
    mask: int = 0xFFFFFFFF
    group: int = 0
    sleeping_allowed: bool = True
    sensor: bool = False

    def with_angle(self, angle):
        return dataclasses.replace(self, angle=angle)

    def default_filter(self):
        return self.categories == 1 and self.mask == 0xFFFFFFFF and self.group == 0


@dataclass
class Body:
    name: str
    shape: Shape
    x: float
    y: float
    state: BodyState

    def to_json(self):
        s = self.state
        out = {"name": self.name, "position": [self.x, self.y], "static": s.static, "angle": s.angle,
               "velocity": [s.vx, s.vy], "angularVelocity": s.angular_velocity, "rotatable": s.rotatable,
               "interacting": s.interacting, "gravity": s.gravity, "sleepingAllowed": s.sleeping_allowed,
               "layers": list(s.layers),
               "shape": self.shape.to_json()}
        if s.kinematic:
            out["kinematic"] = True
        if s.sensor:
            out["sensor"] = True
        if not s.default_filter():
            out["categories"] = _bit_list(s.categories)
            out["mask"] = _bit_list(s.mask)
            out["group"] = s.group
        return out


@dataclass
class World:
    timestep: float = 1.0 / 20
    iterations: int = 10
    dynamic_iterations: bool = False
    gravity: tuple = (0.0, 100.0)
    damping_lateral: float = 0.0
    damping_rotational: float = 0.0
    simulation_area: Optional[dict] = None
    solver: dict = field(default_factory=dict)
    # world.sleeping: None when off, else the tolerances the scene gives (linearTolerance,
    # angularTolerance, timeToSleep; missing ones take the engine's defaults)
    sleeping: Optional[dict] = None


@dataclass
class Action:
    at: float
    kind: str  # impulse, angularImpulse, force, torque, velocity, gravity
    body: Optional[str]
    vector: Optional[tuple]
    point: Optional[tuple]
    value: float  # angular impulse, torque or angular velocity (NaN when not given)
    duration: float  # NaN: one tick


@dataclass
class MetricSpec:
    kind: str
    about: tuple = (0.0, 0.0)
    walls: list = field(default_factory=list)  # str (body name) or ((x, y), (x, y))
    bodies: list = field(default_factory=list)
    whole_shape: bool = False  # tunnelling points: shape (every vertex watched, not only the centre)
    pairs: list = field(default_factory=list)  # penetration: the pair filters (a, b) expectations read (between)

    def channels(self):
        return METRIC_CHANNELS[self.kind] + [pair_channel(q, a, b) for a, b in self.pairs for q in PAIR_QUANTITIES]


@dataclass
class Record:
    every: float  # NaN: every tick
    metrics: list  # [MetricSpec], listed ones first, then those expectations need
    bodies: Optional[str]  # "all", "dynamic", "none", or None with body_names
    body_names: list
    trace: bool


@dataclass
class Scene:
    name: str
    file: str
    description: str
    category: Optional[str]
    world: World
    shapes: dict
    bodies: list
    actions: list
    elements: dict  # section name -> JSON as written (joints, springs, motors, landscape, particles)
    duration: float
    record: Record
    expect: list  # raw expectation dicts
    closed_form: Optional[dict]
    oracle: Optional[dict]
    raw: dict

    @property
    def ticks(self):
        return int(math.ceil(self.duration / self.world.timestep - 1e-9))

    @property
    def sampling_ticks(self):
        every = self.record.every
        return 1 if math.isnan(every) else max(1, java_round(every / self.world.timestep))

    def sample_ticks(self):
        """The ticks at which the state is sampled: 0, every `sampling_ticks`, and the last one."""
        n, every = self.ticks, self.sampling_ticks
        out = [0]
        for k in range(n):
            if (k + 1) % every == 0 or k + 1 == n:
                out.append(k + 1)
        return out

    def body(self, name):
        for b in self.bodies:
            if b.name == name:
                return b
        return None

    def recorded_bodies(self):
        """Names of the bodies whose state is sampled, in creation order, as the harness's runner picks them."""
        r = self.record
        out = []
        if r.bodies is None:
            out.extend(r.body_names)
        elif r.bodies == "all":
            out.extend(b.name for b in self.bodies)
        elif r.bodies == "dynamic":
            out.extend(b.name for b in self.bodies if not b.state.static)
        for e in self.expect:
            ch = e.get("metric", e.get("closedForm"))
            bc = body_channel(ch) if isinstance(ch, str) else None
            extra = [x[0] for x in map(body_channel, extra_channels(e)) if x is not None]
            for name in ([e["body"]] if "body" in e else []) + ([bc[0]] if bc is not None else []) + extra:
                # A group (* for any text) records its members in creation order, as the harness's runner.
                members = [b.name for b in self.bodies if group_matches(name, b.name)] if "*" in name else [name]
                out.extend(m for m in members if m not in out)
        if any("*" in n for e in self.expect for n in _expectation_bodies(e)):
            # With a group, every recorded body in creation order, as the harness's runner.
            order = [b.name for b in self.bodies]
            out.sort(key=order.index)
        return out

    def expanded_json(self):
        """The scene as the harness's `expand` command prints it."""
        return {"scene": self.name, "timestep": self.world.timestep, "ticks": self.ticks,
                "samplingTicks": self.sampling_ticks, "bodies": [b.to_json() for b in self.bodies]}


def java_round(x):
    """Java's Math.round: floor(x + 0.5)."""
    return int(math.floor(x + 0.5))


def _expectation_bodies(e):
    ch = e.get("metric", e.get("closedForm"))
    bc = body_channel(ch) if isinstance(ch, str) else None
    return ([e["body"]] if "body" in e else []) + ([bc[0]] if bc is not None else [])


def extra_channels(e):
    """The channels an expectation reads besides its own: minus and relativeTo's metric."""
    out = [e["minus"]] if isinstance(e.get("minus"), str) else []
    rel = e.get("relativeTo")
    if isinstance(rel, dict) and isinstance(rel.get("metric"), str):
        out.append(rel["metric"])
    return out


def group_matches(pattern, name):
    """Whether a body name matches an expectation's group: * any text, everything else literal."""
    return re.fullmatch(".*".join(re.escape(p) for p in pattern.split("*")), name) is not None


def body_channel(channel):
    """For body.NAME.Q: (NAME, Q); otherwise None (as harness Channels.bodyChannel)."""
    if channel is None or not channel.startswith("body."):
        return None
    dot = channel.rfind(".")
    if dot <= 5:
        return None
    q = channel[dot + 1:]
    return (channel[5:dot], q) if q in BODY_QUANTITIES else None


def metric_of(channel):
    channel = base_channel(channel) if isinstance(channel, str) else channel
    for kind, chans in METRIC_CHANNELS.items():
        if channel in chans:
            return kind
    return None


# ------------------------------------------------------------------------------------------------
# Files

def find_schema(start: Path) -> Path:
    """scenarios/scenario.schema.json in the folder of `start` or above (as the harness looks for it)."""
    for d in [start.resolve(), *start.resolve().parents]:
        candidate = d / "scenarios" / "scenario.schema.json"
        if candidate.is_file():
            return candidate
    raise SceneError("cannot find scenarios/scenario.schema.json here or above; give --schema")


def scene_files(paths):
    """Scene files under paths (folders recursively, sorted), as the harness's ScenarioFiles.expand."""
    out = []
    for p in map(Path, paths):
        if p.is_dir():
            found = [f for f in p.rglob("*") if f.is_file() and is_scene(f)]
            out.extend(sorted(found, key=lambda f: str(f)))
        else:
            out.append(p)
    return out


def is_scene(f: Path):
    n = f.name
    return n.endswith((".yaml", ".yml", ".json")) and not n.endswith((".schema.json", ".trace.json", ".expect.yaml"))


class Loader:
    """Loads scenes against one schema; scene ids are paths relative to the schema's folder."""

    def __init__(self, schema_file: Path):
        self.schema_file = Path(schema_file)
        self.root = self.schema_file.resolve().parent
        with open(self.schema_file, encoding="utf-8") as f:
            self.validator = Draft202012Validator(json.load(f))

    def default_name(self, file: Path):
        a = file.resolve()
        try:
            rel = a.relative_to(self.root).as_posix()
        except ValueError:
            rel = a.name
        dot = rel.rfind(".")
        return rel[:dot] if dot > 0 else rel

    def load(self, file) -> Scene:
        file = Path(file)
        try:
            text = file.read_text(encoding="utf-8")
        except OSError as e:
            raise SceneError(f"{file}: cannot read: {e}") from e
        return self.load_text(str(file), text, self.default_name(file))

    def load_text(self, shown: str, text: str, name: str) -> Scene:
        try:
            # JSON is YAML for the documents we write: one parser for both, as the harness does.
            root = yaml.load(text, Loader=_SceneYamlLoader)
        except yaml.YAMLError as e:
            raise SceneError(f"{shown}: cannot parse: {e}") from e
        if not isinstance(root, dict):
            raise SceneError(f"{shown}: a scene is a mapping")
        errors = sorted(self.validator.iter_errors(root), key=lambda e: list(e.absolute_path))
        if errors:
            lines = [f"{shown}: {json_path(e.absolute_path)}: {e.message}" for e in errors]
            raise SceneError("\n".join(lines))
        return _Reader(shown).read(root, name)


class _SceneYamlLoader(yaml.SafeLoader):
    """PyYAML's safe loader, but reading 1e-5 as a number as SnakeYAML (the harness's parser) does:
    PyYAML's YAML 1.1 float rule wants a dot in the mantissa, so JSON's 1e-5 would become a string."""


_SceneYamlLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"""^(?:[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?(?:[eE][-+]?[0-9]+)?
                    |\.[0-9_]+(?:[eE][-+]?[0-9]+)?
                    |[-+]?\.(?:inf|Inf|INF)
                    |\.(?:nan|NaN|NAN))$""", re.X),
    list("-+0123456789."))


def json_path(parts):
    out = "$"
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else f".{p}"
    return out


# ------------------------------------------------------------------------------------------------
# Reading a valid document

def _sleeping(s):
    """world.sleeping: true/false, or an object of tolerances (which turns it on)."""
    if s is None or s is False:
        return None
    if s is True:
        return {}
    return {k: float(v) for k, v in s.items()}


def _vec(v, dx=0.0, dy=0.0):
    return (float(v[0]), float(v[1])) if v is not None else (dx, dy)


def _bits(v, default):
    """A list of bit numbers (0..31) as an unsigned 32-bit set, or the default when absent."""
    if v is None:
        return default
    out = 0
    for k in v:
        out |= 1 << int(k)
    return out


def _bit_list(bits):
    return [k for k in range(32) if bits >> k & 1]


def _num(o, key, default):
    return float(o[key]) if key in o else default


class _Reader:
    def __init__(self, shown):
        self.shown = shown
        self.problems = []
        self.shapes = {}
        self.generators = set()  # generator names: a bare one in an expectation is a group
        self.has_landscape = False

    def problem(self, path, message):
        self.problems.append(f"{self.shown}: {path}: {message}")

    def read(self, root, default_name) -> Scene:
        name = root.get("name", default_name)
        world = self.world(root.get("world"))
        for key, node in (root.get("shapes") or {}).items():
            self.shapes[key] = self.shape(key, node, f"$.shapes.{key}")
        bodies = []
        for i, b in enumerate(root.get("bodies") or []):
            shape = self.shape_ref(b["shape"], f"$.bodies[{i}].shape")
            x, y = _vec(b.get("position"))
            bodies.append(Body(b.get("name", f"body{i}"), shape, x, y, self.state(b, f"$.bodies[{i}]")))
        for i, g in enumerate(root.get("generators") or []):
            bodies.extend(self.generator(g, f"$.generators[{i}]"))
        names = set()
        for b in bodies:
            if b.name in names:
                self.problem("$", f"duplicate body name '{b.name}'")
            names.add(b.name)
        actions = self.actions(root.get("actions") or [], names)
        elements = {}
        for section in ELEMENT_SECTIONS:
            if section in root:
                elements[section] = root[section]
                self.check_body_refs(root[section], f"$.{section}", names)
        reference = root.get("reference") or {}
        closed_form = reference.get("closedForm")
        if closed_form is not None:
            self.check_body_refs(closed_form, "$.reference.closedForm", names)
        run = root["run"]
        self.generators = {g["name"] for g in root.get("generators") or []}
        self.has_landscape = "landscape" in root
        record, expect = self.record(run, names)
        if self.problems:
            raise SceneError("\n".join(self.problems))
        return Scene(name=name, file=self.shown, description=root.get("description", ""),
                     category=root.get("category"), world=world, shapes=self.shapes, bodies=bodies,
                     actions=actions, elements=elements, duration=float(run["duration"]), record=record,
                     expect=expect, closed_form=closed_form, oracle=reference.get("oracle"), raw=root)

    def world(self, w) -> World:
        d = World()
        if w is None:
            return d
        if "ticksPerSecond" in w and "timestep" in w:
            self.problem("$.world.timestep", "give ticksPerSecond or timestep, not both")
        if "timestep" in w:
            h = float(w["timestep"])
        elif "ticksPerSecond" in w:
            h = 1.0 / float(w["ticksPerSecond"])
        else:
            h = d.timestep
        damping = w.get("damping") or {}
        return World(timestep=h, iterations=int(w.get("iterations", d.iterations)),
                     dynamic_iterations=bool(w.get("dynamicIterations", False)),
                     gravity=_vec(w.get("gravity"), *d.gravity),
                     damping_lateral=_num(damping, "lateral", 0.0),
                     damping_rotational=_num(damping, "rotational", 0.0),
                     simulation_area=w.get("simulationArea"), solver=dict(w.get("solver") or {}),
                     sleeping=_sleeping(w.get("sleeping")))

    def shape_ref(self, node, path):
        if isinstance(node, str):
            s = self.shapes.get(node)
            if s is None:
                self.problem(path, f"no shape named '{node}' under shapes")
            return s
        return self.shape(None, node, path)

    def shape(self, name, s, path) -> Shape:
        kind = s["type"]
        parts = []
        for i, part in enumerate(s.get("parts") or []):
            ox, oy = _vec(part.get("offset"))
            parts.append((self.shape_ref(part["shape"], f"{path}.parts[{i}].shape"), ox, oy,
                          _num(part, "angle", 0.0)))
        default_mass = 1.0
        if kind == "multiShape":
            default_mass = sum(p[0].mass for p in parts if p[0] is not None)
        return Shape(kind=kind, radius=_num(s, "radius", 0.0), width=_num(s, "width", 0.0),
                     height=_num(s, "height", 0.0), sides=int(s.get("sides", 0)),
                     vertices=[_vec(v) for v in s.get("vertices") or []], parts=parts,
                     mass=_num(s, "mass", default_mass), friction=_num(s, "friction", 0.25),
                     elasticity=_num(s, "elasticity", 0.0), name=name)

    def state(self, b, path) -> BodyState:
        if b is None:
            return BodyState()
        if "angle" in b and "angleDeg" in b:
            self.problem(f"{path}.angleDeg", "give angle or angleDeg, not both")
        angle = math.radians(float(b["angleDeg"])) if "angleDeg" in b else _num(b, "angle", 0.0)
        vx, vy = _vec(b.get("velocity"))
        static = bool(b.get("static", False))
        kinematic = bool(b.get("kinematic", False))
        omega = _num(b, "angularVelocity", 0.0)
        if static and kinematic:
            self.problem(f"{path}.kinematic", "a body is static or kinematic, not both")
        elif static and (vx != 0 or vy != 0):
            self.problem(f"{path}.velocity", "a static body does not move; give kinematic: true to move it by its velocity")
        elif static and omega != 0:
            self.problem(f"{path}.angularVelocity", "a static body does not turn; give kinematic: true to turn it")
        return BodyState(static=static, angle=angle, vx=vx, vy=vy,
                         angular_velocity=omega,
                         rotatable=bool(b.get("rotatable", True)), interacting=bool(b.get("interacting", True)),
                         gravity=bool(b.get("gravity", True)), layers=tuple(int(x) for x in b.get("layers") or []),
                         kinematic=kinematic, categories=_bits(b.get("categories"), 1),
                         mask=_bits(b.get("mask"), 0xFFFFFFFF), group=int(b.get("group", 0)),
                         sleeping_allowed=bool(b.get("sleepingAllowed", True)),
                         sensor=bool(b.get("sensor", False)))

    def generator(self, g, path):
        shapes = []
        if "shape" in g:
            shapes.append(self.shape_ref(g["shape"], f"{path}.shape"))
        for i, s in enumerate(g.get("shapes") or []):
            shapes.append(self.shape_ref(s, f"{path}.shapes[{i}]"))
        if any(s is None for s in shapes):
            return []
        spacing = None
        if "spacing" in g:
            sp = g["spacing"]
            spacing = [float(sp)] if isinstance(sp, (int, float)) else list(_vec(sp))
        elif g["type"] != "rain" and shapes[0].size() is None:
            self.problem(path, "give spacing: the default spacing needs a shape with a known size")
            return []
        anchor = g.get("base", g.get("origin", g.get("start")))
        region = g.get("region")
        spec = generators.Spec(kind=g["type"], name=g["name"], shapes=shapes, anchor=_vec(anchor),
                               count=int(g.get("count", 0)), rows=int(g.get("rows", 0)),
                               columns=int(g.get("columns", 0)), spacing=spacing,
                               min=_vec(region["min"]) if region else None,
                               max=_vec(region["max"]) if region else None,
                               seed=int(g.get("seed", 0)), random_angle=bool(g.get("randomAngle", False)),
                               template=self.state(g.get("body"), f"{path}.body"))
        return [Body(n, s, x, y, st) for n, s, x, y, st in generators.expand(spec)]

    def actions(self, items, names):
        out = []
        for i, a in enumerate(items):
            kind = a["type"]
            body = a.get("body")
            if body is not None and body not in names:
                self.problem(f"$.actions[{i}].body", f"no body named '{body}'")
            vector, value = None, math.nan
            if kind in ("impulse", "force", "gravity"):
                vector = _vec(a[kind])
            elif kind == "velocity":
                vector = _vec(a["velocity"]) if "velocity" in a else None
                value = _num(a, "angularVelocity", math.nan)
                if vector is None and math.isnan(value):
                    self.problem(f"$.actions[{i}]", "give velocity, angularVelocity or both")
            elif kind == "torque":
                value = float(a["torque"])
            elif kind == "emit":
                value = float(a["count"])  # a particle burst: nothing in pymunk (MAPPING.md, Actions)
            else:
                value = float(a["angularImpulse"])
            out.append(Action(float(a["at"]), kind, body, vector, _vec(a["point"]) if "point" in a else None,
                              value, _num(a, "duration", math.nan)))
        return out

    def record(self, run, names):
        rec = run.get("record") or {}
        metrics = {}
        for i, m in enumerate(rec.get("metrics") or []):
            spec = self.metric(m, f"$.run.record.metrics[{i}]", names)
            if spec.kind in metrics:
                self.problem(f"$.run.record.metrics[{i}]", f"metric '{spec.kind}' is listed twice")
            metrics[spec.kind] = spec
        bodies, body_names = "all", []
        if "bodies" in rec:
            if isinstance(rec["bodies"], str):
                bodies = rec["bodies"]
            else:
                bodies = None
                for i, n in enumerate(rec["bodies"]):
                    if n not in names:
                        self.problem(f"$.run.record.bodies[{i}]", f"no body named '{n}'")
                    body_names.append(n)
        pairs = []
        expect = [self.resolved(e, f"$.run.expect[{i}]", names, pairs) for i, e in enumerate(run.get("expect") or [])]
        for i, e in enumerate(expect):
            # An expectation is a request: the metric it reads exists even if record does not list it.
            needed = None
            if "metric" in e or "closedForm" in e:
                needed = metric_of(e.get("metric", e.get("closedForm")))
            elif "noTunnelling" in e:
                needed = "tunnelling"
            elif "stable" in e:
                needed = "stability"
            if needed == "tunnelling" and needed not in metrics:
                self.problem(f"$.run.expect[{i}]", "noTunnelling needs the tunnelling metric with its walls")
            elif needed is not None and needed not in metrics:
                metrics[needed] = MetricSpec(needed)
            if "stable" in e and "maxEnergyRise" in e["stable"] and "energy" not in metrics:
                metrics["energy"] = MetricSpec("energy")
            for extra in extra_channels(e):
                k = metric_of(extra)
                if k is not None and k != "tunnelling" and k not in metrics:
                    metrics[k] = MetricSpec(k)
                xc = body_channel(extra)
                if bodies is None and xc is not None and xc[0] not in body_names:
                    body_names.append(xc[0])
            if bodies is None:
                if "body" in e and e["body"] not in body_names and "*" not in e["body"]:
                    body_names.append(e["body"])
                bc = body_channel(e.get("metric", e.get("closedForm")))
                if bc is not None and bc[0] not in body_names and "*" not in bc[0]:
                    body_names.append(bc[0])
        if pairs:
            metrics["penetration"].pairs = pairs
        every = float(rec["every"]) if "every" in rec else math.nan
        return Record(every, list(metrics.values()), bodies, body_names, bool(rec.get("trace", True))), expect

    def group(self, name, path, names):
        """A bare generator name stands for its bodies (NAME[*]) unless a body has that name too (harness
        ScenarioReader.group)."""
        if name not in self.generators:
            return name
        if name in names:
            self.problem(path, f"'{name}' names both a body and the generator {name}: write {name}[*] for the "
                               "generator's bodies, or rename the body")
            return name
        return name + "[*]"

    def resolved(self, e, path, names, pairs):
        """An expectation as the harness reads it: bare generator names as groups, between as a pair channel
        (its filter added to `pairs`). The dict returned is a copy; the file's stays as written."""
        e = dict(e)
        if isinstance(e.get("body"), str):
            e["body"] = self.group(e["body"], f"{path}.body", names)
        for key in ("metric", "closedForm"):
            bc = body_channel(e.get(key)) if isinstance(e.get(key), str) else None
            if bc is not None:
                e[key] = f"body.{self.group(bc[0], f'{path}.{key}', names)}.{bc[1]}"
        between = e.get("between")
        metric = e.get("metric")
        if isinstance(between, list) and isinstance(metric, str) and metric.startswith("penetration."):
            party = []
            for i, n in enumerate(between[:2]):
                party.append(n if n == LANDSCAPE else self.group(n, f"{path}.between[{i}]", names))
            if tuple(party) not in pairs:
                pairs.append(tuple(party))
            e["metric"] = pair_channel(metric[len("penetration."):], *party)
        return e

    def metric(self, m, path, names) -> MetricSpec:
        if isinstance(m, str):
            return MetricSpec(m)
        kind, o = next(iter(m.items()))
        walls = []
        for i, w in enumerate(o.get("walls") or []):
            if isinstance(w, str):
                if w not in names:
                    self.problem(f"{path}.{kind}.walls[{i}]", f"no body named '{w}'")
                walls.append(w)
            else:
                walls.append((_vec(w["from"]), _vec(w["to"])))
        bodies = list(o.get("bodies") or [])
        for i, n in enumerate(bodies):
            if n not in names:
                self.problem(f"{path}.{kind}.bodies[{i}]", f"no body named '{n}'")
        return MetricSpec(kind, _vec(o.get("about")), walls, bodies, o.get("points", "centre") == "shape")

    def check_body_refs(self, node, path, names):
        if isinstance(node, list):
            for i, n in enumerate(node):
                self.check_body_refs(n, f"{path}[{i}]", names)
        elif isinstance(node, dict):
            for key in ("body", "bodyA", "bodyB"):
                v = node.get(key)
                if isinstance(v, str) and v not in names:
                    self.problem(f"{path}.{key}", f"no body named '{v}'")
