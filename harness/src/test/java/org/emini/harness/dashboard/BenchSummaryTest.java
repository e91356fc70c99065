package org.emini.harness.dashboard;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class BenchSummaryTest {
    private static final String REPORT = "{\"format\": \"emini-bench\", \"version\": 1, \"generated\": \"2026-11-24T13:30:00Z\","
        + " \"mode\": \"full\", \"machine\": {\"cpu\": \"AMD EPYC\", \"cores\": 2.0, \"loadAverage\": 1.0},"
        + " \"loadAverageEnd\": 1.5, \"seconds\": 3000, \"resumed\": true,"
        + " \"scenes\": ["
        + "  {\"id\": \"bench/pyramid-20\", \"title\": \"20-row pyramid\", \"status\": \"ran\", \"message\": \"\", \"results\": ["
        + "    {\"engine\": \"emini\", \"status\": \"ok\", \"cpuMsPerTick\": 0.4, \"msPerTick\": 0.5, \"threadBytesPerTick\": 0.0,"
        + "     \"check\": {\"verdict\": \"stable\"}, \"afterRun\": {\"verdict\": \"stable\"}},"
        + "    {\"engine\": \"dyn4j\", \"status\": \"ok\", \"cpuMsPerTick\": null, \"msPerTick\": 0.9,"
        + "     \"check\": {\"verdict\": \"drifted\"}},"
        + "    {\"engine\": \"jbox2d\", \"status\": \"failed\", \"message\": \"JMH exited with 1\"},"
        + "    {\"engine\": \"box2d-v3\", \"status\": \"ok\", \"cpuMsPerTick\": 0.15, \"msPerTick\": 0.2, \"threadBytesPerTick\": null,"
        + "     \"check\": {\"verdict\": \"stable\"}},"
        + "    {\"engine\": \"rapier\", \"status\": \"missing\", \"message\": \"cargo build failed\"}]},"
        + "  {\"id\": \"bench/tumbler\", \"title\": \"tumbler\", \"status\": \"pending\", \"message\": \"no scene file\", \"results\": []}],"
        + " \"scaling\": ["
        + "  {\"engine\": \"emini\", \"dynamicBodies\": 100, \"cpuMsPerTick\": 0.5},"
        + "  {\"engine\": \"emini\", \"dynamicBodies\": 10000, \"cpuMsPerTick\": 50.0},"
        + "  {\"engine\": \"pymunk\", \"dynamicBodies\": 100, \"cpuMsPerTick\": 0.3},"
        + "  {\"engine\": \"pymunk\", \"dynamicBodies\": 10000, \"cpuMsPerTick\": 300.0},"
        + "  {\"engine\": \"dyn4j\", \"dynamicBodies\": 100, \"status\": \"failed\"}]}";

    private static Path write(Path reports, String json) throws IOException {
        Path dir = Files.createDirectories(reports.resolve("bench"));
        return Files.writeString(dir.resolve("bench.json"), json, StandardCharsets.UTF_8);
    }

    @Test
    void noBenchmarkRunGivesNoSummary(@TempDir Path reports) throws IOException {
        assertNull(BenchSummary.read(reports));
    }

    @Test
    void summarisesTimesVerdictsAndScaling(@TempDir Path reports) throws IOException {
        write(reports, REPORT);
        JsonObject s = BenchSummary.read(reports);
        assertEquals("2026-11-24T13:30:00Z", s.get("generated").getAsString());
        assertEquals("AMD EPYC", s.getAsJsonObject("machine").get("cpu").getAsString());
        assertTrue(s.get("resumed").getAsBoolean(), "the page says when figures were kept from an earlier run");
        assertEquals("[\"emini\",\"dyn4j\",\"jbox2d\",\"box2d-v3\",\"rapier\",\"pymunk\"]", s.get("engines").toString());

        JsonObject pyramid = s.getAsJsonArray("scenes").get(0).getAsJsonObject().getAsJsonObject("results");
        JsonObject emini = pyramid.getAsJsonObject("emini");
        assertEquals(0.4, emini.get("cpuMsPerTick").getAsDouble(), "CPU time where measured");
        assertEquals("stable", emini.get("verdict").getAsString());
        assertEquals(0.9, pyramid.getAsJsonObject("dyn4j").get("cpuMsPerTick").getAsDouble(), "else wall time");
        assertEquals("drifted", pyramid.getAsJsonObject("dyn4j").get("verdict").getAsString());
        JsonObject failed = pyramid.getAsJsonObject("jbox2d");
        assertFalse(failed.has("cpuMsPerTick"));
        assertEquals("JMH exited with 1", failed.get("message").getAsString());
        // The out-of-process engines (issue 16): a time without an allocation figure, and an engine that could not be made.
        assertEquals(0.15, pyramid.getAsJsonObject("box2d-v3").get("cpuMsPerTick").getAsDouble());
        assertEquals("stable", pyramid.getAsJsonObject("box2d-v3").get("verdict").getAsString());
        assertEquals("missing", pyramid.getAsJsonObject("rapier").get("status").getAsString());
        assertEquals("cargo build failed", pyramid.getAsJsonObject("rapier").get("message").getAsString());
        assertEquals("pending", s.getAsJsonArray("scenes").get(1).getAsJsonObject().get("status").getAsString());

        JsonObject scaling = s.getAsJsonObject("scaling");
        assertEquals(1.0, scaling.getAsJsonObject("emini").get("slope").getAsDouble(), 1e-12);
        assertEquals(1.5, scaling.getAsJsonObject("pymunk").get("slope").getAsDouble(), 1e-12);
        assertFalse(scaling.has("dyn4j"), "a failed point has no time to plot");

        assertFalse(s.has("page"));
        assertEquals(0, s.getAsJsonArray("images").size());
    }

    @Test
    void linksOnlyThePageAndPlotsThatExist(@TempDir Path reports) throws IOException {
        write(reports, REPORT);
        Files.writeString(reports.resolve("bench").resolve("index.html"), "<html></html>");
        Files.writeString(reports.resolve("bench").resolve("scaling.svg"), "<svg/>");
        JsonObject s = BenchSummary.read(reports);
        assertEquals("bench/index.html", s.get("page").getAsString());
        assertEquals("[\"bench/scaling.svg\"]", s.get("images").toString());
    }

    @Test
    void withoutARunOfItsOwnThePublishedRunIsShown(@TempDir Path repo) throws IOException {
        Path reports = repo.resolve("reports");
        Path published = repo.resolve("bench").resolve("results");
        Files.createDirectories(reports);
        Files.createDirectories(published);
        Files.writeString(published.resolve("bench.json"), REPORT);
        Files.writeString(published.resolve("scaling.png"), "png");
        JsonObject s = BenchSummary.read(reports, published);
        assertEquals("../bench/results/bench.json", s.get("published").getAsString());
        assertEquals("[\"../bench/results/scaling.png\"]", s.get("images").toString(), "links relative to the dashboard");
        write(reports, REPORT);
        assertFalse(BenchSummary.read(reports, published).has("published"), "the folder's own run comes first");
    }

    @Test
    void aDamagedOrForeignFileIsAnErrorNamingIt(@TempDir Path reports) throws IOException {
        Path f = write(reports, "{\"format\": \"emini-bench\", \"scenes\": [");
        IOException x = assertThrows(IOException.class, () -> BenchSummary.read(reports));
        assertTrue(x.getMessage().startsWith(f.toString()) && x.getMessage().contains("not valid JSON"), x.getMessage());
        write(reports, "{\"format\": \"emini-results\"}");
        x = assertThrows(IOException.class, () -> BenchSummary.read(reports));
        assertTrue(x.getMessage().contains("not a benchmark report"), x.getMessage());
    }
}
