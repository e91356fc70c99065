package org.emini.io;

/**
 * An entry of a world file's shape list: a {@link PhyShape} (circle, line or polygon with its
 * material) or a {@link PhyMultiShape} (a compound of earlier entries). Bodies, multishape parts
 * and event filters name entries by their position in that list.
 */
public abstract class PhyShapeBase extends PhyElement {
    PhyShapeBase() {
    }

    /**
     * Whether this entry is a multishape.
     *
     * @return true for a {@link PhyMultiShape}
     */
    public abstract boolean isMultiShape();
}
