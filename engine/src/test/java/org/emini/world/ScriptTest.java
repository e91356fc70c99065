package org.emini.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.event.Event;
import org.emini.event.Script;
import org.emini.io.BuildResult;
import org.emini.io.PhyBody;
import org.emini.io.PhyScript;
import org.emini.io.PhyScriptBinding;
import org.emini.io.PhyScriptElement;
import org.emini.io.PhyShape;
import org.emini.io.PhyVector;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWriter;
import org.emini.io.WorldBuilder;
import org.emini.io.WorldWriter;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** The original's scripts (issue 21, item 3): timing, effects, events that start them, world files. */
class ScriptTest {
    private static World weightless() {
        World w = new World();
        w.setGravity(0);
        return w;
    }

    private static Body box(World w) {
        Body b = new Body(0, 0, Shape.createRectangle(10, 10), true);
        w.addBody(b);
        return b;
    }

    /** The body's x velocity after each of n ticks. */
    private static List<Float> velocities(World w, Body b, int n) {
        List<Float> out = new ArrayList<>();
        for (int t = 0; t < n; t++) {
            w.tick();
            out.add(b.getVelocityX());
        }
        return out;
    }

    @Test
    void elementsLastTheirTicksThenOneMoreAndTheScriptEndsAfterAnIdleTick() {
        World w = weightless();
        Body b = box(w);
        Script s = new Script(false).addElement(Script.VELOCITY, 10, 0, 3).addElement(Script.VELOCITY, 20, 0, 2);
        w.applyScript(s, b);
        // The first element 3 ticks, the second 2 + 1, an idle tick (the velocity stays), then the end.
        assertEquals(List.of(10f, 10f, 10f, 20f, 20f, 20f, 20f), velocities(w, b, 7));
        assertEquals(1, w.getRunningScriptCount());
        w.tick();
        assertEquals(0, w.getRunningScriptCount(), "ended on the tick after the idle one");
    }

    @Test
    void aRestartingScriptBeginsAgainAndItsFirstElementThenLastsOneTickMore() {
        World w = weightless();
        Body b = box(w);
        Script s = new Script(true).addElement(Script.VELOCITY, 10, 0, 2).addElement(Script.VELOCITY, 20, 0, 1);
        w.applyScript(s, b);
        assertEquals(List.of(10f, 10f, 20f, 20f, 20f, 10f, 10f, 10f, 20f, 20f, 20f, 10f), velocities(w, b, 12));
        assertEquals(1, w.getRunningScriptCount());
    }

    @Test
    void accelerationsAddUpOverTheTicksAndAZeroTickElementNeverEnds() {
        World w = weightless();
        Body b = box(w);
        w.applyScript(new Script(false).addElement(Script.ACCELERATION, 40, -20, 10), b);
        Body spinner = box(w);
        spinner.setPosition(100, 0);
        w.applyScript(new Script(false).addElement(Script.ANGULAR_ACCELERATION, 2f, 0), spinner);
        for (int t = 0; t < 10; t++) {
            w.tick();
        }
        float dt = w.getTimestep();
        assertEquals(40 * dt * 10, b.getVelocityX(), 1e-4f);
        assertEquals(-20 * dt * 10, b.getVelocityY(), 1e-4f);
        assertEquals(2f * dt * 10, spinner.getAngularVelocity(), 1e-4f, "engine sign: the angle grows");
        for (int t = 0; t < 100; t++) {
            w.tick();
        }
        assertEquals(2f * dt * 110, spinner.getAngularVelocity(), 1e-3f, "0 ticks: for ever");
        w.removeBody(spinner);
        assertEquals(0, w.getRunningScriptCount(), "a removed body's runs stop (the first ended)");
    }

