package org.emini.io;

import java.io.IOException;
import java.io.InputStream;
import java.util.List;

/**
 * Reads an original world file (<code>.phy</code>, <code>.world</code>; versions 1 to 10) into a
 * {@link PhyWorld} with every record's raw values, following the original loader field by field
 * (see the format notes in this package's <code>phy-mapping.md</code>).
 *
 * <p>Unlike the original, which reads garbage past the end of data and runs away on bad counts,
 * this reader refuses a damaged file with a {@link PhyFormatException} naming the byte offset and
 * what it expected there: a short file, an unsupported version word, a negative or oversized
 * count or string length, an index naming no earlier record, an unknown constraint type, and by
 * default a section tag above 8 (tag 0, which ends some designer files, is skipped as the
 * original skips it). It never allocates more than a small multiple of the input.
 * Reading is deterministic and keeps no state between calls.
 */
public final class PhyReader {
    /** The largest input {@link #read(InputStream)} accepts by default: 16 MiB. */
    public static final int DEFAULT_MAX_SIZE = 16 << 20;

    private int maxSize = DEFAULT_MAX_SIZE;
    private boolean skipUnknownSections;

    /** Creates a reader that refuses section tags above 8 and inputs above 16 MiB. */
    public PhyReader() {
    }

    /**
     * Sets the largest input {@link #read(InputStream)} accepts (designer files are a few KiB).
     *
     * @param bytes the limit, &gt; 0
     * @return this reader
     */
    public PhyReader setMaxSize(int bytes) {
        if (bytes <= 0) {
            throw new IllegalArgumentException("PhyReader.setMaxSize: bytes must be > 0, was " + bytes);
        }
        maxSize = bytes;
        return this;
    }

    /**
     * Lets the reader skip section tags above 8 as the original does (it consumes the tag byte
     * and reads the next byte as a tag); they are kept in {@link PhyWorld#getLayout()} so the file
     * round-trips. By default such a tag is refused: no designer writes one, so it means a damaged
     * file. Tag 0 is always skipped (and kept): the old designer ended its version-5 files with a
     * 0x00 byte, which the original reads as an unknown tag.
     *
     * @param skip true to skip unknown tags
     * @return this reader
     */
    public PhyReader setSkipUnknownSections(boolean skip) {
        skipUnknownSections = skip;
        return this;
    }

    /**
     * Reads a world file from a stream, to its end. The stream is not closed.
     *
     * @param in the stream
     * @return the document
     * @throws PhyFormatException if the data is not a world file the original accepts, or is
     *     larger than the limit ({@link #setMaxSize(int)})
     * @throws IOException if the stream fails
     */
    public PhyWorld read(InputStream in) throws IOException {
        byte[] buf = new byte[(int) Math.min(4096L, (long) maxSize + 1)];
        int n = 0;
        while (true) {
            if (n == buf.length) {
                if (n > maxSize) {
                    break;
                }
                byte[] grown = new byte[(int) Math.min((long) buf.length * 2, (long) maxSize + 1)];
                System.arraycopy(buf, 0, grown, 0, n);
                buf = grown;
            }
            int r = in.read(buf, n, buf.length - n);
            if (r < 0) {
                break;
            }
            n += r;
        }
        if (n > maxSize) {
            throw new PhyFormatException(maxSize, "end of data within the reader's limit of " + maxSize + " bytes",
                    "more data");
        }
        return parse(buf, n);
    }

    /**
     * Reads a world file from bytes.
     *
     * @param data the whole file
     * @return the document
     * @throws PhyFormatException if the data is not a world file the original accepts
     */
    public PhyWorld read(byte[] data) throws PhyFormatException {
        if (data == null) {
            throw new IllegalArgumentException("PhyReader.read: data must not be null");
        }
        return parse(data, data.length);
    }

    private PhyWorld parse(byte[] data, int length) throws PhyFormatException {
        PhyInput header = new PhyInput(data, length, 0, 0);
        int version = header.i32("version word");
        if (!PhyVersion.isSupported(version)) {
            throw new PhyFormatException(0, "a version word with (word & 0xFF00) from 0x0100 to 0x0A00",
                    PhyVersion.toString(version));
        }
        PhyInput in = new PhyInput(data, length, version, 4);
        PhyWorld w = new PhyWorld(version);
        if (!PhyVersion.isTagged(version)) {
            // Version 1: fixed order, no tags; the original reads nothing after the events.
            readShapes(in, w);
            readBodies(in, w);
            readConstraints(in, w);
            readEvents(in, w);
            w.setTrailingBytes(in.rest());
            return w;
        }
        while (in.remaining() > 0) {
            int at = in.position();
            in.record("", -1);
            int tag = in.u8("section tag");
            switch (tag) {
                case PhySection.SHAPES:
                    readShapes(in, w);
                    break;
                case PhySection.BODIES:
                    readBodies(in, w);
                    break;
                case PhySection.CONSTRAINTS:
                    readConstraints(in, w);
                    break;
                case PhySection.SCRIPTS:
                    readScripts(in, w);
                    break;
                case PhySection.EVENTS:
                    readEvents(in, w);
                    break;
                case PhySection.LANDSCAPE:
                    // A later landscape replaces an earlier one, as in the original.
                    w.setLandscape(PhyLandscape.read(in));
                    w.getLayout().add(new PhySection(tag, 0, 0));
                    break;
                case PhySection.WORLD:
                    in.record("world", -1);
                    w.setSettings(PhyWorldSettings.read(in));
                    w.getLayout().add(new PhySection(tag, 0, 0));
                    break;
                case PhySection.PARTICLES:
                    readEmitters(in, w);
                    break;
                default:
                    // Tag 0 ends the version-5 test files (the old designer's end byte, like the
                    // trailing byte of its version-1 files); the original skips it like any unknown tag.
                    if (tag != 0 && !skipUnknownSections) {
                        throw new PhyFormatException(at, "a section tag from 1 to 8", Integer.toString(tag));
                    }
                    w.getLayout().add(new PhySection(tag, 0, 0));
                    break;
            }
        }
        return w;
    }

