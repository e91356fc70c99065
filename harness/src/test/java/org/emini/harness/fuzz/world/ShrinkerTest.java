package org.emini.harness.fuzz.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The shrinker keeps exactly what a failure needs, and a written finding replays. */
class ShrinkerTest {
    @Test
    void aFailureNeedingTwoBodiesAndAJointShrinksToThem() {
        Recipe r = WorldGenerator.generate(7, 3, Profile.GENERAL);
        BodyRecipe a = r.bodies.get(r.bodies.size() - 1);
        BodyRecipe b = r.bodies.get(r.bodies.size() - 2);
        JointRecipe j = new JointRecipe();
        j.id = 999;
        j.a = b.id;
        j.b = a.id;
        j.atPoint = true;
        r.joints.add(j);
        Recipe small = new Shrinker(c -> c.joints.stream().anyMatch(x -> x.id == 999), 500).shrink(r);
        assertEquals(2, small.bodies.size(), small.summary());
        assertEquals(1, small.joints.size());
        assertEquals(0, small.events.size() + small.emitters.size() + small.segments.size() + small.springs.size()
                + small.motors.size() + small.forces.size());
        assertEquals(List.of(b.id, a.id), small.bodies.stream().map(x -> x.id).toList());
    }

    @Test
    void aWrittenFindingDescribesTheWorldAndReplays(@TempDir Path dir) throws Exception {
        Recipe r = InvariantChecksTest.drop();
        r.seed = 5;
        r.index = 2;
        Violation v = new Violation(ViolationKind.ENERGY, 3, "planted");
        Path json = FindingWriter.write(dir, new Finding(v, r, r, v, 0));
        String text = Files.readString(json);
        assertTrue(text.contains("\"kept\"") && text.contains("\"recipe\"") && text.contains("--replay"), text);
        Path yaml = dir.resolve(json.getFileName().toString().replace(".json", ".yaml"));
        assertTrue(Files.readString(yaml).contains("maxEnergyRise"));
        // The drop keeps its energy: the replay finds nothing, and says so with exit status 0.
        assertEquals(0, org.emini.harness.cli.Main.execute("fuzz", "worlds", "--replay", json.toString()));
    }
}
