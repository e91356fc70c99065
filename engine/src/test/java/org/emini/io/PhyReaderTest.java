package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.util.List;

import org.junit.jupiter.api.Test;

/** Reading: version rules, the original's special cases, and refusals with offsets. */
class PhyReaderTest {
    private static PhyFormatException refused(byte[] data) {
        return assertThrows(PhyFormatException.class, () -> new PhyReader().read(data));
    }

    /** A minimal valid version-10 file: one square, one body. */
    private static Bytes minimal10() {
        return Bytes.version(0x0A00).u8(PhySection.SHAPES, 1).square10(10, "").u8(0)
                .u8(PhySection.BODIES, 1).body10(0, 0, 0, "");
    }

    @Test
    void emptyAndShortInputsAreRefusedAtByteZero() {
        PhyFormatException e = refused(new byte[0]);
        assertEquals(0, e.getOffset());
        assertEquals("version word (4 bytes)", e.getExpected());
        assertEquals("end of data after 0 bytes", e.getFound());
        assertEquals(0, refused(new byte[] {0, 0, 10}).getOffset());
    }

    @Test
    void versionWordsOutsideOneToTenAreRefused() {
        for (int word : new int[] {0, 0x00FF, 0x0B00, 0xFFFF, 0x7FFFFFFF, 0x1000}) {
            PhyFormatException e = refused(Bytes.version(word).u8(0, 0, 0, 0).bytes());
            assertEquals(0, e.getOffset(), e.getMessage());
            assertEquals(PhyVersion.toString(word), e.getFound());
            assertTrue(e.getExpected().contains("0x0100 to 0x0A00"), e.getExpected());
        }
    }

    @Test
    void versionTestsCompareTheRawOrMaskedWordLikeTheOriginal() {
        assertTrue(PhyVersion.shapeHasLegacyId(0x0200));
        assertFalse(PhyVersion.shapeHasLegacyId(0x0201), "raw test: 0x0201 > 0x0200");
        assertTrue(PhyVersion.eventHasLegacyId(0x03FF));
        assertFalse(PhyVersion.eventHasLegacyId(0x0400));
        assertFalse(PhyVersion.eventHasLegacyId(0x00010500), "masked test ignores the high bits");
        assertTrue(PhyVersion.bodyHasLegacyMass(0x04FF));
        assertFalse(PhyVersion.shapeHasMass(0x04FF));
        assertTrue(PhyVersion.shapeHasMass(0x0500));
        assertTrue(PhyVersion.shapeAndBodyHaveUserData(0x0601), "raw test: 0x0601 > 0x0600");
        assertFalse(PhyVersion.othersHaveUserData(0x0700));
        assertTrue(PhyVersion.hasMultiShapes(0x0801));
        assertTrue(PhyVersion.hasSeparateDamping(0x0901));
        // A negative word with a valid index: the raw tests all see a small number.
        int negative = 0xFFFF0A00;
        assertTrue(PhyVersion.isSupported(negative));
        assertEquals(10, PhyVersion.index(negative));
        assertTrue(PhyVersion.shapeHasLegacyId(negative));
        assertFalse(PhyVersion.hasMultiShapes(negative));
        assertFalse(PhyVersion.isTagged(0x01F0));
        assertTrue(PhyVersion.isTagged(0x0200));
    }

    @Test
    void aWordJustAboveABoundaryReadsTheNewerLayout() throws Exception {
        // 0x0201: tagged, no shape legacy id (raw 0x0201 > 0x0200), old event layout (masked 0x0200 < 0x0400).
        byte[] file = Bytes.version(0x0201).u8(PhySection.SHAPES, 1, 1).px(0, 5).i32(0, 1024)
                .u8(PhySection.EVENTS, 1, 0, 7, 255, 255).i32(1, 2, 3, 4).bytes();
        PhyWorld w = new PhyReader().read(file);
        PhyShape s = (PhyShape) w.getShapes().get(0);
        assertEquals(1, s.getVertexCount());
        assertEquals(5, s.getCircleRadius());
        assertEquals(PhyFixed.FX_ONE, s.getMassRaw(), "no mass field before 0x0500: 1.0");
        assertEquals(7, w.getEvents().get(0).getLegacyId());
        assertEquals(PhyWorld.NONE, w.getEvents().get(0).getConstraintFilter());
        assertArrayEquals(file, new PhyWriter().write(w));
    }

    @Test
    void versionOneHasFixedSectionsAndKeepsTrailingBytes() throws Exception {
        byte[] file = Bytes.version(0x0100).u8(1, 9, 1).px(0, -3).i32(0, 1024).u8(0, 0, 0, 0xAB, 0xCD).bytes();
        PhyWorld w = new PhyReader().read(file);
        assertEquals(1, w.getShapes().size());
        assertEquals(9, ((PhyShape) w.getShapes().get(0)).getLegacyId());
        assertArrayEquals(new byte[] {(byte) 0xAB, (byte) 0xCD}, w.getTrailingBytes());
        assertEquals(List.of(new PhySection(1, 1, 0), new PhySection(2, 0, 0), new PhySection(3, 0, 0),
                new PhySection(5, 0, 0)), w.getLayout());
        assertArrayEquals(file, new PhyWriter().write(w));
    }

