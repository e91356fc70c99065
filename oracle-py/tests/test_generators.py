"""Generators expand as scenarios/README.md says, and exactly as the harness expands them."""

import math

import pytest

from conftest import SCENARIOS, harness_json, load
from emini_oracle import scene as scene_mod
from emini_oracle.generators import SplitMix64


def test_splitmix64_matches_the_published_sequence():
    # Steele, Lea, Flood (2014) / Vigna's reference splitmix64.c, seed 0.
    r = SplitMix64(0)
    assert [r.next_long() for _ in range(3)] == [0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4, 0x06C45D188009454F]


def test_splitmix64_doubles_are_the_top_53_bits():
    r, s = SplitMix64(42), SplitMix64(42)
    for _ in range(100):
        u = r.next_double()
        assert 0 <= u < 1
        assert u == (s.next_long() >> 11) / 2.0 ** 53


def test_tower_pyramid_grid_row_follow_the_placement_rules(loader):
    s = load(loader, """
shapes: {box: {type: rectangle, width: 20, height: 10}, ball: {type: circle, radius: 5}}
generators:
  - {type: tower, name: t, shape: box, base: [0, -5], count: 3}
  - {type: pyramid, name: p, shape: box, base: [100, -5], rows: 3, spacing: [22, 10]}
  - {type: grid, name: g, shape: ball, origin: [-50, 0], columns: 2, rows: 2}
  - {type: row, name: r, shape: ball, start: [0, -100], count: 3, spacing: [12, 1]}
run: {duration: 1}
""")
    pos = {b.name: (b.x, b.y) for b in s.bodies}
    assert [pos[f"t[{i}]"] for i in range(3)] == [(0, -5), (0, -15), (0, -25)]
    # Row r from the bottom has rows - r bodies, centred, dx apart; numbered row by row.
    assert [pos[f"p[{i}]"] for i in range(6)] == [(78, -5), (100, -5), (122, -5), (89, -15), (111, -15), (100, -25)]
    # Default grid spacing [w, -h] (rows stack upward), numbered row by row.
    assert [pos[f"g[{i}]"] for i in range(4)] == [(-50, 0), (-40, 0), (-50, -10), (-40, -10)]
    assert [pos[f"r[{i}]"] for i in range(3)] == [(0, -100), (12, -99), (24, -98)]


def test_rain_draws_x_y_shape_angle_in_that_order(loader):
    s = load(loader, """
shapes: {a: {type: circle, radius: 5}, b: {type: rectangle, width: 4, height: 4}}
generators:
  - {type: rain, name: rain, shapes: [a, b], region: {min: [-10, -20], max: [10, 0]}, count: 5, seed: 7,
     randomAngle: true, body: {velocity: [0, 5]}}
run: {duration: 1}
""")
    r = SplitMix64(7)
    for i, b in enumerate(s.bodies):
        assert b.name == f"rain[{i}]"
        assert b.x == -10 + r.next_double() * 20
        assert b.y == -20 + r.next_double() * 20
        assert b.shape is s.shapes["ab"[int(math.floor(r.next_double() * 2))]]
        assert b.state.angle == r.next_double() * 2 * math.pi
        assert (b.state.vx, b.state.vy) == (0, 5)


def test_every_library_scene_expands_as_the_harness_expands_it(loader):
    # Body names, order, positions, states, shapes and the run's ticks, compared exactly (same double
    # arithmetic on both sides): the oracle simulates the very scene the engine does.
    harness_scenes = harness_json("expand", str(SCENARIOS))
    ours = [loader.load(f).expanded_json() for f in scene_mod.scene_files([SCENARIOS])]
    assert len(ours) == len(harness_scenes) > 50
    for mine, theirs in zip(ours, harness_scenes):
        assert mine["scene"] == theirs["scene"]
        assert len(mine["bodies"]) == len(theirs["bodies"]), mine["scene"]
        assert mine == theirs, mine["scene"]


def test_a_generator_scene_with_every_generator_matches_the_harness(loader, tmp_path):
    f = tmp_path / "gens.yaml"
    f.write_text("""
shapes:
  box: {type: rectangle, width: 20, height: 20}
  hex: {type: regularPolygon, radius: 12, sides: 6}
  wedge: {type: polygon, vertices: [[-10, 10], [10, 10], [0, -10]]}
generators:
  - {type: tower, name: tower, shape: box, base: [-300, -10], count: 7, spacing: 21.5}
  - {type: pyramid, name: pyr, shape: hex, base: [-200, -12], rows: 6, spacing: [24.3, 21]}
  - {type: grid, name: grid, shape: wedge, origin: [0.1, -400], columns: 7, rows: 3}
  - {type: row, name: row, shape: box, start: [-300, -500], count: 9, spacing: [25, -0.3]}
  - {type: rain, name: rain, shapes: [box, hex, wedge], region: {min: [-200.5, -900], max: [200, -600.25]},
     count: 40, seed: -1234567890123, randomAngle: true, body: {angularVelocity: 1, layers: [2, 5]}}
run: {duration: 0.5, record: {every: 0.12}}
""")
    (theirs,) = harness_json("expand", "--schema", str(scene_mod.find_schema(SCENARIOS)), str(f))
    mine = loader.load(f).expanded_json()
    assert len(mine["bodies"]) == 7 + 21 + 21 + 9 + 40
    assert mine == theirs


def test_sample_ticks_round_the_interval_and_keep_the_last_tick(loader):
    s = load(loader, "bodies: [{shape: {type: circle, radius: 1}}]\nrun: {duration: 1.01, record: {every: 0.12}}")
    # h = 0.05: 21 ticks (ceil of 20.2), sampled every round(2.4) = 2 ticks and at the last.
    assert s.ticks == 21 and s.sampling_ticks == 2
    assert s.sample_ticks() == [0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 21]


def test_an_invalid_scene_is_refused_with_its_path(loader):
    with pytest.raises(scene_mod.SceneError, match=r"\$\.run.*colour|colour"):
        load(loader, "run: {duration: 1, colour: red}")
    with pytest.raises(scene_mod.SceneError, match="no shape named 'nope'"):
        load(loader, "bodies: [{shape: nope}]\nrun: {duration: 1}")
