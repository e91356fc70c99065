package org.emini.harness.fuzz.world;

/**
 * One removable part of a recipe: an element of a list by its generated id, or a world feature
 * (the simulation area, the listener).
 *
 * @param list "bodies", "segments", "joints", "springs", "motors", "emitters", "forces", "events",
 *     "removals", or "area" / "listener" (id -1)
 * @param id the element's id
 */
public record ElementRef(String list, int id) {
    @Override
    public String toString() {
        return id < 0 ? list : list + "[" + id + "]";
    }
}
