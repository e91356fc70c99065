package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.Scenes;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;

/** A YAML scene and its JSON translation build the same world and run the same way. */
class YamlJsonEquivalenceTest {
    private static final String[] YAML = {
        "world: {ticksPerSecond: 60, gravity: [0, 50], damping: {lateral: 0.01}}",
        "shapes:",
        "  box: {type: rectangle, width: 20, height: 10, mass: 2, friction: 0.5}",
        "bodies:",
        "  - {name: ground, shape: {type: rectangle, width: 400, height: 20}, position: [0, 10], static: true}",
        "  - {name: ball, shape: {type: circle, radius: 5, elasticity: 0.5}, position: [3, -50], velocity: [10, 0], angleDeg: 30, layers: [2]}",
        "generators:",
        "  - {type: rain, name: rain, shapes: [box], region: {min: [-100, -300], max: [100, -100]}, count: 5, seed: 7, randomAngle: true}",
        "run: {duration: 0.5}",
    };
    private static final String[] JSON = {
        "{\"world\": {\"ticksPerSecond\": 60, \"gravity\": [0, 50], \"damping\": {\"lateral\": 0.01}},",
        " \"shapes\": {\"box\": {\"type\": \"rectangle\", \"width\": 20, \"height\": 10, \"mass\": 2, \"friction\": 0.5}},",
        " \"bodies\": [",
        "  {\"name\": \"ground\", \"shape\": {\"type\": \"rectangle\", \"width\": 400, \"height\": 20}, \"position\": [0, 10], \"static\": true},",
        "  {\"name\": \"ball\", \"shape\": {\"type\": \"circle\", \"radius\": 5, \"elasticity\": 0.5}, \"position\": [3, -50],",
        "   \"velocity\": [10, 0], \"angleDeg\": 30, \"layers\": [2]}],",
        " \"generators\": [{\"type\": \"rain\", \"name\": \"rain\", \"shapes\": [\"box\"], \"region\": {\"min\": [-100, -300], \"max\": [100, -100]},",
        "   \"count\": 5, \"seed\": 7, \"randomAngle\": true}],",
        " \"run\": {\"duration\": 0.5}}",
    };

    private static List<float[]> state(World world) {
        List<float[]> out = new ArrayList<>();
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            out.add(new float[] {b.getX(), b.getY(), b.getAngle(), b.getVelocityX(), b.getVelocityY(),
                b.getAngularVelocity(), b.getMass(), b.getInertia(), b.getShape().getFriction(),
                b.getShape().getElasticity(), b.getCollisionLayers(), b.isDynamic() ? 1 : 0});
        }
        return out;
    }

    @Test
    void yamlAndJsonBuildIdenticalWorlds() throws Exception {
        Scenario yaml = Scenes.valid("same.yaml", YAML);
        Scenario json = Scenes.valid("same.json", JSON);
        assertEquals(yaml.world(), json.world());
        World a = WorldBuilder.build(yaml).world();
        World b = WorldBuilder.build(json).world();
        assertEquals(7, a.getBodyCount());
        assertEquals(a.getTimestep(), b.getTimestep());
        assertEquals(a.getGravityY(), b.getGravityY());
        assertEquals(a.getDampingLateral(), b.getDampingLateral());
        for (int tick = 0; tick <= 30; tick++) {
            List<float[]> sa = state(a);
            List<float[]> sb = state(b);
            for (int i = 0; i < sa.size(); i++) {
                assertArrayEquals(sa.get(i), sb.get(i), "body " + i + " at tick " + tick);
            }
            a.tick();
            b.tick();
        }
    }
}
