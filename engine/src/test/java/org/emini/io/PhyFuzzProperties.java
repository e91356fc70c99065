package org.emini.io;

import java.util.Arrays;
import java.util.Random;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.Size;

/**
 * Random and damaged inputs are read or refused with a located error; the reader never throws
 * anything else, never hangs and never allocates beyond the input.
 */
class PhyFuzzProperties {
    private final PhyReader strict = new PhyReader();
    private final PhyReader lenient = new PhyReader().setSkipUnknownSections(true);

    @Provide
    Arbitrary<Integer> versionWords() {
        return Arbitraries.oneOf(Arbitraries.of(Arrays.stream(RandomDocuments.VERSION_WORDS).boxed().toList()),
                Arbitraries.integers());
    }

    @Property(tries = 2000)
    void randomBytesAreReadOrRefused(@ForAll @Size(max = 3000) byte[] data) {
        Corruption.readOrRefuse(strict, data);
        Corruption.readOrRefuse(lenient, data);
    }

    @Property(tries = 3000)
    void randomSectionsAfterAVersionWordAreReadOrRefused(@ForAll("versionWords") int version,
            @ForAll @Size(max = 600) byte[] sections) {
        byte[] data = new byte[4 + sections.length];
        data[0] = (byte) (version >>> 24);
        data[1] = (byte) (version >>> 16);
        data[2] = (byte) (version >>> 8);
        data[3] = (byte) version;
        System.arraycopy(sections, 0, data, 4, sections.length);
        Corruption.readOrRefuse(strict, data);
        Corruption.readOrRefuse(lenient, data);
    }

    @Provide
    Arbitrary<byte[]> damagedDocuments() {
        return Arbitraries.randomValue(r -> damage(r, new PhyWriter().write(RandomDocuments.generate(r))));
    }

    /** Overwrites, inserts or deletes a few bytes, or cuts the file. */
    private static byte[] damage(Random r, byte[] b) {
        byte[] d = b;
        int edits = 1 + r.nextInt(4);
        for (int k = 0; k < edits && d.length > 0; k++) {
            int at = r.nextInt(d.length);
            switch (r.nextInt(5)) {
                case 0:
                    d[at] = (byte) r.nextInt(256);
                    break;
                case 1:
                    d[at] ^= (byte) (1 << r.nextInt(8));
                    break;
                case 2:
                    byte[] ins = new byte[d.length + 1];
                    System.arraycopy(d, 0, ins, 0, at);
                    ins[at] = (byte) (r.nextBoolean() ? 0xFF : r.nextInt(256));
                    System.arraycopy(d, at, ins, at + 1, d.length - at);
                    d = ins;
                    break;
                case 3:
                    byte[] del = new byte[d.length - 1];
                    System.arraycopy(d, 0, del, 0, at);
                    System.arraycopy(d, at + 1, del, at, d.length - at - 1);
                    d = del;
                    break;
                default:
                    d = Arrays.copyOf(d, at);
                    break;
            }
        }
        return d;
    }

    @Property(tries = 3000)
    void damagedDocumentsAreReadOrRefused(@ForAll("damagedDocuments") byte[] data) {
        Corruption.readOrRefuse(strict, data);
        Corruption.readOrRefuse(lenient, data);
    }
}
