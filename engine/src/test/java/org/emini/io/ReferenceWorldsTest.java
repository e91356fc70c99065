package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The original's real files: they load, decode to the counts the format document gives (section 8
 * of phy-world-format.md, copied here, not taken from this reader), round-trip, and build into a
 * world that runs 600 ticks stably.
 */
class ReferenceWorldsTest {
    /**
     * The format document's decode: file, bytes, version word, standard shapes, multishapes,
     * bodies, constraints, landscape segments (-1: no landscape section), events, emitters,
     * trailing bytes.
     */
    static Stream<Arguments> documentedDecodes() {
        return Stream.of(
                Arguments.of("rhabarber-small.phy", 789, 0x0A00, 3, 0, 5, 0, 17, 0, 0, 0),
                Arguments.of("rhabarber-testWorld.phy", 1108, 0x0A00, 3, 0, 13, 1, 10, 0, 0, 0),
                Arguments.of("test_basic.world", 105, 0x01F0, 1, 0, 1, 0, -1, 1, 0, 1),
                Arguments.of("BoxTunnelTest.world", 981, 0x01F0, 6, 0, 22, 0, -1, 1, 0, 1),
                Arguments.of("CirclePolyCollisionTest.world", 141, 0x01F0, 2, 0, 2, 0, -1, 1, 0, 1),
                Arguments.of("ElasticityTest.world", 139, 0x01F0, 1, 0, 2, 0, -1, 1, 0, 1),
                Arguments.of("FixJointTest.world", 295, 0x01F0, 2, 0, 3, 1, -1, 4, 0, 1),
                Arguments.of("StackTest5.world", 321, 0x01F0, 2, 0, 6, 0, -1, 2, 0, 1),
                Arguments.of("LandscapeFacesTest.world", 503, 0x0500, 1, 0, 6, 0, 6, 7, 0, 0),
                Arguments.of("PerformanceTest.world", 1680, 0x0500, 4, 0, 40, 6, 6, 1, 0, 0));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("documentedDecodes")
    void decodeMatchesTheFormatDocument(String file, int size, int version, int shapes, int multiShapes, int bodies,
            int constraints, int segments, int events, int emitters, int trailing) throws Exception {
        byte[] bytes = ReferenceWorlds.bytes(file);
        assertEquals(size, bytes.length, file + " size");
        PhyWorld w = new PhyReader().read(bytes);
        assertEquals(version, w.getVersionWord(), file + " version word");
        assertEquals(shapes, w.getStandardShapeCount(), file + " shapes");
        assertEquals(multiShapes, w.getMultiShapeCount(), file + " multishapes");
        assertEquals(bodies, w.getBodies().size(), file + " bodies");
        assertEquals(constraints, w.getConstraints().size(), file + " constraints");
        assertEquals(segments, w.getLandscape() == null ? -1 : w.getLandscape().getSegments().size(),
                file + " segments");
        assertEquals(events, w.getEvents().size(), file + " events");
        assertEquals(emitters, w.getParticleEmitters().size(), file + " emitters");
        assertEquals(trailing, w.getTrailingBytes().length, file + " trailing bytes");
        assertTrue(w.getScripts().isEmpty() && w.getScriptBindings().isEmpty(), file + " has no scripts");
        for (PhyEvent e : w.getEvents()) {
            assertEquals(PhyEvent.TYPE_BODY_POSITION, e.getType(), file + ": all events are position events");
            assertEquals(PhyWorld.NONE, e.getBodyFilter(), file + ": no body filter");
            assertEquals(PhyWorld.NONE, e.getShapeFilter(), file + ": no shape filter");
        }
    }

    @Test
    void rhabarberSmallDetailsMatchTheFormatDocument() throws Exception {
        PhyWorld w = ReferenceWorlds.read("rhabarber-small.phy");
        assertEquals(List.of(4, 3, 5), vertexCounts(w));
        int withUserData = 0;
        for (PhyBody b : w.getBodies()) {
            assertEquals(3, b.getFlags(), "all dynamic, rotating");
            assertEquals(0, b.getCollisionLayers());
            withUserData += b.getUserData().isEmpty() ? 0 : 1;
        }
        assertEquals(5, withUserData);
        assertEquals("element=treasurespawn\nvalue=100", w.getBodies().get(1).getUserData());
        assertArrayEquals(new int[] {3, 9, 5}, faceCounts(w.getLandscape()));
        assertEquals(0f, w.getLandscape().getMaterial().getElasticity());
        assertEquals(1f, w.getLandscape().getMaterial().getFriction());
        PhyWorldSettings s = w.getSettings();
        assertEquals(0f, s.getGravity().getX());
        assertEquals(100f, s.getGravity().getY());
        assertEquals(0, s.getDampingLinearRaw());
        assertEquals(0, s.getDampingRotationalRaw());
        assertEquals("", s.getUserData());
    }

    @Test
    void rhabarberTestWorldDetailsMatchTheFormatDocument() throws Exception {
        PhyWorld w = ReferenceWorlds.read("rhabarber-testWorld.phy");
        int dynamic = 0;
        int anchors = 0;
        int withUserData = 0;
        for (PhyBody b : w.getBodies()) {
            dynamic += b.getFlags() == 3 ? 1 : 0;
            anchors += b.getFlags() == 12 ? 1 : 0;
            withUserData += b.getUserData().isEmpty() ? 0 : 1;
        }
        assertEquals(12, dynamic);
        assertEquals(1, anchors);
        assertEquals(10, withUserData);
        assertArrayEquals(new int[] {10, 0, 0}, faceCounts(w.getLandscape()));
        assertEquals(1f, w.getLandscape().getMaterial().getFriction());
        PhySpring spring = (PhySpring) w.getConstraints().get(0);
        assertTrue(spring.isRigid());
        assertEquals(0, spring.getCoefficientRaw());
        assertEquals(192.39f, spring.getRestLength(), 0.005f);
    }

    @Test
    void versionOneTestFilesMatchTheFormatDocument() throws Exception {
        PhyWorld box = ReferenceWorlds.read("BoxTunnelTest.world");
        assertEquals(List.of(6, 2, 2, 5, 1, 2), vertexCounts(box), "a 6-gon, three lines, a 5-gon, a circle");
        assertEquals(15, ((PhyShape) box.getShapes().get(4)).getCircleRadius());
        assertEquals(19, box.getBodies().stream().filter(PhyBody::isDynamic).count());
        assertEquals(3, box.getBodies().stream().filter(b -> !b.isDynamic()).count());
        PhyWorld circle = ReferenceWorlds.read("CirclePolyCollisionTest.world");
        assertEquals(List.of(2, 1), vertexCounts(circle));
        assertEquals(15, ((PhyShape) circle.getShapes().get(1)).getCircleRadius());
        PhyWorld elastic = ReferenceWorlds.read("ElasticityTest.world");
        assertEquals(4, ((PhyShape) elastic.getShapes().get(0)).getVertexCount());
        assertEquals(0.99f, ((PhyShape) elastic.getShapes().get(0)).getElasticity(), 0.0005f);
        assertEquals(1, elastic.getBodies().stream().filter(b -> !b.isDynamic()).count());
        PhyWorld joint = ReferenceWorlds.read("FixJointTest.world");
        assertTrue(((PhyJoint) joint.getConstraints().get(0)).isFixed());
        assertEquals(1, joint.getBodies().stream().filter(b -> !b.isDynamic()).count());
        PhyJoint j = (PhyJoint) joint.getConstraints().get(0);
        assertEquals(1, joint.getBodies().get(j.getBody1()).getCollisionLayers() & 1, "layer bit 0");
        assertEquals(1, joint.getBodies().get(j.getBody2()).getCollisionLayers() & 1, "layer bit 0");
        PhyWorld stack = ReferenceWorlds.read("StackTest5.world");
        assertEquals(List.of(2, 4), vertexCounts(stack), "a line floor and a square");
        assertEquals(1, stack.getBodies().stream().filter(b -> !b.isDynamic()).count());
        for (Path p : ReferenceWorlds.all()) {
            // Six version-1 files, each with one extra byte the original never reads.
            PhyWorld w = new PhyReader().read(java.nio.file.Files.readAllBytes(p));
            if (w.getVersion() == 1) {
                assertArrayEquals(new byte[] {0}, w.getTrailingBytes(), p + ": one trailing 0x00");
            }
        }
    }

    @Test
    void versionFiveTestFilesMatchTheFormatDocument() throws Exception {
        PhyWorld faces = ReferenceWorlds.read("LandscapeFacesTest.world");
        assertArrayEquals(new int[] {0, 3, 3}, faceCounts(faces.getLandscape()));
        long vertical = faces.getLandscape().getSegments().stream()
                .filter(s -> s.getStart().getXRaw() == s.getEnd().getXRaw()).count();
        assertEquals(2, vertical);
        assertTrue(faces.getEvents().stream().allMatch(PhyEvent::isTriggerOnce));
        PhyWorld perf = ReferenceWorlds.read("PerformanceTest.world");
        assertArrayEquals(new int[] {0, 6, 0}, faceCounts(perf.getLandscape()));
        for (PhyConstraint c : perf.getConstraints()) {
            assertTrue(c instanceof PhySpring && ((PhySpring) c).isRigid(), "rigid springs");
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("files")
    void saveReproducesTheFileByteForByteAndTheModel(Path file) throws Exception {
        ReferenceWorlds.require();
        byte[] bytes = java.nio.file.Files.readAllBytes(file);
        PhyWorld first = new PhyReader().read(bytes);
        byte[] saved = new PhyWriter().write(first);
        assertArrayEquals(bytes, saved, file + ": save after load gives the same bytes");
        assertEquals(first, new PhyReader().read(saved), file + ": load after save gives the same model");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("files")
    void worldRuns600TicksStably(Path file) throws Exception {
        ReferenceWorlds.require();
        BuildResult r = new WorldBuilder().build(new PhyReader().read(java.nio.file.Files.readAllBytes(file)));
        World world = r.getWorld();
        PhyWorld doc = r.getDocument();
        assertEquals(doc.getBodies().size() - r.getUnsupportedCount(UnsupportedElement.Kind.BODY),
                world.getBodyCount(), "every body is built or listed");
        float g = (float) Math.hypot(world.getGravityX(), world.getGravityY());
        float v0 = 0f;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            v0 = Math.max(v0, (float) Math.hypot(b.getVelocityX(), b.getVelocityY()));
        }
        for (int tick = 1; tick <= 600; tick++) {
            world.tick();
            // Nothing here pushes bodies: no body is faster than falling freely since the start.
            float bound = v0 + 1.05f * g * world.getTimestep() * tick + 50f;
            for (int i = 0; i < world.getBodyCount(); i++) {
                Body b = world.getBody(i);
                assertTrue(Float.isFinite(b.getX()) && Float.isFinite(b.getY()) && Float.isFinite(b.getAngle()),
                        file + ": body " + i + " finite at tick " + tick);
                float speed = (float) Math.hypot(b.getVelocityX(), b.getVelocityY());
                assertTrue(speed <= bound, file + ": body " + i + " speed " + speed + " above " + bound
                        + " at tick " + tick);
                assertTrue(Math.abs(b.getAngularVelocity()) < 100f, file + ": body " + i + " spins at "
                        + b.getAngularVelocity() + " rad/s at tick " + tick);
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("files")
    void everyRecordIsBuiltOrListed(Path file) throws Exception {
        ReferenceWorlds.require();
        PhyWorld doc = new PhyReader().read(java.nio.file.Files.readAllBytes(file));
        BuildResult r = new WorldBuilder().build(doc);
        int built = 0;
        for (int i = 0; i < doc.getBodies().size(); i++) {
            built += r.getBody(i) != null ? 1 : 0;
        }
        assertEquals(doc.getBodies().size(), built + r.getUnsupportedCount(UnsupportedElement.Kind.BODY));
        int segments = doc.getLandscape() == null ? 0 : doc.getLandscape().getSegments().size();
        assertEquals(segments, r.getWorld().getLandscape().getSegmentCount()
                + r.getUnsupportedCount(UnsupportedElement.Kind.LANDSCAPE_SEGMENT));
        int constraints = 0;
        for (int i = 0; i < doc.getConstraints().size(); i++) {
            constraints += r.getConstraint(i) != null ? 1 : 0;
        }
        assertEquals(doc.getConstraints().size(), constraints + r.getUnsupportedCount(UnsupportedElement.Kind.JOINT)
                + r.getUnsupportedCount(UnsupportedElement.Kind.SPRING)
                + r.getUnsupportedCount(UnsupportedElement.Kind.MOTOR));
        assertEquals(constraints, r.getWorld().getConstraintCount());
        int events = 0;
        for (int i = 0; i < doc.getEvents().size(); i++) {
            events += r.getEvent(i) != null ? 1 : 0;
        }
        assertEquals(doc.getEvents().size(), events + r.getUnsupportedCount(UnsupportedElement.Kind.EVENT));
        assertEquals(events, r.getWorld().getEventCount());
        int emitters = 0;
        for (int i = 0; i < doc.getParticleEmitters().size(); i++) {
            emitters += r.getParticleEmitter(i) != null ? 1 : 0;
        }
        assertEquals(doc.getParticleEmitters().size(),
                emitters + r.getUnsupportedCount(UnsupportedElement.Kind.PARTICLE_EMITTER));
        assertFalse(r.getUnsupported().stream().anyMatch(e -> e.getReason().isEmpty()));
    }

    /** The files; one null when the folder is absent, so the tests run once and skip with a message. */
    static Stream<Path> files() {
        List<Path> all = ReferenceWorlds.all();
        return all.isEmpty() ? Stream.of((Path) null) : all.stream();
    }

    @Test
    void theFolderHoldsTheTenDocumentedFiles() {
        ReferenceWorlds.require();
        assertEquals(10, ReferenceWorlds.all().size());
    }

    private static List<Integer> vertexCounts(PhyWorld w) {
        return w.getShapes().stream().map(s -> ((PhyShape) s).getVertexCount()).toList();
    }

    private static int[] faceCounts(PhyLandscape l) {
        int[] n = new int[3];
        for (PhySegment s : l.getSegments()) {
            n[s.getFace()]++;
        }
        return n;
    }
}
