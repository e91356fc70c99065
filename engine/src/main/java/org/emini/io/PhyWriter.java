package org.emini.io;

import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;

/**
 * Writes a {@link PhyWorld} in the original binary format, in the document's version, so that
 * {@link PhyReader} (and the original loader) read back the same document.
 *
 * <p>The sections follow the document's recorded layout when it still matches its lists, which
 * reproduces a read file byte for byte; otherwise the World Designer's order: shapes, bodies,
 * landscape, constraints, scripts, events, particle emitters, world record. Lists longer than a
 * section's 255-record count are split over several sections (the original accumulates them),
 * except in version 1, which has exactly one section of each kind.
 *
 * <p>A document the format cannot hold is refused with an {@link IllegalArgumentException} naming
 * the record: a reference to no earlier record, a field the version does not store holding a
 * value other than its default (user data before its version, shape mass before 0x0500, separate
 * damping before 0x0A00, multishapes before 0x0900, landscape, scripts, emitters or a world
 * record in version 1), a sensor event without a sensor body, or trailing bytes in a tagged file.
 */
public final class PhyWriter {
    private static final int MAX = 255;

    /** Creates a writer. */
    public PhyWriter() {
    }

    /**
     * Writes a document to a stream. The stream is not closed.
     *
     * @param world the document
     * @param out the stream
     * @throws IOException if the stream fails
     * @throws IllegalArgumentException if the format cannot hold the document
     */
    public void write(PhyWorld world, OutputStream out) throws IOException {
        byte[] b = write(world);
        out.write(b);
    }

    /**
     * Writes a document to bytes.
     *
     * @param world the document
     * @return the file's bytes
     * @throws IllegalArgumentException if the format cannot hold the document
     */
    public byte[] write(PhyWorld world) {
        PhyWorld.checkNotNull("PhyWriter.write", "world", world);
        if (layoutFits(world)) {
            try {
                return emit(world, world.getLayout());
            } catch (IllegalArgumentException e) {
                // An edit made a reference point forward in the old layout: use the designer's order.
            }
        }
        return emit(world, canonicalPlan(world));
    }

    private static boolean layoutFits(PhyWorld w) {
        List<PhySection> layout = w.getLayout();
        int v = w.getVersionWord();
        if (layout.isEmpty()) {
            // A tagged file may hold no section at all; a document built in code gets the designer's.
            return PhyVersion.isTagged(v) && w.getShapes().isEmpty() && w.getBodies().isEmpty()
                    && w.getLandscape() == null && w.getConstraints().isEmpty() && w.getScripts().isEmpty()
                    && w.getScriptBindings().isEmpty() && w.getEvents().isEmpty()
                    && w.getParticleEmitters().isEmpty() && w.getSettings() == null;
        }
        if (!PhyVersion.isTagged(v) && !isVersion1Order(layout)) {
            return false;
        }
        int shape = 0;
        int[] counts = new int[9];
        int rows = 0;
        for (PhySection s : layout) {
            int tag = s.getTag();
            if (tag == PhySection.SHAPES) {
                if (s.getExtraCount() > 0 && !PhyVersion.hasMultiShapes(v)
                        || !kindsMatch(w.getShapes(), shape, s.getCount(), false)
                        || !kindsMatch(w.getShapes(), shape + s.getCount(), s.getExtraCount(), true)) {
                    return false;
                }
                shape += s.getCount() + s.getExtraCount();
            } else if (tag >= 1 && tag <= 8) {
                counts[tag] += tag == PhySection.LANDSCAPE || tag == PhySection.WORLD ? 1 : s.getCount();
                rows += tag == PhySection.SCRIPTS ? s.getExtraCount() : 0;
            }
        }
        return shape == w.getShapes().size() && counts[PhySection.BODIES] == w.getBodies().size()
                && counts[PhySection.CONSTRAINTS] == w.getConstraints().size()
                && counts[PhySection.SCRIPTS] == w.getScripts().size() && rows == w.getScriptBindings().size()
                && counts[PhySection.EVENTS] == w.getEvents().size()
                && counts[PhySection.PARTICLES] == w.getParticleEmitters().size()
                && (counts[PhySection.LANDSCAPE] > 0) == (w.getLandscape() != null)
                && (counts[PhySection.WORLD] > 0) == (w.getSettings() != null);
    }

