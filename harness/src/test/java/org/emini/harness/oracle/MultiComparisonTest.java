package org.emini.harness.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.metrics.PenetrationPair;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The engine against two oracles: rows merged by channel and figure, "closer to the truth" ranks all three. */
class MultiComparisonTest {
    private static Comparison.Row row(String channel, double engineError, double oracleError, Closer pairwise) {
        return new Comparison.Row(channel, "series, maxError", 10, 10 + oracleError, 10 - engineError, "closed form x",
                oracleError - engineError, 1, engineError, oracleError,
                Math.abs(oracleError - engineError) <= 1 ? Agreement.AGREE : Agreement.DIFFER, pairwise);
    }

    private static Comparison.Scene scene(Comparison.Row... rows) {
        return new Comparison.Scene("s", "s.yaml", null, CompareStatus.COMPARED, "", "pass", null, OracleSettings.DEFAULT,
                "x", List.of(rows));
    }

    @Test
    void theClosestOfTheThreeWinsAndTheTwoClosestWithinFivePercentTie() {
        Map<String, Comparison.Scene> by = new LinkedHashMap<>();
        by.put("pymunk", scene(row("body.a.x", 1.0, 3.0, Closer.ENGINE), row("body.a.y", 1.0, 5.0, Closer.ENGINE)));
        by.put("box2d", scene(row("body.a.x", 1.0, 0.5, Closer.ORACLE), row("body.a.y", 1.0, 1.02, Closer.TIE)));
        MultiComparison.Scene m = MultiComparison.merge(by);
        assertEquals(2, m.rows().size(), "one row per channel and figure");
        MultiComparison.Row x = m.rows().get(0);
        assertEquals("box2d", x.closer());
        assertEquals(List.of("box2d", "emini", "pymunk"), x.ranking());
        assertEquals(3.0, x.oracles().get("pymunk").error());
        assertEquals(0.5, x.oracles().get("box2d").error());
        assertEquals("tie", m.rows().get(1).closer(), "emini 1.0 and box2d 1.02 are within 5%");
        MultiComparison.Summary s = MultiComparison.Summary.of(List.of(m), List.of("pymunk", "box2d"), 0);
        assertEquals(Map.of("emini", 0, "pymunk", 0, "box2d", 1, "tie", 1), s.closer());
        assertEquals(0, s.agree().get("pymunk"), "2 and 4 apart: both differ");
        assertEquals(2, s.agree().get("box2d"));
    }

    @Test
    void anOracleThatDidNotRunIsLeftOutOfTheRanking(@TempDir Path dir) throws Exception {
        Map<String, Comparison.Scene> by = new LinkedHashMap<>();
        by.put("pymunk", scene(row("body.a.x", 2.0, 1.0, Closer.ORACLE)));
        by.put("box2d", scene(row("body.a.x", 2.0, Double.NaN, Closer.NONE)));
        MultiComparison.Scene m = MultiComparison.merge(by);
        assertEquals(List.of("pymunk", "emini"), m.rows().get(0).ranking());
        assertEquals("pymunk", m.rows().get(0).closer());
        MultiComparison.write(dir, List.of(m), MultiComparison.Summary.of(List.of(m), List.of("pymunk", "box2d"), 1),
                "test", List.of("pymunk", "box2d"), "pymunk 7.3.1, Box2D 3.1.1");
        String json = Files.readString(dir.resolve("compare.json"));
        assertTrue(json.contains("\"version\": 2") && json.contains("\"ranking\": [") && json.contains("\"box2d\": {"), json);
        String md = Files.readString(dir.resolve("summary.md"));
        assertTrue(md.contains("| reference | emini | pymunk | box2d | tie |") && md.contains("pymunk < emini"), md);
    }

    @Test
    void theDeepestPairsOfEachEngineStandSideBySideWithTheOthersFigures(@TempDir Path dir) throws Exception {
        List<PenetrationPair> emini = List.of(new PenetrationPair("light", "heavy", 0.2, 0.15, 200),
                new PenetrationPair("ground", "light", 0.18, 0.07, 198));
        List<PenetrationPair> pymunk = List.of(new PenetrationPair("ground", "light", 6.3, 3, 200),
                new PenetrationPair("light", "heavy", 4.8, 2, 200), new PenetrationPair("light", "box[3]", 3.2, 1, 50));
        Map<String, Comparison.Scene> by = new LinkedHashMap<>();
        by.put("pymunk", new Comparison.Scene("s", "s.yaml", null, CompareStatus.COMPARED, "", "pass", null,
                OracleSettings.DEFAULT, null, List.of(), emini, pymunk));
        by.put("box2d", new Comparison.Scene("s", "s.yaml", null, CompareStatus.COMPARED, "", "pass", null,
                OracleSettings.DEFAULT, null, List.of(), emini, null));
        MultiComparison.Scene m = MultiComparison.merge(by);
        List<MultiComparison.PairRow> pairs = MultiComparison.pairs(m);
        // The union of each engine's deepest, deepest first; a pair one engine never overlapped reads 0 there;
        // box2d, which gave no pairs, has no column.
        assertEquals(3, pairs.size(), pairs.toString());
        assertEquals(List.of("ground", "light"), List.of(pairs.get(0).a(), pairs.get(0).b()));
        assertEquals(Map.of("emini", 0.18, "pymunk", 6.3), pairs.get(0).max());
        assertEquals("box[3]", pairs.get(2).b());
        assertEquals(0.0, pairs.get(2).max().get("emini"));
        MultiComparison.write(dir, List.of(m), MultiComparison.Summary.of(List.of(m), List.of("pymunk", "box2d"), 1),
                "test", List.of("pymunk", "box2d"), "pymunk 7.3.1, Box2D 3.1.1");
        String json = Files.readString(dir.resolve("compare.json"));
        assertTrue(json.contains("\"penetrationPairs\": [") && json.contains("\"pymunk\": 6.3"), json);
        String md = Files.readString(dir.resolve("summary.md"));
        assertTrue(md.contains("| pair | emini | pymunk |") && md.contains("| ground – light | 0.18 | 6.3 |"), md);
    }
}
