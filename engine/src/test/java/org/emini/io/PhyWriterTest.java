package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import org.junit.jupiter.api.Test;

/** Writing: the designer's order, section splitting, and refusal of what a version cannot store. */
class PhyWriterTest {
    /** A version-10 document holding one record of every kind. */
    private static PhyWorld everyKind() {
        PhyWorld w = new PhyWorld();
        w.getShapes().add(new PhyShape(PhyVector.of(0, 10)));
        w.getShapes().add(new PhyMultiShape(0));
        PhyBody b = new PhyBody();
        b.setUserData("element=playerspawn");
        w.getBodies().add(b);
        PhyLandscape l = new PhyLandscape();
        l.getSegments().add(new PhySegment(PhyVector.of(0, 0), PhyVector.of(100, 0), PhySegment.FACE_LEFT));
        w.setLandscape(l);
        w.getConstraints().add(new PhyMotor());
        PhyScript s = new PhyScript();
        s.getElements().add(new PhyScriptElement(PhyScriptElement.TYPE_VELOCITY, 4096, 0, 20));
        w.getScripts().add(s);
        w.getScriptBindings().add(new PhyScriptBinding(0, 0));
        w.getEvents().add(new PhyEvent());
        w.getParticleEmitters().add(new PhyParticleEmitter());
        w.setSettings(new PhyWorldSettings());
        return w;
    }

    private static PhyWorld roundTrip(PhyWorld w) throws PhyFormatException {
        return new PhyReader().read(new PhyWriter().write(w));
    }

    @Test
    void aDocumentBuiltInCodeIsWrittenInTheDesignersOrder() throws Exception {
        PhyWorld back = roundTrip(everyKind());
        List<Integer> tags = new ArrayList<>();
        back.getLayout().forEach(s -> tags.add(s.getTag()));
        assertEquals(List.of(PhySection.SHAPES, PhySection.BODIES, PhySection.LANDSCAPE, PhySection.CONSTRAINTS,
                PhySection.SCRIPTS, PhySection.EVENTS, PhySection.PARTICLES, PhySection.WORLD), tags);
        back.getLayout().clear();
        assertEquals(everyKind(), back);
    }

    @Test
    void anEmptyDocumentIsJustTheVersionWord() throws Exception {
        byte[] b = new PhyWriter().write(new PhyWorld());
        assertArrayEquals(new byte[] {0, 0, 0x0A, 0}, b);
        assertEquals(new PhyWorld(), new PhyReader().read(b));
        byte[] v1 = new PhyWriter().write(new PhyWorld(0x0100));
        assertArrayEquals(new byte[] {0, 0, 1, 0, 0, 0, 0, 0}, v1, "version 1 always has its four sections");
    }

    @Test
    void moreThan255RecordsAreSplitOverSections() throws Exception {
        PhyWorld w = new PhyWorld();
        for (int i = 0; i < 300; i++) {
            w.getShapes().add(new PhyShape(PhyVector.of(0, 1 + i % 50)));
        }
        for (int i = 0; i < 600; i++) {
            PhyBody b = new PhyBody();
            b.setShapeIndex(i % 255);
            b.setPosition(PhyVector.of(i, 0));
            w.getBodies().add(b);
        }
        for (int i = 0; i < 256; i++) {
            w.getEvents().add(new PhyEvent());
        }
        for (int i = 0; i < 300; i++) {
            w.getScriptBindings().add(new PhyScriptBinding(0, PhyWorld.NONE));
        }
        w.getScripts().add(new PhyScript());
        PhyWorld back = roundTrip(w);
        assertEquals(List.of(new PhySection(PhySection.SHAPES, 255, 0), new PhySection(PhySection.SHAPES, 45, 0),
                new PhySection(PhySection.BODIES, 255, 0), new PhySection(PhySection.BODIES, 255, 0),
                new PhySection(PhySection.BODIES, 90, 0), new PhySection(PhySection.SCRIPTS, 1, 255),
                new PhySection(PhySection.SCRIPTS, 0, 45), new PhySection(PhySection.EVENTS, 255, 0),
                new PhySection(PhySection.EVENTS, 1, 0)), back.getLayout());
        back.getLayout().clear();
        assertEquals(w, back);
    }

    @Test
    void versionOneHoldsAt255OfAKind() {
        PhyWorld w = new PhyWorld(0x01F0);
        w.getShapes().add(new PhyShape(PhyVector.of(0, 5)));
        for (int i = 0; i < 256; i++) {
            w.getBodies().add(new PhyBody());
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new PhyWriter().write(w));
        assertEquals("PhyWriter.write: version 1 holds at most 255 bodies, got 256", e.getMessage());
    }

