package org.emini.io;

import static org.emini.io.Squares.square;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.util.ArrayList;
import java.util.List;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Circle;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** Building an engine world from a document: the original's conventions mapped, nothing dropped. */
class WorldBuilderTest {
    private static PhyWorld oneBody(PhyShape shape, PhyBody body) {
        PhyWorld w = new PhyWorld();
        w.getShapes().add(shape);
        w.getBodies().add(body);
        return w;
    }

    @Test
    void bodyStateCarriesOverWithTheAngularVelocityNegated() {
        PhyBody b = new PhyBody();
        b.setPosition(new PhyVector(411648, -82944));
        b.setVelocity(PhyVector.of(3, 4));
        b.setAngleRaw(PhyFixed.PI_2FX / 2);
        b.setAngularVelocityRaw(PhyFixed.FX2_ONE);
        PhyWorld doc = oneBody(square(10), b);
        PhyWorldSettings noGravity = new PhyWorldSettings();
        noGravity.setGravity(PhyVector.ZERO);
        doc.setSettings(noGravity);
        BuildResult r = new WorldBuilder().build(doc);
        Body body = r.getBody(0);
        assertEquals(100.5f, body.getX());
        assertEquals(-20.25f, body.getY());
        assertEquals(3f, body.getVelocityX());
        assertEquals(4f, body.getVelocityY());
        assertEquals(PhyFixed.fx2(PhyFixed.PI_2FX / 2), body.getAngle());
        assertEquals(-1f, body.getAngularVelocity(), "the original's +1 rad/s turns counter-clockwise on screen");
        // The original advances angle ← angle − ω·dt: one free tick lowers the angle by dt.
        World world = r.getWorld();
        float before = body.getAngle();
        world.tick();
        assertEquals(before - world.getTimestep(), body.getAngle(), 1e-5f);
        // Counter-clockwise on a y-down screen: the local +x axis turns toward −y.
        assertTrue(body.toWorldY(1, 0) - body.getY() < 1f - 1e-4f);
    }

    @Test
    void theAngleIsWrappedIntoZeroToTwoPiAsTheOriginalLoadsIt() {
        PhyBody b = new PhyBody();
        b.setAngleRaw(-PhyFixed.PI_2FX / 2);
        Body body = new WorldBuilder().build(oneBody(square(10), b)).getBody(0);
        assertEquals(PhyFixed.fx2(PhyFixed.TWO_PI_2FX - PhyFixed.PI_2FX / 2), body.getAngle());
    }

    @Test
    void aCircleGetsTheOriginalsWholePixelRadius() {
        BuildResult r = new WorldBuilder().build(oneBody(new PhyShape(PhyVector.of(3, -15.9f)), new PhyBody()));
        Circle c = (Circle) r.getShape(0);
        assertEquals(16f, c.getRadius(), "|(3, −15.9)| = 16.18 → 16");
        assertEquals(0f, c.getCenterX());
        assertEquals(0f, c.getCenterY());
        BuildResult tiny = new WorldBuilder().build(oneBody(new PhyShape(PhyVector.of(0.5f, 0.5f)), new PhyBody()));
        assertNull(tiny.getShape(0));
        assertEquals("shape 0: a circle whose radius truncates to 0 px", tiny.getUnsupported().get(0).toString());
        assertEquals("body 0: its shape 0 is not built", tiny.getUnsupported().get(1).toString());
        assertEquals(0, tiny.getWorld().getBodyCount());
    }

    @Test
    void aLineBecomesAThinSlabThatHoldsABox() {
        PhyWorld doc = new PhyWorld();
        doc.getShapes().add(new PhyShape(PhyVector.of(100, 0), PhyVector.of(-100, 0)));
        doc.getShapes().add(square(10));
        PhyBody floor = new PhyBody();
        floor.setFlags(PhyBody.FLAG_ROTATES);
        doc.getBodies().add(floor);
        PhyBody box = new PhyBody();
        box.setShapeIndex(1);
        box.setPosition(PhyVector.of(0, -40));
        doc.getBodies().add(box);
        BuildResult r = new WorldBuilder().setLineThickness(2).build(doc);
        Polygon slab = (Polygon) r.getShape(0);
        assertEquals(4, slab.getVertexCount());
        assertEquals(400f, slab.getArea(), 1e-3f);
        assertEquals(UnsupportedElement.Kind.SHAPE, r.getApproximations().get(0).getKind());
        assertTrue(r.getUnsupported().isEmpty());
        for (int i = 0; i < 100; i++) {
            r.getWorld().tick();
        }
        assertEquals(-11f, r.getBody(1).getY(), 0.1f, "the box rests on the slab's upper face");
        assertThrows(IllegalArgumentException.class, () -> new WorldBuilder().setLineThickness(0));
    }

