package org.emini.harness.expect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.harness.Scenes;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.SceneResult;
import org.emini.harness.scenario.ExpectationSpec;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;

/** A bare generator name in an expectation stands for the generator's bodies, as {@code NAME[*]} does. */
class GeneratorGroupTest {
    private static final String TOWER = String.join("\n",
            "world: {ticksPerSecond: 20}",
            "shapes: {ground: {type: rectangle, width: 800, height: 40}, box: {type: rectangle, width: 20, height: 20}}",
            "bodies:",
            "  - {name: ground, shape: ground, position: [0, 20], static: true}",
            "generators: [{type: tower, name: box, shape: box, base: [0, -10], count: 5}]",
            "run:",
            "  duration: 2",
            "  record: {bodies: none}",
            "  expect:");

    @Test
    void aBareGeneratorNameIsItsBodiesInChannelsAndBodyKeys() {
        Scenario s = Scenes.valid("tower.yaml", TOWER,
                "    - {metric: body.box.displacement, of: max, atMost: 1}",
                "    - {body: box, staysInside: {min: [-20, -120], max: [20, 0]}}",
                "    - {metric: body.box.y, of: final, atMost: -80}");
        ExpectationSpec first = s.run().expect().get(0);
        assertEquals("body.box[*].displacement", first.channel());
        assertEquals("box[*]", first.group());
        assertEquals("box[*]", s.run().expect().get(1).body());
        SceneResult r = ScenarioRunner.run(s, n -> { });
        assertEquals(5, r.trace().bodies().size(), r.trace().bodies().toString());
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        assertTrue(r.verdicts().get(0).detail().contains("of 5 bodies"), r.verdicts().get(0).detail());
        assertTrue(r.verdicts().get(1).passed(), r.verdicts().get(1).detail());
        // Four boxes end below y = -80 (the top one at -90 does not): the bare name fails as the group does.
        assertFalse(r.verdicts().get(2).passed());
        assertTrue(r.verdicts().get(2).detail().startsWith("box[0]") && r.verdicts().get(2).detail().contains("4 of 5"),
                r.verdicts().get(2).detail());
    }

    @Test
    void aBodyWithTheGeneratorsNameMakesTheBareNameAmbiguous() {
        String clash = TOWER.replace("  - {name: ground,", "  - {name: box, shape: box, position: [300, -10]}\n  - {name: ground,");
        ScenarioLoader.Loaded l = Scenes.load("clash.yaml", clash, "    - {metric: body.box.y, of: final, atMost: 0}");
        assertEquals("'box' names both a body and the generator box: write box[*] for the generator's bodies, "
                + "or rename the body", Scenes.onlyProblem(l).message());
        assertEquals("$.run.expect[0].metric", Scenes.onlyProblem(l).path());
        // Written as a group, or as another body's name, there is no ambiguity.
        assertTrue(Scenes.load("clash.yaml", clash, "    - {metric: 'body.box[*].y', of: final, atMost: 0}").ok());
        assertTrue(Scenes.load("clash.yaml", clash, "    - {metric: body.ground.y, of: final, atMost: 100}").ok());
    }
}