    private static void refuses(int version, Consumer<PhyWorld> edit, String message) {
        PhyWorld w = new PhyWorld(version);
        w.getShapes().add(new PhyShape(PhyVector.of(0, 5)));
        w.getBodies().add(new PhyBody());
        edit.accept(w);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new PhyWriter().write(w));
        assertTrue(e.getMessage().startsWith("PhyWriter.write: "), e.getMessage());
        assertTrue(e.getMessage().contains(message), e.getMessage() + " should contain " + message);
    }

    @Test
    void whatAVersionCannotStoreIsRefusedNotDropped() {
        refuses(0x0600, w -> w.getBodies().get(0).setUserData("x"), "cannot store the user data of body 0");
        refuses(0x0700, w -> {
            w.getConstraints().add(new PhyJoint());
            w.getConstraints().get(0).setUserData("x");
        }, "cannot store the user data of constraint 0");
        refuses(0x0800, w -> w.getShapes().add(new PhyMultiShape(0)), "cannot store multishapes; shape 1 is one");
        refuses(0x0100, w -> w.setLandscape(new PhyLandscape()), "cannot store a landscape");
        refuses(0x0100, w -> w.setSettings(new PhyWorldSettings()), "cannot store a world record");
        refuses(0x0100, w -> w.getScripts().add(new PhyScript()), "cannot store scripts");
        refuses(0x0100, w -> w.getParticleEmitters().add(new PhyParticleEmitter()), "cannot store particle emitters");
        refuses(0x0400, w -> ((PhyShape) w.getShapes().get(0)).setMassRaw(8192), "stores no shape mass; shape 0");
        refuses(0x0900, w -> {
            PhyWorldSettings s = new PhyWorldSettings();
            s.setDampingLinearRaw(10);
            w.setSettings(s);
        }, "stores one damping for both");
        refuses(0x0300, w -> {
            w.getEvents().add(new PhyEvent());
            w.getEvents().get(0).setTriggerOnceByte(1);
        }, "stores no trigger-once flag or constraint filter; event 0");
        refuses(0x0A00, w -> {
            w.getEvents().add(new PhyEvent());
            w.getEvents().get(0).setType(PhyEvent.TYPE_BODY_SENSOR);
        }, "event 0 of type 5 needs a sensor body");
        refuses(0x0A00, w -> {
            w.getEvents().add(new PhyEvent());
            w.getEvents().get(0).setSensor(new PhyBody());
        }, "event 0 of type 0 cannot store its sensor body");
        refuses(0x0A00, w -> w.setTrailingBytes(new byte[] {0}), "cannot store trailing bytes");
        refuses(0x0A00, w -> w.getBodies().get(0).setShapeIndex(1), "body 0 shape index 1 names no entry");
        refuses(0x0A00, w -> w.getShapes().add(new PhyMultiShape(1)), "shape 1 part shape index 1 names no entry");
        refuses(0x0A00, w -> {
            PhyEvent e = new PhyEvent();
            e.setConstraintFilter(0);
            w.getEvents().add(e);
        }, "event 0 constraint filter 0 names no entry");
    }

    @Test
    void anEditedFileIsWrittenInTheDesignersOrderWithItsEdit() throws Exception {
        PhyWorld w = new PhyWorld();
        w.getShapes().add(new PhyShape(PhyVector.of(0, 5)));
        w.getBodies().add(new PhyBody());
        w.setSettings(new PhyWorldSettings());
        PhyWorld read = roundTrip(w);
        PhyBody extra = new PhyBody();
        extra.setPosition(PhyVector.of(7, 8));
        read.getBodies().add(extra);
        PhyWorld back = roundTrip(read);
        assertEquals(2, back.getBodies().size());
        assertEquals(extra, back.getBodies().get(1));
        assertEquals(List.of(new PhySection(PhySection.SHAPES, 1, 0), new PhySection(PhySection.BODIES, 2, 0),
                new PhySection(PhySection.WORLD, 0, 0)), back.getLayout());
    }

    @Test
    void aReferenceMovedBehindItsTargetFallsBackToTheDesignersOrder() throws Exception {
        // A file whose bodies come before a second shapes section; pointing a body at the later shape
        // cannot be written in that layout, so the writer reorders.
        byte[] file = Bytes.version(0x0A00).u8(PhySection.SHAPES, 1).square10(5, "").u8(0)
                .u8(PhySection.BODIES, 1).body10(0, 0, 0, "")
                .u8(PhySection.SHAPES, 1).square10(9, "").u8(0).bytes();
        PhyWorld w = new PhyReader().read(file);
        w.getBodies().get(0).setShapeIndex(1);
        PhyWorld back = roundTrip(w);
        assertEquals(1, back.getBodies().get(0).getShapeIndex());
        assertEquals(List.of(new PhySection(PhySection.SHAPES, 2, 0), new PhySection(PhySection.BODIES, 1, 0)),
                back.getLayout());
    }

    @Test
    void upgradingAVersionOneFileKeepsItsContent() throws Exception {
        byte[] file = Bytes.version(0x01F0).u8(1, 0, 1).px(0, -15).i32(1536, 1024)
                .u8(1).i32(16777217).px(10, 20, 0, 0).i32(0, 0).u8(0, 2).i32(1)
                .u8(0).u8(1, 0, 3, 255, 255).px(-10, -10, 10, 10).u8(0).bytes();
        PhyWorld w = new PhyReader().read(file);
        w.setVersionWord(PhyVersion.CURRENT);
        w.setTrailingBytes(null);
        w.getLayout().clear();
        PhyWorld back = roundTrip(w);
        PhyShape s = (PhyShape) back.getShapes().get(0);
        assertEquals(15, s.getCircleRadius());
        assertEquals(0.375f, s.getElasticity());
        assertEquals(1f, s.getMass());
        PhyBody b = back.getBodies().get(0);
        assertEquals(2, b.getFlags());
        assertEquals(1, b.getCollisionLayers());
        assertEquals(20f, b.getPosition().getY());
        assertEquals(10f, PhyFixed.fx(back.getEvents().get(0).getTargetRaw(2)));
        assertEquals(PhyWorld.NONE, back.getEvents().get(0).getConstraintFilter());
    }
}