    @Test
    void theLineSlabIsListedInTheOriginalsWinding() {
        float[] xy = WorldBuilder.lineSlab(PhyVector.of(-100, 0), PhyVector.of(100, 0), 1);
        assertEquals(List.of(-100f, 0.5f, 100f, 0.5f, 100f, -0.5f, -100f, -0.5f),
                List.of(xy[0], xy[1], xy[2], xy[3], xy[4], xy[5], xy[6], xy[7]));
        float winding = 0;
        for (int i = 0; i < 4; i++) {
            int j = (i + 1) % 4;
            winding += xy[2 * j] * xy[2 * i + 1] - xy[2 * j + 1] * xy[2 * i];
        }
        assertTrue(winding > 0, "x(i+1)·y(i) − y(i+1)·x(i) sums positive, as in every designer file");
        assertNull(WorldBuilder.lineSlab(PhyVector.of(3, 4), PhyVector.of(3, 4), 1));
    }

    @Test
    void flagsAndLayersCarryOver() {
        PhyBody b = new PhyBody();
        b.setFlags(PhyBody.FLAG_NOT_INTERACTING | PhyBody.FLAG_NO_GRAVITY);
        b.setCollisionLayers(0x80000001);
        Body body = new WorldBuilder().build(oneBody(square(10), b)).getBody(0);
        assertFalse(body.isDynamic());
        assertFalse(body.canRotate());
        assertFalse(body.isInteracting());
        assertFalse(body.isAffectedByGravity());
        assertEquals(0x80000001, body.getCollisionLayers());
        PhyBody d = new PhyBody();
        d.setFlags(PhyBody.FLAG_DYNAMIC | PhyBody.FLAG_ROTATES);
        Body dynamic = new WorldBuilder().build(oneBody(square(10), d)).getBody(0);
        assertTrue(dynamic.isDynamic() && dynamic.canRotate() && dynamic.isInteracting()
                && dynamic.isAffectedByGravity());
    }

    @Test
    void materialAndMassAreTheStoredFactors() {
        PhyShape s = square(10);
        s.setElasticityRaw(99 * 4096 / 100);
        s.setFrictionRaw(1024);
        s.setMassRaw(8192);
        Shape shape = new WorldBuilder().build(oneBody(s, new PhyBody())).getShape(0);
        assertEquals(0.98999023f, shape.getElasticity());
        assertEquals(0.25f, shape.getFriction());
        assertEquals(2f, shape.getMass());
        PhyShape odd = square(10);
        odd.setFrictionRaw(8192);
        odd.setElasticityRaw(-1);
        odd.setMassRaw(0);
        BuildResult r = new WorldBuilder().build(oneBody(odd, new PhyBody()));
        assertEquals(1f, r.getShape(0).getFriction());
        assertEquals(0f, r.getShape(0).getElasticity());
        assertEquals(1f, r.getShape(0).getMass());
        assertEquals(3, r.getApproximations().size(), r.getApproximations().toString());
    }

    @Test
    void bodiesShareTheirShapeAsInTheOriginal() {
        PhyWorld doc = oneBody(square(10), new PhyBody());
        doc.getBodies().add(new PhyBody());
        BuildResult r = new WorldBuilder().build(doc);
        assertSame(r.getBody(0).getShape(), r.getBody(1).getShape());
        assertSame(r.getShape(0), r.getBody(0).getShape());
    }

