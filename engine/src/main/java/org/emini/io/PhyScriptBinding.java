package org.emini.io;

/**
 * A row of the script-body table: a script running on a body from the start. Read in the
 * designer's two-byte form (the original engine's loader reads two more bytes per row, which no
 * designer file holds). Immutable.
 */
public final class PhyScriptBinding {
    private final int script;
    private final int body;

    /**
     * Creates a row.
     *
     * @param script the script's index in the script list, 0 to 255
     * @param body the body's index in the body list, 0 to 255 ({@link PhyWorld#NONE}: the designer
     *     did not find the body)
     */
    public PhyScriptBinding(int script, int body) {
        this.script = PhyWorld.checkU8("PhyScriptBinding", "script", script);
        this.body = PhyWorld.checkU8("PhyScriptBinding", "body", body);
    }

    /**
     * The script's index in the script list.
     *
     * @return 0 to 255
     */
    public int getScript() {
        return script;
    }

    /**
     * The body's index in the body list.
     *
     * @return 0 to 255; {@link PhyWorld#NONE} for no body
     */
    public int getBody() {
        return body;
    }

    static PhyScriptBinding read(PhyInput in, int scriptsSoFar, int bodiesSoFar)
            throws PhyFormatException {
        int s = in.index("script index", scriptsSoFar);
        return new PhyScriptBinding(s, in.optionalIndex("body index", bodiesSoFar));
    }

    void write(PhyOutput out) {
        out.index("script index", script, out.scripts);
        out.optionalIndex("body index", body, out.bodies);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PhyScriptBinding && ((PhyScriptBinding) o).script == script
                && ((PhyScriptBinding) o).body == body;
    }

    @Override
    public int hashCode() {
        return script * 256 + body;
    }

    @Override
    public String toString() {
        return "PhyScriptBinding[script " + script + " on body " + body + "]";
    }
}
