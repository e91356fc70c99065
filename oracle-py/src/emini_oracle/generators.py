"""Generators (tower, pyramid, grid, row, rain), expanded exactly as the harness's Generators.java.

Body i of generator NAME is NAME[i]. The same double arithmetic in the same order gives the same
positions bit for bit; rain draws from SplitMix64 (scenarios/README.md, Generators).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

MASK64 = (1 << 64) - 1


class SplitMix64:
    """SplitMix64 with 64-bit wrapping arithmetic, as scenarios/README.md spells it out."""

    def __init__(self, seed: int):
        self.state = seed & MASK64

    def next_long(self) -> int:
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK64
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
        return z ^ (z >> 31)

    def next_double(self) -> float:
        """Uniform in [0, 1): the top 53 bits times 2^-53."""
        return (self.next_long() >> 11) * (2.0 ** -53)


@dataclass
class Spec:
    kind: str
    name: str
    shapes: list
    anchor: tuple
    count: int
    rows: int
    columns: int
    spacing: Optional[list]
    min: Optional[tuple]
    max: Optional[tuple]
    seed: int
    random_angle: bool
    template: object  # scene.BodyState


def expand(g: Spec):
    """(name, shape, x, y, state) of each body, in order."""
    return {"tower": _tower, "pyramid": _pyramid, "grid": _grid, "row": _row, "rain": _rain}[g.kind](g)


def _tower(g):
    shape = g.shapes[0]
    dy = g.spacing[0] if g.spacing is not None else shape.size()[1]
    return [(f"{g.name}[{i}]", shape, g.anchor[0], g.anchor[1] - i * dy, g.template) for i in range(g.count)]


def _pyramid(g):
    shape = g.shapes[0]
    size = shape.size()
    dx = g.spacing[0] if g.spacing is not None else size[0]
    dy = g.spacing[1] if g.spacing is not None else size[1]
    out = []
    i = 0
    for r in range(g.rows):
        n = g.rows - r
        for j in range(n):
            x = g.anchor[0] + (j - (n - 1) / 2.0) * dx
            out.append((f"{g.name}[{i}]", shape, x, g.anchor[1] - r * dy, g.template))
            i += 1
    return out


def _grid(g):
    shape = g.shapes[0]
    size = shape.size()
    dx = g.spacing[0] if g.spacing is not None else size[0]
    dy = g.spacing[1] if g.spacing is not None else -size[1]
    out = []
    i = 0
    for r in range(g.rows):
        for c in range(g.columns):
            out.append((f"{g.name}[{i}]", shape, g.anchor[0] + c * dx, g.anchor[1] + r * dy, g.template))
            i += 1
    return out


def _row(g):
    shape = g.shapes[0]
    dx = g.spacing[0] if g.spacing is not None else shape.size()[0]
    dy = g.spacing[1] if g.spacing is not None else 0.0
    return [(f"{g.name}[{i}]", shape, g.anchor[0] + i * dx, g.anchor[1] + i * dy, g.template)
            for i in range(g.count)]


def _rain(g):
    random = SplitMix64(g.seed)
    n = len(g.shapes)
    out = []
    for i in range(g.count):
        x = g.min[0] + random.next_double() * (g.max[0] - g.min[0])
        y = g.min[1] + random.next_double() * (g.max[1] - g.min[1])
        shape = g.shapes[int(math.floor(random.next_double() * n))] if n > 1 else g.shapes[0]
        state = g.template
        if g.random_angle:
            state = state.with_angle(random.next_double() * 2 * math.pi)
        out.append((f"{g.name}[{i}]", shape, x, y, state))
    return out
