package org.emini.io;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The document model of an original world file (<code>.phy</code>, <code>.world</code>): every
 * record with its raw stored values, in file order. {@link PhyReader} fills it, {@link PhyWriter}
 * stores it, {@link WorldBuilder} turns it into a {@link org.emini.world.World}.
 *
 * <p>Records name each other by their index in these lists: bodies name shapes (the shape list
 * holds standard shapes and multishapes in file order), constraints and script rows name bodies,
 * events name bodies, shapes and constraints, emitters name bodies. A reference may only name an
 * entry stored before it. The lists are live; edit them to change the document.
 */
public final class PhyWorld {
    /** The byte value meaning "none" for the optional indices of events, emitters and script rows. */
    public static final int NONE = 255;

    private int versionWord;
    private final List<PhyShapeBase> shapes = new ArrayList<PhyShapeBase>();
    private final List<PhyBody> bodies = new ArrayList<PhyBody>();
    private PhyLandscape landscape;
    private final List<PhyConstraint> constraints = new ArrayList<PhyConstraint>();
    private final List<PhyScript> scripts = new ArrayList<PhyScript>();
    private final List<PhyScriptBinding> scriptBindings = new ArrayList<PhyScriptBinding>();
    private final List<PhyEvent> events = new ArrayList<PhyEvent>();
    private final List<PhyParticleEmitter> emitters = new ArrayList<PhyParticleEmitter>();
    private PhyWorldSettings settings;
    private byte[] trailing = new byte[0];
    private final List<PhySection> layout = new ArrayList<PhySection>();

    /** Creates an empty version-10 document with no landscape and no world record. */
    public PhyWorld() {
        this(PhyVersion.CURRENT);
    }

    /**
     * Creates an empty document.
     *
     * @param versionWord the version word; see {@link PhyVersion#isSupported(int)}
     * @throws IllegalArgumentException if the original would not load that version
     */
    public PhyWorld(int versionWord) {
        setVersionWord(versionWord);
    }

    /**
     * The version word as stored; it decides which fields the records hold ({@link PhyVersion}).
     *
     * @return the word, e.g. 0x0A00
     */
    public int getVersionWord() {
        return versionWord;
    }

    /**
     * Sets the version word the document is written with. Fields a version does not store must
     * hold their defaults (or be empty) for the writer to accept the document.
     *
     * @param versionWord a word with (word &amp; 0xFF00) in 0x0100 to 0x0A00
     * @throws IllegalArgumentException if the original would not load that version
     */
    public void setVersionWord(int versionWord) {
        if (!PhyVersion.isSupported(versionWord)) {
            throw new IllegalArgumentException("PhyWorld.setVersionWord: version word "
                    + PhyVersion.toString(versionWord) + " is not 0x0100 to 0x0A00 in its second byte");
        }
        this.versionWord = versionWord;
    }

    /**
     * The version index, 1 to 10.
     *
     * @return (word &amp; 0xFF00) &gt;&gt; 8
     */
    public int getVersion() {
        return PhyVersion.index(versionWord);
    }

    /**
     * The shape list: standard shapes and multishapes in file order.
     *
     * @return the live list
     */
    public List<PhyShapeBase> getShapes() {
        return shapes;
    }

    /**
     * The number of standard shapes (circles, lines, polygons) in the shape list.
     *
     * @return the count
     */
    public int getStandardShapeCount() {
        return shapes.size() - getMultiShapeCount();
    }

    /**
     * The number of multishapes in the shape list.
     *
     * @return the count
     */
    public int getMultiShapeCount() {
        int n = 0;
        for (PhyShapeBase s : shapes) {
            if (s.isMultiShape()) {
                n++;
            }
        }
        return n;
    }

    /**
     * The bodies in file order.
     *
     * @return the live list
     */
    public List<PhyBody> getBodies() {
        return bodies;
    }

    /**
     * The landscape.
     *
     * @return the landscape, or null when the file has none (version 1 files never do)
     */
    public PhyLandscape getLandscape() {
        return landscape;
    }

