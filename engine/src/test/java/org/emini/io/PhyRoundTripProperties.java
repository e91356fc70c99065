package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/** Random documents of every version and record type survive write → read → write unchanged. */
class PhyRoundTripProperties {
    @Provide
    Arbitrary<PhyWorld> documents() {
        return Arbitraries.randomValue(RandomDocuments::generate);
    }

    @Property(tries = 2000)
    void aWrittenDocumentReadsBackAsTheSameModel(@ForAll("documents") PhyWorld doc) throws Exception {
        byte[] bytes = new PhyWriter().write(doc);
        PhyWorld back = new PhyReader().read(bytes);
        back.getLayout().clear();
        assertEquals(doc, back, () -> "document " + doc + " read back as " + back + " from " + RandomDocuments.hex(bytes));
    }

    @Property(tries = 2000)
    void aReadFileIsWrittenBackByteForByte(@ForAll("documents") PhyWorld doc) throws Exception {
        byte[] bytes = new PhyWriter().write(doc);
        PhyWorld read = new PhyReader().read(bytes);
        assertArrayEquals(bytes, new PhyWriter().write(read));
        assertEquals(read, new PhyReader().read(new PhyWriter().write(read)));
    }

    /** Legacy fields (ids, body mass) have no meaning and are not stored in version 10; all else is kept. */
    @Property(tries = 300)
    void upgradingToVersionTenKeepsEveryStoredValue(@ForAll("documents") PhyWorld doc) throws Exception {
        PhyWorld upgraded = new PhyReader().read(new PhyWriter().write(doc));
        upgraded.getLayout().clear();
        upgraded.setVersionWord(PhyVersion.CURRENT);
        upgraded.setTrailingBytes(null);
        for (PhyShapeBase s : upgraded.getShapes()) {
            if (s instanceof PhyShape) {
                ((PhyShape) s).setLegacyId(0);
            }
        }
        if (upgraded.getLandscape() != null) {
            upgraded.getLandscape().getMaterial().setLegacyId(0);
        }
        for (PhyBody b : upgraded.getBodies()) {
            b.setLegacyMassRaw(0);
        }
        for (PhyEvent e : upgraded.getEvents()) {
            e.setLegacyId(0);
            if (e.getSensor() != null) {
                e.getSensor().setLegacyMassRaw(0);
            }
        }
        PhyWorld back = new PhyReader().read(new PhyWriter().write(upgraded));
        back.getLayout().clear();
        assertEquals(upgraded, back);
    }
}