    @Test
    void positionAndAngleElementsPlaceTheBodyAtTheStartOfTheTick() {
        World w = weightless();
        Body b = box(w);
        b.setVelocity(100, 0);
        w.applyScript(new Script(false).addElement(Script.POSITION, 50, 60, 1).addElement(Script.ANGLE, 0.5f, 1), b);
        w.tick();
        assertEquals(50 + 100 * w.getTimestep(), b.getX(), 1e-4f, "placed, then moved by its velocity in the tick");
        assertEquals(60f, b.getY(), 1e-4f);
        w.tick();
        assertEquals(0.5f, b.getAngle(), 1e-6f);
        assertThrows(IllegalArgumentException.class, () -> new Script(false).addElement(7, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new Script(false).addElement(Script.VELOCITY, 0, 0, 256));
        assertThrows(IllegalArgumentException.class, () -> w.applyScript(new Script(false), new Body(0, 0, Shape.createCircle(2), true)));
    }

    @Test
    void anEventWithAScriptStartsItOnTheBodyInsteadOfTellingTheListener() {
        World w = weightless();
        Body b = box(w);
        Script push = new Script(false).addElement(Script.VELOCITY, 0, -50, 1);
        Event e = Event.createPositionEvent(b, null, -5, -5, 5, 5);
        e.setScript(push);
        e.setTriggerOnce(true);
        w.addEvent(e);
        List<Object> told = new ArrayList<>();
        w.setPhysicsEventListener((event, parameter) -> told.add(parameter));
        w.tick();
        assertEquals(List.of(), told);
        assertEquals(1, w.getRunningScriptCount());
        assertSame(push, w.getRunningScript(0));
        w.tick();
        assertEquals(-50f, b.getVelocityY(), 1e-5f, "the script ran in the next tick");
    }

    @Test
    void worldFilesKeepScriptsInTheOriginalsUnitsAndStartTheirRows() throws IOException {
        PhyWorld doc = new PhyWorld();
        doc.getShapes().add(new PhyShape(PhyVector.of(0, 5)));
        PhyBody body = new PhyBody();
        body.setFlags(PhyBody.FLAG_DYNAMIC | PhyBody.FLAG_ROTATES);
        doc.getBodies().add(body);
        PhyScript script = new PhyScript();
        script.setRestartByte(1);
        script.getElements().add(new PhyScriptElement(PhyScriptElement.TYPE_ANGULAR_VELOCITY, 1 << 24, 0, 4));
        script.getElements().add(new PhyScriptElement(PhyScriptElement.TYPE_VELOCITY, 30 << 12, -(10 << 12), 2));
        doc.getScripts().add(script);
        doc.getScriptBindings().add(new PhyScriptBinding(0, 0));
        BuildResult r = WorldBuilder.loadWorld(new ByteArrayInputStream(new PhyWriter().write(doc)), null);
        assertEquals(List.of(), r.getUnsupported());
        World w = r.getWorld();
        Script s = w.getScript(0);
        assertTrue(s.isRestarting());
        assertEquals(-1f, s.getA(0), 1e-6f, "the original's +1 rad/s turns the other way: negated");
        assertEquals(30f, s.getA(1));
        assertEquals(-10f, s.getB(1));
        assertSame(w.getBody(0), w.getRunningScriptBody(0));
        w.setGravity(0);
        w.tick();
        assertEquals(-1f, w.getBody(0).getAngularVelocity(), 1e-6f);

        ByteArrayOutputStream out = new ByteArrayOutputStream();
        WorldWriter writer = new WorldWriter();
        writer.write(w, out);
        World back = WorldBuilder.loadWorld(new ByteArrayInputStream(out.toByteArray()), null).getWorld();
        assertEquals(1, back.getScriptCount());
        assertEquals(-1f, back.getScript(0).getA(0), 1e-6f);
        assertEquals(1, back.getRunningScriptCount());
        assertTrue(String.join("\n", writer.getNotSaved()).contains("starting again from their first element"));
    }

    @Test
    void aCopiedWorldKeepsItsScriptsWhereTheyAre() {
        World w = weightless();
        Body b = box(w);
        w.applyScript(new Script(false).addElement(Script.VELOCITY, 10, 0, 2).addElement(Script.VELOCITY, 20, 0, 5), b);
        w.tick();
        w.tick();
        World copy = new World(w);
        assertEquals(velocities(w, w.getBody(0), 8), velocities(copy, copy.getBody(0), 8));
    }
}
