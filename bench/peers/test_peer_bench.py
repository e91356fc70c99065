"""peer_bench's method and result file, on a fake world (no physics engine needed).

    oracle-py/.venv/bin/python -m pytest -q -p no:cacheprovider bench/peers
"""

import json
import math

import peer_bench


class Counter:
    """A world of one body that moves 1 px per tick (a second body is lost: NaN)."""

    units = "px"
    settings = "fake"

    def __init__(self, ticks=5):
        self.ticks = ticks
        self.n = 0

    def tick(self):
        self.n += 1

    def state(self):
        return [self.n, 0.0, 0.0, math.nan, 0.0, 0.0], [1.0, 0.0], [0.0, math.inf], [], -1


def args(tmp_path, *extra):
    return peer_bench.arguments("test").parse_args(
        ["--out", str(tmp_path / "out.json"), "--warmups", "1", "--iterations", "2", "--seconds", "0.01", *extra, "a", "b", "c"])


def test_measure_snapshots_the_start_the_preroll_and_the_end(tmp_path):
    w = Counter()
    m = peer_bench.measure(w, args(tmp_path))
    assert m["status"] == "ok" and m["units"] == "px" and m["settings"] == "fake"
    assert m["initial"]["ticks"] == 0 and m["initial"]["poses"][0] == 0
    # The preroll is the world's run duration unless --preroll says otherwise.
    assert m["check"]["ticks"] == 5 and m["check"]["poses"][0] == 5
    assert m["afterRun"]["ticks"] == w.n and m["afterRun"]["poses"][0] == w.n > 5
    # JSON has no NaN: non-finite figures are null.
    assert m["check"]["poses"][3] is None and m["check"]["omegas"][1] is None
    assert m["cpuMsPerTick"] >= 0 and m["msPerTick"] > 0 and m["msPerTickMedian"] > 0
    assert peer_bench.measure(Counter(), args(tmp_path, "--preroll", "2"))["check"]["ticks"] == 2


def test_run_reports_unsupported_and_failing_scenes_and_writes_the_file(tmp_path):
    def build(scene, _):
        if scene == "b":
            raise peer_bench.Unsupported("no particles")
        if scene == "c":
            raise RuntimeError("broken")
        return Counter(ticks=1)

    a = args(tmp_path)
    peer_bench.run("fake", a, build)
    out = json.loads(a.out.read_text())
    assert [(e["scene"], e["engine"], e["status"]) for e in out] == [("a", "fake", "ok"), ("b", "fake", "unsupported"),
                                                                    ("c", "fake", "error")]
    assert out[1]["message"] == "no particles" and out[2]["message"] == "RuntimeError: broken"