    @Test
    void aNegativeStringLengthIsRefusedAtTheLength() {
        Bytes b = minimal10().u8(PhySection.WORLD).px(0, 100).i32(0, 0);
        int at = b.size();
        PhyFormatException e = refused(b.i32(-1).bytes());
        assertEquals(at, e.getOffset());
        assertEquals("world user data length >= 0", e.getExpected());
        assertEquals("-1", e.getFound());
    }

    @Test
    void aStringLongerThanTheDataIsRefusedBeforeAllocating() {
        Bytes b = minimal10().u8(PhySection.WORLD).px(0, 100).i32(0, 0).i32(Integer.MAX_VALUE).u8('a', 'b');
        PhyFormatException e = refused(b.bytes());
        assertEquals(b.size() - 2, e.getOffset());
        assertTrue(e.getExpected().startsWith("world user data (2147483647 bytes)"), e.getExpected());
        assertEquals("end of data after 2 bytes", e.getFound());
    }

    @Test
    void anAbsurdOrNegativeSegmentCountIsRefusedAtTheCount() {
        for (int count : new int[] {Integer.MAX_VALUE, 1 << 26, 2, -1, Integer.MIN_VALUE}) {
            Bytes b = minimal10().u8(PhySection.LANDSCAPE);
            int at = b.size();
            // Room for one segment only.
            PhyFormatException e = refused(b.i32(count).px(0, 0, 10, 0).u8(0).bytes());
            assertEquals(at, e.getOffset(), e.getMessage());
            assertTrue(e.getExpected().startsWith("landscape segment count"), e.getExpected());
            assertEquals(Integer.toString(count), e.getFound());
        }
    }

    @Test
    void anUnknownConstraintTypeIsRefused() {
        Bytes b = minimal10().u8(PhySection.CONSTRAINTS, 1);
        int at = b.size();
        PhyFormatException e = refused(b.u8(PhyConstraint.TYPE_SCRIPT).bytes());
        assertEquals(at, e.getOffset());
        assertEquals("constraint 0 type 0 (joint), 1 (spring) or 3 (motor)", e.getExpected());
        assertEquals("2", e.getFound());
    }

    @Test
    void aReferenceToNoEarlierRecordIsRefused() {
        Bytes body = Bytes.version(0x0A00).u8(PhySection.SHAPES, 1).square10(10, "").u8(0).u8(PhySection.BODIES, 1)
                .px(0, 0, 0, 0).i32(0, 0);
        int at = body.size();
        PhyFormatException e = refused(body.u8(1, 3).i32(0).str("").bytes());
        assertEquals(at, e.getOffset());
        assertEquals("body 0 shape index below 1", e.getExpected());

        Bytes part = Bytes.version(0x0A00).u8(PhySection.SHAPES, 1).square10(10, "").u8(1, 2, 0);
        at = part.size();
        e = refused(part.u8(1).str("").bytes());
        assertEquals(at, e.getOffset());
        assertEquals("shape (multishape) 1 part 1 shape index below 1", e.getExpected());

        Bytes event = minimal10().u8(PhySection.EVENTS, 1, 0, 0, 255, 255);
        at = event.size();
        e = refused(event.u8(0).i32(0, 0, 0, 0).str("").bytes());
        assertEquals(at, e.getOffset());
        assertEquals("event 0 constraint filter below 0 or 255 (none)", e.getExpected());

        Bytes joint = minimal10().u8(PhySection.CONSTRAINTS, 1, PhyConstraint.TYPE_JOINT, 0).px(0, 0);
        at = joint.size();
        e = refused(joint.u8(1).px(0, 0).u8(0).str("").bytes());
        assertEquals(at, e.getOffset());
        assertEquals("constraint 0 body 2 index below 1", e.getExpected());

        Bytes row = minimal10().u8(PhySection.SCRIPTS, 0, 1);
        at = row.size();
        e = refused(row.u8(0, 0).bytes());
        assertEquals(at, e.getOffset());
        assertEquals("script-body row 0 script index below 0", e.getExpected());
    }