    @Test
    void worldSettingsSetGravityAndDamping() {
        PhyWorld doc = oneBody(square(10), new PhyBody());
        World defaults = new WorldBuilder().build(doc).getWorld();
        assertEquals(0f, defaults.getGravityX());
        assertEquals(100f, defaults.getGravityY());
        PhyWorldSettings s = new PhyWorldSettings();
        s.setGravity(PhyVector.of(10, -50));
        s.setDampingLinearRaw(410);
        s.setDampingRotationalRaw(205);
        doc.setSettings(s);
        World w = new WorldBuilder().build(doc).getWorld();
        assertEquals(10f, w.getGravityX());
        assertEquals(-50f, w.getGravityY());
        assertEquals(410 / 4096f, w.getDampingLateral());
        assertEquals(205 / 4096f, w.getDampingRotational());
        assertEquals(1f / 20f, w.getTimestep(), "the file stores no timestep");
        assertEquals(10, w.getConstraintIterations());
        s.setDampingLinearRaw(5000);
        BuildResult r = new WorldBuilder().build(doc);
        assertEquals(1f, r.getWorld().getDampingLateral());
        assertEquals(UnsupportedElement.Kind.WORLD_SETTINGS, r.getApproximations().get(0).getKind());
    }

    @Test
    void theUserDataFactorySeesEveryStoredStringWithItsType() {
        PhyWorld doc = everyKindWithUserData();
        List<String> calls = new ArrayList<>();
        BuildResult r = new WorldBuilder().setUserData((data, type) -> {
            calls.add(type + ":" + data);
            return "object " + data;
        }).build(doc);
        assertEquals(List.of("2:shape", "2:multi", "1:body", "4:joint", "3:event", "1:sensor", "5:emitter", "6:world"),
                calls, "the landscape material's string is discarded");
        assertEquals("object body", r.getBody(0).getUserData());
        assertEquals("object joint", r.getUserData(doc.getConstraints().get(0)));
        assertEquals("object sensor", r.getUserData(doc.getEvents().get(0).getSensor()));
        assertEquals("object world", r.getUserData(doc.getSettings()));
        assertNull(r.getUserData(doc.getLandscape().getMaterial()));
        BuildResult none = new WorldBuilder().build(doc);
        assertNull(none.getBody(0).getUserData());
        assertNull(none.getUserData(doc.getSettings()));
    }

    @Test
    void versionsWithoutUserDataNeverCallTheFactory() {
        PhyWorld doc = oneBody(square(10), new PhyBody());
        doc.setVersionWord(0x0600);
        BuildResult r = new WorldBuilder().setUserData((data, type) -> {
            throw new AssertionError("called for " + data);
        }).build(doc);
        assertEquals(1, r.getWorld().getBodyCount());
    }

    private static PhyWorld everyKindWithUserData() {
        PhyWorld w = new PhyWorld();
        PhyShape s = square(10);
        s.setUserData("shape");
        w.getShapes().add(s);
        PhyMultiShape m = new PhyMultiShape(0);
        m.setUserData("multi");
        w.getShapes().add(m);
        PhyBody b = new PhyBody();
        b.setUserData("body");
        w.getBodies().add(b);
        PhyLandscape l = new PhyLandscape();
        l.getMaterial().setUserData("material");
        l.getSegments().add(new PhySegment(PhyVector.of(-100, 50), PhyVector.of(100, 50), 0));
        w.setLandscape(l);
        PhyJoint j = new PhyJoint();
        j.setUserData("joint");
        w.getConstraints().add(j);
        PhyEvent e = new PhyEvent();
        e.setType(PhyEvent.TYPE_BODY_SENSOR);
        PhyBody sensor = new PhyBody();
        sensor.setUserData("sensor");
        e.setSensor(sensor);
        e.setUserData("event");
        w.getEvents().add(e);
        PhyParticleEmitter p = new PhyParticleEmitter();
        p.setUserData("emitter");
        w.getParticleEmitters().add(p);
        PhyWorldSettings ws = new PhyWorldSettings();
        ws.setUserData("world");
        w.setSettings(ws);
        return w;
    }

