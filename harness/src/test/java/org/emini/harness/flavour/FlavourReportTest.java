package org.emini.harness.flavour;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The side-by-side report of the two flavours, on hand-written compare.json files and sweep points. */
class FlavourReportTest {
    private static Path compare(Path dir, String name, String xError, String angleError) throws IOException {
        Path d = Files.createDirectories(dir.resolve(name));
        Files.writeString(d.resolve("compare.json"), """
            {"scenes": [{"scene": "closed-form/free-rotation", "rows": [
              {"channel": "body.box.x", "figure": "series, maxError", "reference": 1.0, "engineError": %s, "oracleError": 2.8e-14},
              {"channel": "body.box.angle", "figure": "series, maxError", "reference": 1.0, "engineError": %s, "oracleError": 0.0},
              {"channel": "body.box.vx", "figure": "series, maxError", "reference": null, "engineError": 0.0, "oracleError": 0.0}]},
              {"scene": "closed-form/unsupported", "status": "oracle only"}]}
            """.formatted(xError, angleError));
        return d;
    }

    @Test
    void rowsWithAReferenceStandSideBySideWithTheClosestNamed() throws IOException {
        Path dir = Files.createTempDirectory("flavours");
        String md = FlavourReport.markdown(compare(dir, "f", "9.2e-4", "0.0"), compare(dir, "d", "2.8e-12", "0.0"), null);
        assertTrue(md.contains("| closed-form/free-rotation | body.box.x | series, maxError | 0.000920 | 2.80e-12 | 2.80e-14 | pymunk |"), md);
        assertTrue(md.contains("| closed-form/free-rotation | body.box.angle | series, maxError | 0.00 | 0.00 | 0.00 | tie |"), md);
        assertFalse(md.contains("body.box.vx"), "a row without a reference has no error to show");
        assertTrue(md.contains("2 rows; closest: the double flavour alone in 0, pymunk alone in 1."), md);
    }

    @Test
    void sweepPointsOfBothFlavoursGiveTheCostRatio(@TempDir Path dir) throws IOException {
        Files.writeString(dir.resolve("points.jsonl"), String.join("\n",
            point("emini", 0.34, 0.010), point("emini-double", 0.33, 0.012), point("pymunk", 3.3, 0.020),
            point2("emini", 0.10, 0.020), point2("emini-double", 0.10, 0.021)) + "\n");
        String md = FlavourReport.markdown(null, null, dir);
        assertTrue(md.contains("| s | 60 | 10 | 0.340 | 0.330 | 3.30 | 10.0 | 12.0 | 1.20 |"), md);
        assertTrue(md.contains("| s | 120 | 10 | 0.100 | 0.100 |  | 20.0 | 21.0 | 1.05 |"), md);
        assertTrue(md.contains("over 2 points: median 1.20, range 1.05 to 1.20"), md);
    }

    private static String point(String engine, double error, double cpu) {
        return json(engine, 60, error, cpu);
    }

    private static String point2(String engine, double error, double cpu) {
        return json(engine, 120, error, cpu);
    }

    private static String json(String engine, int rate, double error, double cpu) {
        return String.format(java.util.Locale.ROOT, "{\"scene\":\"s\",\"engine\":\"%s\",\"rate\":%d,\"iterations\":10,"
            + "\"status\":\"ok\",\"message\":\"\",\"reference\":\"closedForm:projectile\",\"finalError\":%s,\"maxError\":%s,"
            + "\"rmsError\":%s,\"costSeconds\":%s,\"cpuCostSeconds\":%s,\"repeats\":1,\"motion\":400}", engine, rate, error,
            error, error, cpu, cpu);
    }
}