    @Test
    void sectionTagsAboveEightAreRefusedUnlessSkipping() throws Exception {
        Bytes b = minimal10();
        int at = b.size();
        byte[] file = b.u8(9, 200).bytes();
        PhyFormatException e = refused(file);
        assertEquals(at, e.getOffset());
        assertEquals("a section tag from 1 to 8", e.getExpected());
        assertEquals("9", e.getFound());
        PhyWorld w = new PhyReader().setSkipUnknownSections(true).read(file);
        assertEquals(new PhySection(9, 0, 0), w.getLayout().get(2));
        assertEquals(new PhySection(200, 0, 0), w.getLayout().get(3));
        assertArrayEquals(file, new PhyWriter().write(w), "skipped tags are written back");
    }

    @Test
    void tagZeroIsSkippedLikeTheOriginalDoes() throws Exception {
        byte[] file = minimal10().u8(0).bytes();
        PhyWorld w = new PhyReader().read(file);
        assertEquals(new PhySection(0, 0, 0), w.getLayout().get(w.getLayout().size() - 1));
        assertArrayEquals(file, new PhyWriter().write(w));
    }

    @Test
    void aLaterLandscapeOrWorldRecordReplacesAnEarlierOne() throws Exception {
        byte[] file = minimal10().u8(PhySection.LANDSCAPE).i32(1).px(0, 0, 10, 0).u8(1).u8(0).i32(0, 1024, 4096)
                .str("").u8(PhySection.LANDSCAPE).i32(0).u8(0).i32(0, 4096, 4096).str("")
                .u8(PhySection.WORLD).px(0, 50).i32(0, 0).str("first")
                .u8(PhySection.WORLD).px(0, 75).i32(0, 0).str("second").bytes();
        PhyWorld w = new PhyReader().read(file);
        assertEquals(0, w.getLandscape().getSegments().size());
        assertEquals(1f, w.getLandscape().getMaterial().getFriction());
        assertEquals(75f, w.getSettings().getGravity().getY());
        assertEquals("second", w.getSettings().getUserData());
        assertEquals(w, new PhyReader().read(new PhyWriter().write(w)), "the model survives");
    }

    @Test
    void aStreamAboveTheLimitIsRefusedWithoutReadingOn() {
        InputStream endless = new InputStream() {
            @Override
            public int read() {
                return 0;
            }

            @Override
            public int read(byte[] b, int off, int len) {
                return len;
            }
        };
        PhyFormatException e = assertThrows(PhyFormatException.class,
                () -> new PhyReader().setMaxSize(1 << 16).read(endless));
        assertEquals(1 << 16, e.getOffset());
        assertEquals("more data", e.getFound());
    }

    @Test
    void aStreamReadsLikeItsBytes() throws Exception {
        byte[] file = minimal10().u8(PhySection.WORLD).px(3, 4).i32(41, 42).str("w").bytes();
        InputStream trickle = new ByteArrayInputStream(file) {
            @Override
            public synchronized int read(byte[] b, int off, int len) {
                return super.read(b, off, Math.min(len, 3));
            }
        };
        assertEquals(new PhyReader().read(file), new PhyReader().read(trickle));
    }

    @Test
    void malformedUtf8UserDataIsDecodedAsTheOriginalDoesAndKeptAsBytes() throws Exception {
        byte[] file = Bytes.version(0x0A00).u8(PhySection.SHAPES, 0, 0, PhySection.WORLD).px(0, 100).i32(0, 0)
                .i32(3).u8('a', 0xC3, 'b').bytes();
        PhyWorld w = new PhyReader().read(file);
        assertEquals("a\uFFFDb", w.getSettings().getUserData());
        assertArrayEquals(new byte[] {'a', (byte) 0xC3, 'b'}, w.getSettings().getUserDataBytes());
        assertArrayEquals(file, new PhyWriter().write(w));
    }

    @Test
    void oldDampingIsOneMinusTheRetentionForBoth() throws Exception {
        byte[] file = Bytes.version(0x0900).u8(PhySection.WORLD).px(0, 100).i32(4096 - 410).str("").bytes();
        PhyWorldSettings s = new PhyReader().read(file).getSettings();
        assertEquals(410, s.getDampingLinearRaw());
        assertEquals(410, s.getDampingRotationalRaw());
        assertEquals(0.1f, s.getDampingLinear(), 0.0001f);
        byte[] odd = Bytes.version(0x0900).u8(PhySection.WORLD).px(0, 0).i32(Integer.MIN_VALUE).str("").bytes();
        PhyWorld w = new PhyReader().read(odd);
        assertEquals(4096 - Integer.MIN_VALUE, w.getSettings().getDampingLinearRaw(), "32-bit arithmetic");
        assertArrayEquals(odd, new PhyWriter().write(w));
    }