    /**
     * Sets the landscape.
     *
     * @param landscape the landscape, or null for none
     */
    public void setLandscape(PhyLandscape landscape) {
        this.landscape = landscape;
    }

    /**
     * The constraints (joints, springs, motors) in file order.
     *
     * @return the live list
     */
    public List<PhyConstraint> getConstraints() {
        return constraints;
    }

    /**
     * The scripts in file order.
     *
     * @return the live list
     */
    public List<PhyScript> getScripts() {
        return scripts;
    }

    /**
     * The script-body table: scripts running on bodies from the start.
     *
     * @return the live list
     */
    public List<PhyScriptBinding> getScriptBindings() {
        return scriptBindings;
    }

    /**
     * The events in file order (an event's id is its index).
     *
     * @return the live list
     */
    public List<PhyEvent> getEvents() {
        return events;
    }

    /**
     * The particle emitters in file order.
     *
     * @return the live list
     */
    public List<PhyParticleEmitter> getParticleEmitters() {
        return emitters;
    }

    /**
     * The world record (gravity, damping, world user data).
     *
     * @return the record, or null when the file has none (the defaults apply)
     */
    public PhyWorldSettings getSettings() {
        return settings;
    }

    /**
     * Sets the world record.
     *
     * @param settings the record, or null for none
     */
    public void setSettings(PhyWorldSettings settings) {
        this.settings = settings;
    }

    /**
     * Bytes after the last section of a version-1 file, which the original never reads (the six
     * version-1 test files end with one byte 0x00).
     *
     * @return a copy of the bytes; empty for tagged versions
     */
    public byte[] getTrailingBytes() {
        return trailing.clone();
    }

    /**
     * Sets the bytes written after the last section of a version-1 file.
     *
     * @param bytes the bytes (copied); null counts as empty
     */
    public void setTrailingBytes(byte[] bytes) {
        trailing = bytes == null ? new byte[0] : bytes.clone();
    }

    /**
     * The sections as the file laid them out, in order. The writer follows it when it still
     * matches the lists, and otherwise writes the designer's order.
     *
     * @return the live list; empty for a document built in code
     */
    public List<PhySection> getLayout() {
        return layout;
    }

    static int checkU8(String where, String what, int value) {
        if (value < 0 || value > 255) {
            throw new IllegalArgumentException(where + ": " + what + " must be 0 to 255, was " + value);
        }
        return value;
    }

    static <T> T checkNotNull(String where, String what, T value) {
        if (value == null) {
            throw new IllegalArgumentException(where + ": " + what + " must not be null");
        }
        return value;
    }

    private static boolean same(Object a, Object b) {
        return a == null ? b == null : a.equals(b);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhyWorld)) {
            return false;
        }
        PhyWorld w = (PhyWorld) o;
        return versionWord == w.versionWord && shapes.equals(w.shapes) && bodies.equals(w.bodies)
                && same(landscape, w.landscape) && constraints.equals(w.constraints) && scripts.equals(w.scripts)
                && scriptBindings.equals(w.scriptBindings) && events.equals(w.events)
                && emitters.equals(w.emitters) && same(settings, w.settings) && Arrays.equals(trailing, w.trailing)
                && layout.equals(w.layout);
    }

    @Override
    public int hashCode() {
        return ((versionWord * 31 + shapes.hashCode()) * 31 + bodies.hashCode()) * 31 + constraints.hashCode()
                + events.hashCode();
    }

    @Override
    public String toString() {
        return "PhyWorld[version " + PhyVersion.toString(versionWord) + ", shapes " + getStandardShapeCount() + "+"
                + getMultiShapeCount() + ", bodies " + bodies.size() + ", segments "
                + (landscape == null ? "-" : Integer.toString(landscape.getSegments().size())) + ", constraints "
                + constraints.size() + ", scripts " + scripts.size() + ", events " + events.size() + ", emitters "
                + emitters.size() + (settings == null ? "" : ", " + settings) + "]";
    }
}
