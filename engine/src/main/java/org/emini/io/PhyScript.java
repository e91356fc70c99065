package org.emini.io;

import java.util.ArrayList;
import java.util.List;

/**
 * A script record: a list of elements run one after another on a body, optionally restarted after
 * the last. Scripts carry no user data.
 */
public final class PhyScript {
    private int restart;
    private final List<PhyScriptElement> elements = new ArrayList<PhyScriptElement>();

    /** Creates an empty script that does not restart. */
    public PhyScript() {
    }

    /**
     * The restart byte; a value above 0 restarts the script after its last element.
     *
     * @return 0 to 255
     */
    public int getRestartByte() {
        return restart;
    }

    /**
     * Sets the restart byte.
     *
     * @param value 0 to 255
     */
    public void setRestartByte(int value) {
        restart = PhyWorld.checkU8("PhyScript.setRestartByte", "value", value);
    }

    /**
     * Whether the script restarts after its last element.
     *
     * @return true when the restart byte is above 0
     */
    public boolean isRestarting() {
        return restart > 0;
    }

    /**
     * The elements in order. The list is live; at most 255 can be stored.
     *
     * @return the element list
     */
    public List<PhyScriptElement> getElements() {
        return elements;
    }

    static PhyScript read(PhyInput in) throws PhyFormatException {
        PhyScript s = new PhyScript();
        s.restart = in.u8("restart flag");
        int n = in.u8("element count");
        for (int i = 0; i < n; i++) {
            s.elements.add(PhyScriptElement.read(in, i));
        }
        return s;
    }

    void write(PhyOutput out) {
        if (elements.size() > 255) {
            throw new IllegalArgumentException("PhyWriter.write: " + out.describe() + " has " + elements.size()
                    + " elements; a script holds at most 255");
        }
        out.u8(restart);
        out.u8(elements.size());
        for (PhyScriptElement e : elements) {
            e.write(out);
        }
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PhyScript && restart == ((PhyScript) o).restart
                && elements.equals(((PhyScript) o).elements);
    }

    @Override
    public int hashCode() {
        return restart * 31 + elements.hashCode();
    }

    @Override
    public String toString() {
        return "PhyScript[" + elements.size() + " elements" + (isRestarting() ? ", restarting]" : "]");
    }
}
