package org.emini.harness.expect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.emini.harness.Scenes;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.ExpectationSpec;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;

/** Expectations judged on a hand-made trace: energy 10, 12, 9, 11 at t = 0, 1, 2, 3 s; body b moving. */
class EvaluatorTest {
    private static final Trace TRACE = trace();

    private static Trace trace() {
        Trace t = new Trace(1.0, List.of("b"), List.of("energy.total", "tunnelling.count", "stability.maxSpeed",
                "stability.maxAngularSpeed", "stability.nonFinite"));
        double[] energy = {10, 12, 9, 11};
        for (int i = 0; i < 4; i++) {
            t.add(i, new double[] {i, 2 * i, 0, 1, 2, 0, energy[i], i == 3 ? 1 : 0, 3, 0, 0});
        }
        return t;
    }

    private static Verdict judge(String expectation) {
        Scenario s = Scenes.valid("e.yaml",
                "bodies: [{name: b, shape: {type: circle, radius: 1}}]",
                "run:",
                "  duration: 3",
                "  record: {metrics: [{tunnelling: {walls: [{from: [0, 0], to: [1, 1]}]}}]}",
                "  expect: [" + expectation + "]");
        ExpectationSpec e = s.run().expect().get(0);
        return Evaluator.evaluate(e, TRACE, null);
    }

    @Test
    void reductions() {
        assertEquals(11, judge("{metric: energy.total, of: final, atMost: 100}").measured());
        assertEquals(10, judge("{metric: energy.total, of: initial, atMost: 100}").measured());
        assertEquals(12, judge("{metric: energy.total, of: max, atMost: 100}").measured());
        assertEquals(9, judge("{metric: energy.total, of: min, atMost: 100}").measured());
        assertEquals(10.5, judge("{metric: energy.total, of: mean, atMost: 100}").measured());
        assertEquals(1, judge("{metric: energy.total, of: drift, atMost: 100}").measured());
        assertEquals(2, judge("{metric: energy.total, of: maxDrift, atMost: 100}").measured());
        assertEquals(0.2, judge("{metric: energy.total, of: maxDrift, relative: true, atMost: 100}").measured(), 1e-12);
        assertEquals(9, judge("{metric: energy.total, at: 2.2, atMost: 100}").measured());
        assertEquals(Math.sqrt(5), judge("{metric: body.b.speed, of: final, atMost: 100}").measured(), 1e-12);
    }

    @Test
    void windowsLimitTheSamples() {
        assertEquals(9, judge("{metric: energy.total, of: max, window: [1.5, 2.5], atMost: 100}").measured());
        assertFalse(judge("{metric: energy.total, of: max, window: [5, 6], atMost: 100}").passed());
    }

    @Test
    void bounds() {
        assertTrue(judge("{metric: energy.total, of: max, atMost: 12}").passed());
        assertFalse(judge("{metric: energy.total, of: max, atMost: 11.9}").passed());
        assertTrue(judge("{metric: energy.total, of: min, atLeast: 9}").passed());
        assertFalse(judge("{metric: energy.total, of: min, atLeast: 9.1}").passed());
        assertTrue(judge("{metric: energy.total, of: final, near: 10, tolerance: 1}").passed());
        assertFalse(judge("{metric: energy.total, of: final, near: 10, tolerance: 0.9}").passed());
    }

    @Test
    void bodiesTunnellingAndStability() {
        assertTrue(judge("{body: b, endsNear: [3, 6], tolerance: 0.1}").passed());
        assertFalse(judge("{body: b, endsNear: [3, 7], tolerance: 0.5}").passed());
        assertTrue(judge("{body: b, staysInside: {min: [0, 0], max: [3, 6]}}").passed());
        Verdict out = judge("{body: b, staysInside: {min: [0, 0], max: [2, 6]}}");
        assertFalse(out.passed());
        assertEquals(1, out.measured());
        assertFalse(judge("{noTunnelling: true}").passed());
        assertTrue(judge("{stable: {maxSpeed: 3}}").passed());
        assertFalse(judge("{stable: {maxSpeed: 2.9}}").passed());
    }

    @Test
    void nonFiniteFiguresNeverPass() {
        Trace t = new Trace(1.0, List.of(), List.of("energy.total"));
        t.add(0, new double[] {1});
        t.add(1, new double[] {Double.NaN});
        Scenario s = Scenes.valid("n.yaml", "run: {duration: 1, expect: [{metric: energy.total, of: final, atMost: 1e9}]}");
        assertFalse(Evaluator.evaluate(s.run().expect().get(0), t, null).passed());
        Scenario m = Scenes.valid("m.yaml", "run: {duration: 1, expect: [{metric: energy.total, of: max, atMost: 1e9}]}");
        assertFalse(Evaluator.evaluate(m.run().expect().get(0), t, null).passed());
    }

    @Test
    void closedFormErrors() {
        Scenario s = Scenes.valid("c.yaml",
                "world: {gravity: [0, 0]}",
                "bodies: [{name: b, shape: {type: circle, radius: 1}, velocity: [1, 1]}]",
                "reference: {closedForm: {model: projectile, body: b}}",
                "run: {duration: 3, expect: [{closedForm: body.b.y, of: maxError, atMost: 3}, "
                        + "{closedForm: body.b.y, of: finalError, atMost: 3}]}");
        // The model says y = t; the trace has y = 2t: errors 0, 1, 2, 3.
        org.emini.harness.closedform.ClosedForm model = (channel, t) -> channel.equals("body.b.y") ? t : Double.NaN;
        assertEquals(3, Evaluator.evaluate(s.run().expect().get(0), TRACE, model).measured());
        assertEquals(3, Evaluator.evaluate(s.run().expect().get(1), TRACE, model).measured());
    }
}