    @Test
    void fixedPointConvertsAsTheOriginalReadsIt() {
        assertEquals(1f, PhyFixed.fx(4096));
        assertEquals(-0.5f, PhyFixed.fx(-2048));
        assertEquals(0.989990234375f, PhyFixed.fx(99 * 4096 / 100), "99 % through the percent setter (4055 / 4096, exact)");
        assertEquals(1f, PhyFixed.fx2(1 << 24));
        assertEquals((float) (52707178 / 16777216.0), PhyFixed.fx2(PhyFixed.PI_2FX), "the original's π, 1.5e-7 short");
        assertEquals(1024, PhyFixed.toFx(0.25f));
        assertEquals(3 << 23, PhyFixed.toFx2(1.5f));
        assertEquals(-1, PhyFixed.toFx(-0.0002f), "rounds to the nearest raw value");
        assertThrows(IllegalArgumentException.class, () -> PhyFixed.toFx(1e6f));
        assertThrows(IllegalArgumentException.class, () -> PhyFixed.toFx(Float.NaN));
    }

    @Test
    void anglesWrapWithTheOriginalsTwoPi() {
        int twoPi = PhyFixed.TWO_PI_2FX;
        assertEquals(twoPi - 1, PhyFixed.wrapAngle2fx(-1));
        assertEquals(1, PhyFixed.wrapAngle2fx(twoPi + 1));
        assertEquals(twoPi, PhyFixed.wrapAngle2fx(twoPi), "[0, 2π] is closed");
        assertEquals(0, PhyFixed.wrapAngle2fx(0));
        int w = PhyFixed.wrapAngle2fx(Integer.MIN_VALUE);
        assertTrue(w >= 0 && w <= twoPi);
        assertEquals(Math.floorMod((long) Integer.MIN_VALUE, twoPi), w);
    }

    @Test
    void circleRadiusIsTheOriginalsTruncatedLength() {
        assertEquals(15, PhyFixed.circleRadius(0, 15 * 4096));
        assertEquals(15, PhyFixed.circleRadius(0, -15 * 4096));
        // One Newton step from a rough guess lands a little above the root: 14.9998 px reads as 15.
        assertEquals(15, PhyFixed.circleRadius(0, 15 * 4096 - 1));
        assertEquals(14, PhyFixed.circleRadius(0, 15 * 4096 - 200), "truncated, not rounded");
        assertEquals(5, PhyFixed.circleRadius(3 * 4096, 4 * 4096));
        assertEquals(0, PhyFixed.circleRadius(4095, 0), "within a pixel of the origin");
        assertEquals(0, PhyFixed.circleRadius(0, 0));
        java.util.Random r = new java.util.Random(5);
        for (int i = 0; i < 10000; i++) {
            int x = r.nextInt(1 << 22) - (1 << 21);
            int y = r.nextInt(1 << 22) - (1 << 21);
            double exact = Math.hypot(x, y) / 4096;
            int radius = PhyFixed.circleRadius(x, y);
            assertTrue(exact < 1 ? radius == 0 : Math.abs(radius - Math.floor(exact)) <= 1, x + ", " + y);
        }
    }

    @Test
    void segmentsNormalizeLikeTheOriginalsInsertion() {
        PhyVector a = PhyVector.of(0, 0);
        PhyVector b = PhyVector.of(10, 5);
        PhySegment forward = new PhySegment(a, b, PhySegment.FACE_LEFT);
        assertEquals(forward, forward.normalized());
        assertEquals(new PhySegment(a, b, PhySegment.FACE_RIGHT), new PhySegment(b, a, PhySegment.FACE_LEFT).normalized());
        assertEquals(new PhySegment(a, b, PhySegment.FACE_LEFT), new PhySegment(b, a, PhySegment.FACE_RIGHT).normalized());
        assertEquals(new PhySegment(a, b, 0), new PhySegment(b, a, 0).normalized());
        assertEquals(new PhySegment(a, b, PhySegment.FACE_RIGHT), new PhySegment(b, a, 7).normalized(),
                "another face becomes right");
        PhyVector top = PhyVector.of(0, -10);
        assertEquals(new PhySegment(a, top, PhySegment.FACE_RIGHT), new PhySegment(top, a, 1).normalized(),
                "vertical segments are swapped too");
    }

    @Test
    void aSensorEventCarriesItsBodyRecord() throws Exception {
        byte[] file = minimal10().u8(PhySection.EVENTS, 1, PhyEvent.TYPE_BODY_SENSOR, 1, 255, 0, 255)
                .i32(0, 0, 0, 0).body10(5, 6, 0, "sensor").str("event").bytes();
        PhyEvent e = new PhyReader().read(file).getEvents().get(0);
        assertEquals(5f, e.getSensor().getPosition().getX());
        assertEquals("sensor", e.getSensor().getUserData());
        assertEquals("event", e.getUserData());
        assertTrue(e.isTriggerOnce());
        assertEquals(0, e.getShapeFilter());
        PhyEvent plain = new PhyReader().read(minimal10().u8(PhySection.EVENTS, 1, 0, 0, 255, 255, 255)
                .i32(0, 0, 0, 0).str("").bytes()).getEvents().get(0);
        assertNull(plain.getSensor());
    }
}