    private static boolean isVersion1Order(List<PhySection> layout) {
        return layout.size() == 4 && layout.get(0).getTag() == PhySection.SHAPES
                && layout.get(1).getTag() == PhySection.BODIES && layout.get(2).getTag() == PhySection.CONSTRAINTS
                && layout.get(3).getTag() == PhySection.EVENTS;
    }

    private static boolean kindsMatch(List<PhyShapeBase> shapes, int from, int n, boolean multi) {
        if (from + n > shapes.size()) {
            return false;
        }
        for (int i = from; i < from + n; i++) {
            if (shapes.get(i).isMultiShape() != multi) {
                return false;
            }
        }
        return true;
    }

    private static List<PhySection> canonicalPlan(PhyWorld w) {
        List<PhySection> plan = new ArrayList<PhySection>();
        int v = w.getVersionWord();
        if (!PhyVersion.isTagged(v)) {
            plan.add(new PhySection(PhySection.SHAPES, version1Count(w.getShapes().size(), "shapes"), 0));
            plan.add(new PhySection(PhySection.BODIES, version1Count(w.getBodies().size(), "bodies"), 0));
            plan.add(new PhySection(PhySection.CONSTRAINTS,
                    version1Count(w.getConstraints().size(), "constraints"), 0));
            plan.add(new PhySection(PhySection.EVENTS, version1Count(w.getEvents().size(), "events"), 0));
            return plan;
        }
        List<PhyShapeBase> shapes = w.getShapes();
        int i = 0;
        do {
            int n = run(shapes, i, false);
            int m = PhyVersion.hasMultiShapes(v) ? run(shapes, i + n, true) : 0;
            if (n + m == 0 && i < shapes.size()) {
                throw new IllegalArgumentException("PhyWriter.write: version " + PhyVersion.toString(v)
                        + " cannot store multishapes; shape " + i + " is one");
            }
            plan.add(new PhySection(PhySection.SHAPES, n, m));
            i += n + m;
        } while (i < shapes.size());
        chunks(plan, PhySection.BODIES, w.getBodies().size(), true);
        if (w.getLandscape() != null) {
            plan.add(new PhySection(PhySection.LANDSCAPE, 0, 0));
        }
        chunks(plan, PhySection.CONSTRAINTS, w.getConstraints().size(), false);
        int scripts = w.getScripts().size();
        int rows = w.getScriptBindings().size();
        while (scripts > 0 || rows > 0) {
            int ns = Math.min(MAX, scripts);
            scripts -= ns;
            int nr = scripts > 0 ? 0 : Math.min(MAX, rows);
            rows -= nr;
            plan.add(new PhySection(PhySection.SCRIPTS, ns, nr));
        }
        chunks(plan, PhySection.EVENTS, w.getEvents().size(), false);
        chunks(plan, PhySection.PARTICLES, w.getParticleEmitters().size(), false);
        if (w.getSettings() != null) {
            plan.add(new PhySection(PhySection.WORLD, 0, 0));
        }
        return plan;
    }

    private static int version1Count(int n, String what) {
        if (n > MAX) {
            throw new IllegalArgumentException("PhyWriter.write: version 1 holds at most 255 " + what + ", got " + n);
        }
        return n;
    }

    private static int run(List<PhyShapeBase> shapes, int from, boolean multi) {
        int n = 0;
        while (from + n < shapes.size() && shapes.get(from + n).isMultiShape() == multi && n < MAX) {
            n++;
        }
        return n;
    }

    private static void chunks(List<PhySection> plan, int tag, int total, boolean always) {
        int left = total;
        if (always && left == 0) {
            plan.add(new PhySection(tag, 0, 0));
        }
        while (left > 0) {
            int n = Math.min(MAX, left);
            plan.add(new PhySection(tag, n, 0));
            left -= n;
        }
    }

