package org.emini.harness.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.harness.Scenes;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Trace;
import org.junit.jupiter.api.Test;

/** Each metric on a case small enough to work out by hand (values at tick 0, before any tick). */
class MetricsTest {
    // One 20 x 20 box of mass 2 (I = m (w² + h²) / 12 = 133.33) at (10, -20), v = (3, 4), ω = 0.5,
    // plus a static ground that must not count.
    private static Trace oneBox(String metrics) {
        SceneResult r = ScenarioRunner.run(Scenes.valid("box.yaml",
                "shapes: {box: {type: rectangle, width: 20, height: 20, mass: 2}}",
                "bodies:",
                "  - {name: box, shape: box, position: [10, -20], velocity: [3, 4], angularVelocity: 0.5}",
                "  - {name: ground, shape: {type: rectangle, width: 100, height: 10}, position: [0, 500], static: true}",
                "run: {duration: 0.05, record: {metrics: " + metrics + "}}"), n -> { });
        return r.trace();
    }

    @Test
    void energyIsKineticPlusGravitationalPotential() {
        Trace t = oneBox("[energy]");
        double kinetic = 0.5 * 2 * 25 + 0.5 * (2 * 800 / 12.0) * 0.25;   // 25 + 16.667
        double potential = -2 * (100 * -20.0);                          // −m g·r = 4000
        assertEquals(kinetic, t.column("energy.kinetic")[0], 1e-3);
        assertEquals(potential, t.column("energy.potential")[0], 1e-3);
        assertEquals(kinetic + potential, t.column("energy.total")[0], 1e-3);
    }

    @Test
    void linearMomentumIsMassTimesVelocity() {
        Trace t = oneBox("[linearMomentum]");
        assertEquals(6, t.column("momentum.x")[0], 1e-6);
        assertEquals(8, t.column("momentum.y")[0], 1e-6);
    }

    @Test
    void angularMomentumAboutAPoint() {
        Trace origin = oneBox("[angularMomentum]");
        // I ω + m (x vy − y vx) = 66.667 + 2 (10·4 − (−20)·3) = 266.667
        assertEquals(2 * 800 / 12.0 * 0.5 + 200, origin.column("angularMomentum")[0], 1e-3);
        Trace about = oneBox("[{angularMomentum: {about: [10, -20]}}]");
        assertEquals(2 * 800 / 12.0 * 0.5, about.column("angularMomentum")[0], 1e-3);
    }

    @Test
    void stabilityReportsTheLargestSpeeds() {
        Trace t = oneBox("[stability]");
        assertEquals(5, t.column("stability.maxSpeed")[0], 1e-6);
        assertEquals(0.5, t.column("stability.maxAngularSpeed")[0], 1e-6);
        assertEquals(0, t.column("stability.nonFinite")[0]);
    }

    @Test
    void tunnellingCountsACrossingOfAWallLine() {
        // A non-interacting body flies through a wall segment: exactly one crossing, none before it.
        SceneResult r = ScenarioRunner.run(Scenes.valid("ghost.yaml",
                "world: {gravity: [0, 0]}",
                "bodies:",
                "  - {name: ghost, shape: {type: circle, radius: 1}, position: [-10, 0], velocity: [100, 0], interacting: false}",
                "run:",
                "  duration: 0.5",
                "  record: {metrics: [{tunnelling: {walls: [{from: [0, -5], to: [0, 5]}]}}]}"), n -> { });
        double[] count = r.trace().column("tunnelling.count");
        assertEquals(0, count[1]);
        assertEquals(1, count[count.length - 1]);
    }

    @Test
    void segmentsCrossOnlyWhenThePathPassesTheLine() {
        assertTrue(Segments.cross(-1, 0, 1, 0, 0, -1, 0, 1));
        assertTrue(!Segments.cross(-1, 2, 1, 2, 0, -1, 0, 1));   // passes beyond the end
        assertTrue(!Segments.cross(-1, 0, 0, 0, 0, -1, 0, 1));   // stops on the line
        assertTrue(!Segments.cross(-1, 0, -0.5, 0, 0, -1, 0, 1));
    }

    @Test
    void penetrationMeasuresOverlapAfterTheTick() {
        // A box created 2 px deep in the ground: after one tick some overlap remains, never more than 2 px,
        // on the two corner points of a face contact.
        SceneResult r = ScenarioRunner.run(Scenes.valid("sunk.yaml",
                "world: {gravity: [0, 0]}",
                "bodies:",
                "  - {name: ground, shape: {type: rectangle, width: 200, height: 20}, position: [0, 10], static: true}",
                "  - {name: box, shape: {type: rectangle, width: 20, height: 20}, position: [0, -8]}",
                "run: {duration: 0.05, record: {metrics: [penetration]}}"), n -> { });
        Trace t = r.trace();
        assertEquals(0, t.column("penetration.points")[0], "no contacts exist before the first tick");
        double max = t.column("penetration.max")[1];
        assertTrue(max > 0 && max <= 2.0001, "max " + max);
        assertEquals(2, t.column("penetration.points")[1]);
        assertTrue(t.column("penetration.mean")[1] <= max);
    }

