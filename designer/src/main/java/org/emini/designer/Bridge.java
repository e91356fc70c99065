package org.emini.designer;

import java.io.ByteArrayInputStream;
import java.io.IOException;

import org.emini.harness.convert.WorldToScenario;
import org.emini.io.PhyReader;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWriter;
import org.emini.shape.Shape;
import org.teavm.jso.JSExport;

/**
 * What the page calls: the functions TeaVM exports from the WebAssembly module. The page holds one
 * document at a time, so the bridge keeps it (and its played world) here. A call that fails returns
 * its message (an empty string on success) rather than throwing across the bridge.
 */
public final class Bridge {
    private static PhyWorld doc = new PhyWorld();
    private static Play play;

    private Bridge() {
    }

    /**
     * The module's entry point; the page calls the exports.
     *
     * @param args unused
     */
    public static void main(String[] args) {
    }

    /**
     * Replaces the document and builds its world.
     *
     * @param json the document (see DocJson)
     * @param ticksPerSecond ticks per second
     * @param iterations constraint iterations
     * @return "" or what was wrong
     */
    @JSExport
    public static String load(String json, int ticksPerSecond, int iterations) {
        try {
            PhyWorld next = DocJson.read(json, doc);
            Play built = new Play(next, ticksPerSecond, iterations);
            doc = next;
            play = built;
            return "";
        } catch (RuntimeException e) {
            return message(e);
        }
    }

    /**
     * Reads a world file.
     *
     * @param bytes the file
     * @return {"doc": document} or {"error": message}
     */
    @JSExport
    public static String readPhy(byte[] bytes) {
        try {
            PhyWorld w = new PhyReader().setSkipUnknownSections(true).read(new ByteArrayInputStream(bytes));
            doc = w;
            return "{\"doc\":" + DocJson.write(w) + "}";
        } catch (IOException | RuntimeException e) {
            StringBuilder sb = new StringBuilder("{\"error\":");
            Json.quote(sb, message(e));
            return sb.append('}').toString();
        }
    }

    /**
     * The current document as a world file (version 10 unless it was read from an older file).
     *
     * @return the file's bytes, or an empty array if the writer refused it (see {@link #lastError()})
     */
    @JSExport
    public static byte[] writePhy() {
        try {
            lastError = "";
            return new PhyWriter().write(doc);
        } catch (RuntimeException e) {
            lastError = message(e);
            return new byte[0];
        }
    }

    private static String lastError = "";

    /** @return the last failure's message of {@link #writePhy()} */
    @JSExport
    public static String lastError() {
        return lastError;
    }

    /**
     * The current document as a scene file, by the harness's own converter (what
     * {@code harness convert world.phy} writes, 30 s long).
     *
     * @param source the world file's name, for the scene's header
     * @return the scene's YAML, or "" if the converter refused (see {@link #lastError()})
     */
    @JSExport
    public static String sceneYaml(String source) {
        try {
            lastError = "";
            return WorldToScenario.convert(doc, source, 30).yaml();
        } catch (RuntimeException e) {
            lastError = message(e);
            return "";
        }
    }

    /** @return the current document as JSON */
    @JSExport
    public static String document() {
        return DocJson.write(doc);
    }

    /**
     * What the engine says about a polygon, as the page edits it.
     *
     * @param xy vertex coordinates in px, x and y alternating
     * @return "" when {@link Shape#createPolygon} accepts them, else its message
     */
    @JSExport
    public static String polygonProblem(double[] xy) {
        float[] f = new float[xy.length];
        for (int i = 0; i < xy.length; i++) {
            f[i] = (float) xy[i];
        }
        try {
            Shape.createPolygon(f);
            return "";
        } catch (RuntimeException e) {
            return message(e);
        }
    }

    /** @return the built world's shapes and build report (see Play#geometry) */
    @JSExport
    public static String geometry() {
        return play == null ? "{\"bodies\":[],\"unsupported\":[],\"approximations\":[]}" : play.geometry();
    }

    /**
     * Runs ticks.
     *
     * @param n how many
     * @return "" or the engine's message
     */
    @JSExport
    public static String tick(int n) {
        try {
            if (play != null) {
                play.tick(n);
            }
            return "";
        } catch (RuntimeException e) {
            return message(e);
        }
    }

    /** @return the bodies' state (see Play#frame) */
    @JSExport
    public static float[] frame() {
        return play == null ? new float[0] : play.frame();
    }

    /** @return the touching contact points (see Play#contacts) */
    @JSExport
    public static float[] contacts() {
        return play == null ? new float[0] : play.contacts();
    }

    /** @return the live particles' positions */
    @JSExport
    public static float[] particles() {
        return play == null ? new float[0] : play.particles();
    }

    /** @return the live metrics (see Play#metrics) */
    @JSExport
    public static double[] metrics() {
        return play == null ? new double[] {0, 0, 0, 0, 0, 0, 0, 0, 0, -1} : play.metrics();
    }

    /**
     * The body at a point.
     *
     * @param x world x (px)
     * @param y world y (px)
     * @return its index in the world's body order, or −1
     */
    @JSExport
    public static int bodyAt(double x, double y) {
        return play == null ? -1 : play.bodyAt((float) x, (float) y);
    }

    /**
     * Starts dragging a body.
     *
     * @param body the body's index in the world's order
     * @param x grabbed point x
     * @param y grabbed point y
     * @return whether it is dragged (only dynamic bodies are)
     */
    @JSExport
    public static boolean dragStart(int body, double x, double y) {
        return play != null && play.dragStart(body, (float) x, (float) y);
    }

    /**
     * Moves the dragged point's target.
     *
     * @param x world x
     * @param y world y
     */
    @JSExport
    public static void dragMove(double x, double y) {
        if (play != null) {
            play.dragMove((float) x, (float) y);
        }
    }

    /** Lets the dragged body go. */
    @JSExport
    public static void dragEnd() {
        if (play != null) {
            play.dragEnd();
        }
    }

    private static String message(Throwable e) {
        String m = e.getMessage();
        return m == null || m.isEmpty() ? e.getClass().getName() : m;
    }
}