    private static byte[] emit(PhyWorld w, List<PhySection> plan) {
        int v = w.getVersionWord();
        boolean tagged = PhyVersion.isTagged(v);
        PhyOutput out = new PhyOutput(v);
        out.i32(v);
        int events = 0;
        int emitters = 0;
        int rows = 0;
        boolean landscape = false;
        boolean settings = false;
        for (PhySection s : plan) {
            if (tagged) {
                out.u8(s.getTag());
            }
            switch (s.getTag()) {
                case PhySection.SHAPES:
                    writeShapes(w, s, out);
                    break;
                case PhySection.BODIES:
                    out.bodies = writeList(out, w.getBodies(), out.bodies, s.getCount(), "body");
                    break;
                case PhySection.CONSTRAINTS:
                    out.constraints = writeList(out, w.getConstraints(), out.constraints, s.getCount(), "constraint");
                    break;
                case PhySection.SCRIPTS:
                    out.scripts = writeList(out, w.getScripts(), out.scripts, s.getCount(), "script");
                    rows = writeList(out, w.getScriptBindings(), rows, s.getExtraCount(), "script-body row");
                    break;
                case PhySection.EVENTS:
                    events = writeList(out, w.getEvents(), events, s.getCount(), "event");
                    break;
                case PhySection.LANDSCAPE:
                    out.record("landscape material", -1);
                    w.getLandscape().write(out);
                    landscape = true;
                    break;
                case PhySection.WORLD:
                    out.record("the world record", -1);
                    w.getSettings().write(out);
                    settings = true;
                    break;
                case PhySection.PARTICLES:
                    emitters = writeList(out, w.getParticleEmitters(), emitters, s.getCount(), "particle emitter");
                    break;
                default:
                    break;
            }
        }
        String missing = out.shapes < w.getShapes().size() ? "shapes"
                : out.bodies < w.getBodies().size() ? "bodies"
                : out.constraints < w.getConstraints().size() ? "constraints"
                : out.scripts < w.getScripts().size() || rows < w.getScriptBindings().size() ? "scripts"
                : events < w.getEvents().size() ? "events"
                : emitters < w.getParticleEmitters().size() ? "particle emitters"
                : w.getLandscape() != null && !landscape ? "a landscape"
                : w.getSettings() != null && !settings ? "a world record"
                : tagged && w.getTrailingBytes().length > 0 ? "trailing bytes" : null;
        if (missing != null) {
            throw new IllegalArgumentException("PhyWriter.write: version " + PhyVersion.toString(v)
                    + " cannot store " + missing + " of this document");
        }
        if (!tagged) {
            out.bytes(w.getTrailingBytes());
        }
        return out.toByteArray();
    }

    /** Writes a u8 count and that many records from a list; returns the index after them. */
    private static int writeList(PhyOutput out, List<?> list, int from, int n, String kind) {
        out.u8(n);
        for (int i = from; i < from + n; i++) {
            out.record(kind, i);
            Object r = list.get(i);
            if (r instanceof PhyBody) {
                ((PhyBody) r).write(out);
            } else if (r instanceof PhyConstraint) {
                ((PhyConstraint) r).write(out);
            } else if (r instanceof PhyScript) {
                ((PhyScript) r).write(out);
            } else if (r instanceof PhyScriptBinding) {
                ((PhyScriptBinding) r).write(out);
            } else if (r instanceof PhyEvent) {
                ((PhyEvent) r).write(out);
            } else {
                ((PhyParticleEmitter) r).write(out);
            }
        }
        return from + n;
    }

    private static void writeShapes(PhyWorld w, PhySection s, PhyOutput out) {
        out.u8(s.getCount());
        for (int i = 0; i < s.getCount(); i++, out.shapes++) {
            PhyShapeBase shape = w.getShapes().get(out.shapes);
            out.record("shape", out.shapes);
            if (shape.isMultiShape()) {
                throw new IllegalArgumentException("PhyWriter.write: version " + PhyVersion.toString(out.version())
                        + " cannot store multishapes; shape " + out.shapes + " is one");
            }
            ((PhyShape) shape).write(out);
        }
        if (PhyVersion.hasMultiShapes(out.version())) {
            out.u8(s.getExtraCount());
            for (int i = 0; i < s.getExtraCount(); i++, out.shapes++) {
                out.record("shape", out.shapes);
                ((PhyMultiShape) w.getShapes().get(out.shapes)).write(out);
            }
        }
    }
}
