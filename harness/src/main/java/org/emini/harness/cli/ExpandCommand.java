package org.emini.harness.cli;

import com.google.gson.stream.JsonWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.BodyState;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.ShapeSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Parameters;

/**
 * {@code expand PATHS}: prints scenes as the harness reads them, generators expanded and defaults filled
 * in, as one JSON array. The Python oracle's {@code emini-oracle expand} prints the same document for
 * the same files; its tests compare the two body by body.
 */
@Command(name = "expand", mixinStandardHelpOptions = true,
        description = "Prints scenes with generators expanded and defaults filled in, as JSON.")
final class ExpandCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "PATHS", arity = "1..*", description = "Scene files or folders.")
    List<Path> paths;

    @Override
    public Integer call() throws IOException {
        ScenarioLoader loader = library.loader();
        int invalid = 0;
        Writer out = new OutputStreamWriter(System.out, StandardCharsets.UTF_8);
        JsonWriter json = new JsonWriter(out);
        json.setIndent(" ");
        json.beginArray();
        for (Path file : library.files(spec, paths)) {
            ScenarioLoader.Loaded loaded = loader.load(file);
            if (!loaded.ok()) {
                invalid++;
                for (Problem p : loaded.problems()) {
                    System.err.println(p);
                }
                continue;
            }
            scene(json, loaded.scenario());
        }
        json.endArray();
        json.flush();
        out.write('\n');
        out.flush();
        return invalid == 0 ? 0 : 1;
    }

    private static void scene(JsonWriter json, Scenario s) throws IOException {
        json.beginObject();
        json.name("scene").value(s.name());
        json.name("timestep").value(s.world().timestep());
        json.name("ticks").value(s.ticks());
        json.name("samplingTicks").value(ScenarioRunner.samplingTicks(s.run().record(), s.world().timestep()));
        json.name("bodies").beginArray();
        for (BodySpec b : s.bodies()) {
            BodyState st = b.state();
            json.beginObject();
            json.name("name").value(b.name());
            json.name("position").beginArray().value(b.x()).value(b.y()).endArray();
            json.name("static").value(st.isStatic());
            if (st.kinematic()) {
                json.name("kinematic").value(true);
            }
            if (st.sensor()) {
                json.name("sensor").value(true);
            }
            if (!st.defaultFilter()) {
                bitList(json.name("categories"), st.categoryBits());
                bitList(json.name("mask"), st.maskBits());
                json.name("group").value(st.group());
            }
            json.name("angle").value(st.angle());
            json.name("velocity").beginArray().value(st.vx()).value(st.vy()).endArray();
            json.name("angularVelocity").value(st.angularVelocity());
            json.name("rotatable").value(st.rotatable());
            json.name("interacting").value(st.interacting());
            json.name("gravity").value(st.gravity());
            json.name("sleepingAllowed").value(st.sleepingAllowed());
            json.name("layers").beginArray();
            for (int layer : st.layers()) {
                json.value(layer);
            }
            json.endArray();
            json.name("shape");
            shape(json, b.shape());
            json.endObject();
        }
        json.endArray();
        json.endObject();
    }

    /** A bit set as the list of its bit numbers, as the scene format writes layers, categories and masks. */
    private static void bitList(JsonWriter json, int bits) throws IOException {
        json.beginArray();
        for (int k = 0; k < 32; k++) {
            if ((bits >>> k & 1) != 0) {
                json.value(k);
            }
        }
        json.endArray();
    }

    private static void shape(JsonWriter json, ShapeSpec s) throws IOException {
        json.beginObject();
        json.name("type").value(s.kind().name());
        json.name("mass").value(s.mass());
        json.name("friction").value(s.friction());
        json.name("elasticity").value(s.elasticity());
        switch (s.kind()) {
            case circle -> json.name("radius").value(s.radius());
            case regularPolygon -> {
                json.name("radius").value(s.radius());
                json.name("sides").value(s.sides());
            }
            case rectangle -> {
                json.name("width").value(s.width());
                json.name("height").value(s.height());
            }
            case polygon -> {
                json.name("vertices").beginArray();
                for (double[] v : s.vertices()) {
                    json.beginArray().value(v[0]).value(v[1]).endArray();
                }
                json.endArray();
            }
            case multiShape -> {
                json.name("parts").beginArray();
                for (ShapeSpec.Part p : s.parts()) {
                    json.beginObject();
                    json.name("shape");
                    shape(json, p.shape());
                    json.name("offset").beginArray().value(p.offsetX()).value(p.offsetY()).endArray();
                    json.name("angle").value(p.angle());
                    json.endObject();
                }
                json.endArray();
            }
        }
        json.endObject();
    }
}