    @Test
    void recordsTheEngineCannotBuildAreNamedAndCounted() {
        PhyWorld doc = everyKindWithUserData();
        PhyBody onMulti = new PhyBody();
        onMulti.setShapeIndex(1);
        doc.getBodies().add(onMulti);
        doc.getConstraints().add(new PhySpring());
        doc.getConstraints().add(new PhyMotor());
        doc.getScripts().add(new PhyScript());
        doc.getScriptBindings().add(new PhyScriptBinding(0, 9));
        doc.getLandscape().getSegments().add(new PhySegment(PhyVector.ZERO, PhyVector.of(5, 5), 1));
        BuildResult r = new WorldBuilder().build(doc);
        assertEquals(1, r.getUnsupportedCount(UnsupportedElement.Kind.JOINT), "a joint of body 0 with itself");
        assertEquals(1, r.getUnsupportedCount(UnsupportedElement.Kind.SPRING), "a spring of body 0 with itself");
        assertEquals(0, r.getUnsupportedCount(UnsupportedElement.Kind.SCRIPT), "scripts are built");
        assertEquals(1, r.getWorld().getScriptCount());
        assertEquals(1, r.getUnsupportedCount(UnsupportedElement.Kind.SCRIPT_BINDING), "a row naming a body that is not there");
        assertEquals(1, r.getUnsupportedCount(UnsupportedElement.Kind.PARTICLE_EMITTER), "capacity 0");
        assertEquals(4, r.getUnsupported().size(), r.getUnsupported().toString());
        assertEquals(2, r.getWorld().getBodyCount(), "the body on the multishape too");
        assertEquals(2, r.getWorld().getLandscape().getSegmentCount());
        assertEquals(1, r.getWorld().getConstraintCount());
        assertEquals(1, r.getWorld().getEventCount());
        assertTrue(r.toString().contains("4 unsupported"), r.toString());
    }

    @Test
    void aShapeTheEngineRefusesIsListedWithTheEnginesReason() {
        PhyShape concave = new PhyShape(PhyVector.of(0, 0), PhyVector.of(10, 10), PhyVector.of(20, 0),
                PhyVector.of(10, 30));
        BuildResult r = new WorldBuilder().build(oneBody(concave, new PhyBody()));
        UnsupportedElement e = r.getUnsupported().get(0);
        assertEquals(UnsupportedElement.Kind.SHAPE, e.getKind());
        assertTrue(e.getReason().contains("NOT_CONVEX"), e.getReason());
        PhyVector[] many = new PhyVector[13];
        for (int i = 0; i < many.length; i++) {
            double a = 2 * Math.PI * i / many.length;
            many[i] = PhyVector.of((float) (10 * Math.cos(a)), (float) (10 * Math.sin(a)));
        }
        BuildResult thirteen = new WorldBuilder().build(oneBody(new PhyShape(many), new PhyBody()));
        assertEquals("shape 0: 13 vertices: the original leaves such a shape unusable (at most 12)",
                thirteen.getUnsupported().get(0).toString());
        BuildResult empty = new WorldBuilder().build(oneBody(new PhyShape(), new PhyBody()));
        assertEquals(UnsupportedElement.Kind.SHAPE, empty.getUnsupported().get(0).getKind());
    }

    @Test
    void aReferenceToNoRecordIsListedNotThrown() {
        PhyBody b = new PhyBody();
        b.setShapeIndex(5);
        BuildResult r = new WorldBuilder().build(oneBody(square(10), b));
        assertEquals("body 0: its shape 5 does not exist", r.getUnsupported().get(0).toString());
        assertEquals(0, r.getWorld().getBodyCount());
    }

    @Test
    void aStaticBodyWithAStoredVelocityIsNoted() {
        PhyBody b = new PhyBody();
        b.setFlags(PhyBody.FLAG_ROTATES);
        b.setVelocity(PhyVector.of(5, 0));
        BuildResult r = new WorldBuilder().build(oneBody(square(10), b));
        assertEquals(0f, r.getBody(0).getVelocityX());
        assertEquals(UnsupportedElement.Kind.BODY, r.getApproximations().get(0).getKind());
    }

    @Test
    void loadWorldReadsAndBuildsLikeTheOriginal() throws Exception {
        byte[] file = new PhyWriter().write(everyKindWithUserData());
        BuildResult r = WorldBuilder.loadWorld(new ByteArrayInputStream(file), (data, type) -> data.toUpperCase());
        assertEquals("BODY", r.getBody(0).getUserData());
        assertEquals(everyKindWithUserData(), withoutLayout(r.getDocument()));
    }

    private static PhyWorld withoutLayout(PhyWorld w) {
        w.getLayout().clear();
        return w;
    }
}