    @Test
    void penetrationMeasuresLandscapeContactsAndMultiShapeParts() {
        // The same 2 px deep box, on a landscape floor: a landscape contact has no body B.
        SceneResult land = ScenarioRunner.run(Scenes.valid("sunk-land.yaml",
                "world: {gravity: [0, 0]}",
                "bodies: [{name: box, shape: {type: rectangle, width: 20, height: 20}, position: [0, -8]}]",
                "landscape: {segments: [{from: [-100, 0], to: [100, 0]}]}",
                "run: {duration: 0.05, record: {metrics: [penetration]}}"), n -> { });
        double max = land.trace().column("penetration.max")[1];
        assertTrue(max > 0 && max <= 2.0001, "max " + max);
        assertEquals(2, land.trace().column("penetration.points")[1]);
        // A multi-shape (two boxes side by side) 2 px deep in a static ground: measured part by part.
        SceneResult multi = ScenarioRunner.run(Scenes.valid("sunk-multi.yaml",
                "world: {gravity: [0, 0]}",
                "shapes:",
                "  sq: {type: rectangle, width: 20, height: 20}",
                "  pair: {type: multiShape, parts: [{shape: sq, offset: [-10, 0]}, {shape: sq, offset: [10, 0]}]}",
                "bodies:",
                "  - {name: ground, shape: {type: rectangle, width: 200, height: 20}, position: [0, 10], static: true}",
                "  - {name: pair, shape: pair, position: [0, -8]}",
                "run: {duration: 0.05, record: {metrics: [penetration]}}"), n -> { });
        max = multi.trace().column("penetration.max")[1];
        assertTrue(max > 0 && max <= 2.0001, "max " + max);
        assertEquals(4, multi.trace().column("penetration.points")[1]);
    }

    @Test
    void penetrationOfABodyPushedPastAThinSegmentIsItsDepthFromTheSideItCameFrom() {
        // A ball that has sunk 15 px into a floor of no thickness (its centre 5 px past the line): the
        // contact keeps the side it touched from, so the depth reads 15 px, not 5 px from below.
        SceneResult r = ScenarioRunner.run(Scenes.valid("deep.yaml",
                "world: {gravity: [0, 0]}",
                "bodies: [{name: ball, shape: {type: circle, radius: 10}, position: [0, -10.5], velocity: [0, 60]}]",
                "landscape: {segments: [{from: [-100, 0], to: [100, 0]}]}",
                "run: {duration: 1, record: {metrics: [penetration, {tunnelling: {walls: [{from: [-100, 0], to: [100, 0]}]}}]}}"),
                n -> { });
        double[] max = r.trace().column("penetration.max");
        for (double m : max) {
            assertTrue(m < 1, "a ball stopped by the floor is never deep: " + m);
        }
        assertEquals(0, r.trace().column("tunnelling.count")[max.length - 1]);
    }

    @Test
    void particlesCountsLiveParticlesAndThoseOutsideTheRegion() {
        // 20 particles a tick straight up at 100 px/s without gravity: after 3 ticks 60 exist, those born
        // in the first tick are 10 to 15 px up; a region ending 12 px above the emitter leaves some out.
        SceneResult r = ScenarioRunner.run(Scenes.valid("jet.yaml",
                "world: {gravity: [0, 0]}",
                "particles:",
                "  - {name: jet, from: [0, 0], rate: 400, lifetime: 10, speed: 100, angleDeg: -90}",
                "  - {name: other, from: [500, 0], rate: 400, lifetime: 10}",
                "run:",
                "  duration: 0.15",
                "  record: {metrics: [{particles: {emitters: [jet], region: {min: [-1, -12], max: [1, 0]}}}]}"),
                n -> { });
        double[] count = r.trace().column("particles.count");
        double[] outside = r.trace().column("particles.outside");
        assertEquals(0, count[0]);
        assertEquals(20, count[1]);
        assertEquals(60, count[3]);
        assertEquals(0, outside[1]);
        assertTrue(outside[3] > 0 && outside[3] <= 20, "outside " + outside[3]);
    }

    @Test
    void theParticlesMetricNeedsEmittersWithKnownNames() {
        assertTrue(Scenes.load("none.yaml", "run: {duration: 1, record: {metrics: [particles]}}").problems().toString()
                .contains("the particles metric needs emitters"));
        assertTrue(Scenes.load("wrong.yaml", "particles: [{from: [0, 0]}]",
                "run: {duration: 1, record: {metrics: [{particles: {emitters: [jet]}}]}}").problems().toString()
                .contains("no emitter named 'jet'"));
    }
}