    /** Reads one record of a list. */
    private interface RecordReader<T> {
        T read(PhyInput in) throws PhyFormatException;
    }

    /** Reads a u8 count and that many records, naming each by its index in the whole list. */
    private static <T> int readList(PhyInput in, String count, String kind, List<T> list, RecordReader<T> reader)
            throws PhyFormatException {
        in.record("", -1);
        int n = in.u8(count);
        for (int i = 0; i < n; i++) {
            in.record(kind, list.size());
            list.add(reader.read(in));
        }
        return n;
    }

    private static void readShapes(final PhyInput in, final PhyWorld w) throws PhyFormatException {
        final List<PhyShapeBase> shapes = w.getShapes();
        int n = readList(in, "shape count", "shape", shapes, new RecordReader<PhyShapeBase>() {
            @Override
            public PhyShapeBase read(PhyInput i) throws PhyFormatException {
                return PhyShape.read(i);
            }
        });
        int m = 0;
        if (PhyVersion.hasMultiShapes(in.version())) {
            m = readList(in, "multishape count", "shape (multishape)", shapes, new RecordReader<PhyShapeBase>() {
                @Override
                public PhyShapeBase read(PhyInput i) throws PhyFormatException {
                    return PhyMultiShape.read(i, shapes.size());
                }
            });
        }
        w.getLayout().add(new PhySection(PhySection.SHAPES, n, m));
    }

    private static void readBodies(PhyInput in, final PhyWorld w) throws PhyFormatException {
        int n = readList(in, "body count", "body", w.getBodies(), new RecordReader<PhyBody>() {
            @Override
            public PhyBody read(PhyInput i) throws PhyFormatException {
                return PhyBody.read(i, w.getShapes().size());
            }
        });
        w.getLayout().add(new PhySection(PhySection.BODIES, n, 0));
    }

    private static void readConstraints(PhyInput in, final PhyWorld w) throws PhyFormatException {
        int n = readList(in, "constraint count", "constraint", w.getConstraints(), new RecordReader<PhyConstraint>() {
            @Override
            public PhyConstraint read(PhyInput i) throws PhyFormatException {
                return PhyConstraint.read(i, w.getBodies().size());
            }
        });
        w.getLayout().add(new PhySection(PhySection.CONSTRAINTS, n, 0));
    }

    private static void readScripts(PhyInput in, final PhyWorld w) throws PhyFormatException {
        int n = readList(in, "script count", "script", w.getScripts(), new RecordReader<PhyScript>() {
            @Override
            public PhyScript read(PhyInput i) throws PhyFormatException {
                return PhyScript.read(i);
            }
        });
        int r = readList(in, "script-body row count", "script-body row", w.getScriptBindings(),
                new RecordReader<PhyScriptBinding>() {
                    @Override
                    public PhyScriptBinding read(PhyInput i) throws PhyFormatException {
                        return PhyScriptBinding.read(i, w.getScripts().size(), w.getBodies().size());
                    }
                });
        w.getLayout().add(new PhySection(PhySection.SCRIPTS, n, r));
    }

    private static void readEvents(PhyInput in, final PhyWorld w) throws PhyFormatException {
        int n = readList(in, "event count", "event", w.getEvents(), new RecordReader<PhyEvent>() {
            @Override
            public PhyEvent read(PhyInput i) throws PhyFormatException {
                return PhyEvent.read(i, w);
            }
        });
        w.getLayout().add(new PhySection(PhySection.EVENTS, n, 0));
    }

    private static void readEmitters(PhyInput in, final PhyWorld w) throws PhyFormatException {
        int n = readList(in, "particle emitter count", "particle emitter", w.getParticleEmitters(),
                new RecordReader<PhyParticleEmitter>() {
                    @Override
                    public PhyParticleEmitter read(PhyInput i) throws PhyFormatException {
                        return PhyParticleEmitter.read(i, w.getBodies().size());
                    }
                });
        w.getLayout().add(new PhySection(PhySection.PARTICLES, n, 0));
    }
}
