package org.emini.harness.load;

/**
 * The largest scene the harness reads, so that no file can hang it or exhaust its memory: each limit
 * is reported as a located problem, never met as an OutOfMemoryError. Documented in scenarios/README.md
 * (Limits); the schema carries the per-field bounds, these are the ones a schema cannot state (sizes
 * after alias expansion, totals over the scene, products such as bodies × ticks).
 */
public final class Limits {
    private Limits() {
    }

    /** Bytes of a scene file (the library's largest, bench/joint-grid.yaml, is 106 kB). */
    public static final long FILE_BYTES = 4L << 20;

    /** Code points of a scene's text: the file limit, so that SnakeYAML's own limit is never the one met. */
    public static final int CODE_POINTS = (int) FILE_BYTES;

    /** YAML events (scalars, collections, aliases) the parser reads, before alias expansion. */
    public static final int EVENTS = 500_000;

    /** Values in the document after aliases are expanded (an alias bomb stops here). */
    public static final int NODES = 500_000;

    /** Collections nested in collections. */
    public static final int DEPTH = 40;

    /** Aliases to collections (SnakeYAML's maxAliasesForCollections). */
    public static final int COLLECTION_ALIASES = 100;

    /** Bodies in a scene, written and generated. */
    public static final int BODIES = 100_000;

    /** Ticks of a run (duration / timestep). */
    public static final long TICKS = 1_000_000;

    /** Bodies × ticks: the work of a run (bench/rain-20000 is 7.2 million). */
    public static final long BODY_TICKS = 100_000_000;

    /** Values a run's trace holds: samples × (6 per recorded body + metric channels). */
    public static final long TRACE_VALUES = 20_000_000;

    /** Convex parts of one multi-shape, once named parts (which may nest) are placed. */
    public static final long SHAPE_PARTS = 1_000;

    /**
     * Pairs of bodies whose bounding boxes (of their bounding circles) overlap at the start: the engine
     * collides them all in the first tick, and thousands of bodies piled on one spot make that tick
     * quadratic or worse (the library's most is bench/rain-20000's 28,418).
     */
    public static final long STARTING_OVERLAPS = 200_000;

    /**
     * Coordinates (px) a dynamic body may have, at the start and after every tick. Beyond 10^7 a float
     * no longer resolves a pixel, bodies collapse onto the same coordinates and the broadphase pairs
     * them all (a pile falling for an hour, a gravity of 1e30): the run stops there instead.
     */
    public static final float POSITION = 1e7f;

    /**
     * Wall-clock seconds a scene's run may take by default ({@code run --scene-timeout}): the library's
     * longest takes about a minute; a scene that piles pairs up (bodies moving many widths per tick)
     * can take hours, and stops here with an error instead.
     */
    public static final double SCENE_SECONDS = 1800;

    /** Particles in all emitters' pools together. */
    public static final long PARTICLES = 1_000_000;
}
