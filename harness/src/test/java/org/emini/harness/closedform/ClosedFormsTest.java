package org.emini.harness.closedform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Map;
import org.emini.harness.Repo;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.load.JsonPath;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.Section;
import org.junit.jupiter.api.Test;

class ClosedFormsTest {
    private static Scenario load(String id) {
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(Repo.schema()), Repo.scenarios());
        return loader.load(Repo.scenarios().resolve(id + ".yaml")).scenario();
    }

    @Test
    void aSceneKeepsItsModelWhenTheEngineLacksOneOfItsElements() {
        Scenario pendulum = load("closed-form/pendulum-90deg");
        Scenario lacking = pendulum.withElements(Map.of("ropes", new Section(null, JsonPath.ROOT.key("ropes"))));
        assertThrows(UnsupportedElementException.class, () -> WorldBuilder.build(lacking));
        ClosedForm model = ClosedForms.of(lacking);
        assertNotNull(model, "the model reads the bodies alone, never the elements");
        for (double t = 0; t < 10; t += 0.37) {
            assertEquals(ClosedForms.of(pendulum).predict("body.bob.y", t), model.predict("body.bob.y", t));
        }
    }

    @Test
    void aSceneWithoutAClosedFormHasNoModel() {
        assertNull(ClosedForms.of(load("stacking/tower-10-20hz")));
    }
}
