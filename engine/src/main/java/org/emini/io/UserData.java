package org.emini.io;

/**
 * The application's hook for user data, as in the original engine: while a world is built from a
 * file, each user-data string the file's version stores is handed to
 * {@link #createNewUserData(String, int)} with the kind of record it belongs to, and the returned
 * object is attached to what was built ({@code setUserData} of the world, shapes, bodies, sensor
 * bodies, events and the manual's constraints; emitters have none) and kept in
 * {@link BuildResult#getUserData(PhyElement)} for every record, built or not.
 *
 * <p>The original's {@code UserData.copy()}, which {@code World(World)} called on each object, has
 * no counterpart: copies of a world share their user-data objects (see PORTING.md).
 * The landscape material's string is discarded, as in the original.
 */
public interface UserData {
    /** Type code of a body's user data (including an event's sensor body). */
    int TYPE_BODY = 1;
    /** Type code of a shape's or multishape's user data. */
    int TYPE_SHAPE = 2;
    /** Type code of an event's user data. */
    int TYPE_EVENT = 3;
    /** Type code of a joint's, spring's or motor's user data. */
    int TYPE_CONSTRAINT = 4;
    /** Type code of a particle emitter's user data. */
    int TYPE_PARTICLE = 5;
    /** Type code of the world record's user data. */
    int TYPE_WORLD = 6;

    /**
     * Creates the application's object for a stored user-data string.
     *
     * @param data the string (possibly empty, never null)
     * @param type the kind of record: {@link #TYPE_BODY}, {@link #TYPE_SHAPE},
     *     {@link #TYPE_EVENT}, {@link #TYPE_CONSTRAINT}, {@link #TYPE_PARTICLE} or
     *     {@link #TYPE_WORLD}
     * @return the object to attach, or null for none
     */
    Object createNewUserData(String data, int type);
}
