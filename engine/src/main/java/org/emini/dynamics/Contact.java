package org.emini.dynamics;

/**
 * A contact between two bodies whose bounding boxes overlap, or between a body and a segment of the
 * landscape: up to two contact points with a common normal, and the impulses the solver applied at
 * them in the last tick.
 *
 * <p>Contacts persist from tick to tick while the bodies stay close, so their impulses warm-start
 * the solver. Contact objects are pooled by the world: a reference is good until the contact ends
 * (its getters then throw {@link IllegalStateException}), and once the object serves another pair
 * it reads that pair. To keep a contact across ticks, keep its {@link #getHandle() handle} and
 * look it up with {@link Simulation#findContact(long)}, which answers null once it has ended. A
 * contact with no points is a pair that is near but not touching.
 *
 * <p>A body with a {@link org.emini.shape.MultiShape} has one contact per pair of parts whose
 * bounding boxes are near each other (and per part and landscape segment near it): each part has its
 * own box in the broadphase. {@link #getPartA()} and {@link #getPartB()} tell which. A landscape
 * contact ({@link #isLandscape()}) has the body as A and no body B; its normal points from the
 * body to the segment.
 */
public final class Contact {
    Body bodyA;
    Body bodyB;
    int partA;
    int partB;
    // The parts' keys in the world's PartKeys (their broadphase proxies); keyB is −1 for a landscape contact.
    int keyA = -1;
    int keyB = -1;
    // Landscape contacts: the segment's slot and stamp in the landscape; slot −1 for body pairs.
    Landscape landscape;
    int segmentSlot = -1;
    int segmentStamp;
    // The side of the segment the body touched last tick (Segment.side), kept while it touches.
    int segmentSide;
    // The tick in which the world last collected this contact for the solver.
    long gathered = -1;
    // Intrusive doubly linked lists through both bodies' contact lists.
    Contact prevA;
    Contact nextA;
    Contact prevB;
    Contact nextB;
    int index = -1;
    boolean filterDirty;

    // The points, as fields rather than small arrays: one object per contact, so the per-contact
    // passes touch a few adjacent cache lines instead of eight objects.
    int pointCount;
    // Touching, with the hysteresis StepData describes.
    boolean touching;
    float normalX;
    float normalY;
    float pointX0;
    float pointX1;
    float pointY0;
    float pointY1;
    float separation0;
    float separation1;
    int id0;
    int id1;
    float normalImpulse0;
    float normalImpulse1;
    float tangentImpulse0;
    float tangentImpulse1;
    float maxNormalImpulse0;
    float maxNormalImpulse1;
    float friction;
    float restitution;
    // ManifoldReuse: whether the points may be reused, the pose they were found at (B's in A's frame;
    // A's in the world for a landscape contact), the normal in that frame, and each point's two
    // surface points, on A in A's frame and on B in B's frame (the world for a landscape contact).
    boolean reusable;
    // ManifoldReuse for a pair found apart (no points): the gap the collider measured then
    // (Collider.getApartGap), 0 when not remembered; the pose fields below hold where B was.
    float apartGap;
    float poseX;
    float poseY;
    float poseC;
    float poseS;
    float frameNormalX;
    float frameNormalY;
    float surfaceAX0;
    float surfaceAY0;
    float surfaceBX0;
    float surfaceBY0;
    float surfaceAX1;
    float surfaceAY1;
    float surfaceBX1;
    float surfaceBY1;

    // The contact's place in the world's list of every contact object, and how many times the
    // object has ended: together its handle.
    int serial = -1;
    int generation;

    Contact() {
    }

    /** Refuses to read a contact that has ended: it is the pool's, and may soon be another pair. */
    private void live(String where) {
        if (index < 0) {
            throw new IllegalStateException(where + ": the contact has ended (contacts are reused; keep getHandle()"
                + " and look it up with World.findContact)");
        }
    }

    /**
     * A value that names this contact for as long as it lasts, for {@link Simulation#findContact(long)}.
     *
     * @return the handle
     */
    public long getHandle() {
        live("Contact.getHandle");
        return ((long) serial << 32) | (generation & 0xFFFFFFFFL);
    }

    Contact next(Body b) {
        return b == bodyA ? nextA : nextB;
    }

    float pointX(int p) {
        return p == 0 ? pointX0 : pointX1;
    }

    float pointY(int p) {
        return p == 0 ? pointY0 : pointY1;
    }

    float separation(int p) {
        return p == 0 ? separation0 : separation1;
    }

    float normalImpulse(int p) {
        return p == 0 ? normalImpulse0 : normalImpulse1;
    }

    float tangentImpulse(int p) {
        return p == 0 ? tangentImpulse0 : tangentImpulse1;
    }

    float maxNormalImpulse(int p) {
        return p == 0 ? maxNormalImpulse0 : maxNormalImpulse1;
    }

    /** Sets the impulses of a point (the solver's results, kept for warm starting and queries). */
    void setImpulses(int p, float normal, float tangent, float maxNormal) {
        if (p == 0) {
            normalImpulse0 = normal;
            tangentImpulse0 = tangent;
            maxNormalImpulse0 = maxNormal;
        } else {
            normalImpulse1 = normal;
            tangentImpulse1 = tangent;
            maxNormalImpulse1 = maxNormal;
        }
    }

    /**
     * The first body; the normal points from it to the second.
     *
     * @return body A
     */
    public Body getBodyA() {
        live("Contact.getBodyA");
        return bodyA;
    }

    /**
     * The second body.
     *
     * @return body B, or null for a landscape contact
     */
    public Body getBodyB() {
        live("Contact.getBodyB");
        return bodyB;
    }

    /**
     * The body on the other side of this contact.
     *
     * @param body one of the two bodies
     * @return the other one; null when that is the landscape
     */
    public Body getOther(Body body) {
        live("Contact.getOther");
        return body == bodyA ? bodyB : bodyA;
    }

    /**
     * Whether this is a contact between body A and the landscape.
     *
     * @return true for a landscape contact
     */
    public boolean isLandscape() {
        live("Contact.isLandscape");
        return segmentSlot >= 0;
    }

    /**
     * The landscape segment of a landscape contact, as its current index in the landscape.
     *
     * @return the segment index, or −1 for a contact between two bodies (or a segment removed
     *     since the last tick)
     */
    public int getSegment() {
        live("Contact.getSegment");
        if (segmentSlot < 0 || landscape.stampOf(segmentSlot) != segmentStamp) {
            return -1;
        }
        return landscape.indexOfSlot(segmentSlot);
    }

    /**
     * The part of body A's shape that touches: its index in A's
     * {@link org.emini.shape.MultiShape}, or 0 when A's shape is a single shape.
     *
     * @return the part index
     */
    public int getPartA() {
        live("Contact.getPartA");
        return partA;
    }

    /**
     * The part of body B's shape that touches: its index in B's
     * {@link org.emini.shape.MultiShape}, or 0 when B's shape is a single shape or B is the
     * landscape.
     *
     * @return the part index
     */
    public int getPartB() {
        live("Contact.getPartB");
        return partB;
    }

    /**
     * Whether the shapes touch: since a point of theirs came to zero separation or inside, until
     * none is within {@link SolverSettings#getSpeculativeDistance()} (see {@link StepData}).
     *
     * @return true when touching
     */
    public boolean isTouching() {
        live("Contact.isTouching");
        return touching;
    }

    /**
     * The number of contact points: 0, 1 (a corner on a face: "single") or 2 (face on face).
     *
     * @return the point count
     */
    public int getPointCount() {
        live("Contact.getPointCount");
        return pointCount;
    }

    /**
     * Whether this is a single-point contact, as the original engine reports it.
     *
     * @return true when there is exactly one point
     */
    public boolean isSingle() {
        live("Contact.isSingle");
        return pointCount == 1;
    }

    /**
     * The x component of the unit normal, pointing from body A to body B. With no points (the
     * bodies apart, as when the contact ends) it is the normal of the last tick that had points,
     * (0, 0) if none had.
     *
     * @return normal x
     */
    public float getNormalX() {
        live("Contact.getNormalX");
        return normalX;
    }

    /**
     * The y component of the unit normal, pointing from body A to body B ({@link #getNormalX()}).
     *
     * @return normal y
     */
    public float getNormalY() {
        live("Contact.getNormalY");
        return normalY;
    }

    /**
     * The x position of a contact point (midway between the surfaces).
     *
     * @param i the point, 0 or 1
     * @return x (px)
     */
    public float getPointX(int i) {
        live("Contact.getPointX");
        return pointX(checkPoint(i));
    }

    /**
     * The y position of a contact point (midway between the surfaces).
     *
     * @param i the point, 0 or 1
     * @return y (px)
     */
    public float getPointY(int i) {
        live("Contact.getPointY");
        return pointY(checkPoint(i));
    }

    /**
     * The separation at a contact point when it was detected: negative when the shapes overlap.
     *
     * @param i the point, 0 or 1
     * @return the separation (px)
     */
    public float getSeparation(int i) {
        live("Contact.getSeparation");
        return separation(checkPoint(i));
    }

    /**
     * The overlap at a contact point when it was detected (the opposite of the separation, never
     * below 0).
     *
     * @param i the point, 0 or 1
     * @return the depth (px)
     */
    public float getDepth(int i) {
        live("Contact.getDepth");
        float d = -separation(checkPoint(i));
        return d > 0f ? d : 0f;
    }

    /**
     * The normal impulse the solver applied at a point in the last substep (warm-start value).
     *
     * @param i the point, 0 or 1
     * @return the impulse (mass·px/s)
     */
    public float getNormalImpulse(int i) {
        live("Contact.getNormalImpulse");
        return normalImpulse(checkPoint(i));
    }

    /**
     * The friction impulse the solver applied at a point in the last substep.
     *
     * @param i the point, 0 or 1
     * @return the impulse (mass·px/s)
     */
    public float getTangentImpulse(int i) {
        live("Contact.getTangentImpulse");
        return tangentImpulse(checkPoint(i));
    }

    /**
     * The largest normal impulse applied at a point during the last tick, summed over one substep;
     * a measure of how hard the bodies hit.
     *
     * @param i the point, 0 or 1
     * @return the impulse (mass·px/s)
     */
    public float getMaxNormalImpulse(int i) {
        live("Contact.getMaxNormalImpulse");
        return maxNormalImpulse(checkPoint(i));
    }

    /**
     * The friction coefficient of this contact: the product of the two shapes' friction factors
     * (for a landscape contact, the shape's factor times the landscape's).
     *
     * @return the friction coefficient
     */
    public float getFriction() {
        live("Contact.getFriction");
        return friction;
    }

    /**
     * The elasticity of this contact: the product of the two shapes' elasticities (for a landscape
     * contact, the shape's elasticity times the landscape's).
     *
     * @return the restitution coefficient
     */
    public float getElasticity() {
        live("Contact.getElasticity");
        return restitution;
    }

    private int checkPoint(int i) {
        if (i < 0 || i >= pointCount) {
            throw new IndexOutOfBoundsException("Contact point " + i + " of " + pointCount);
        }
        return i;
    }

    @Override
    public String toString() {
        String other = segmentSlot >= 0 ? "landscape segment " + getSegment() : String.valueOf(bodyB);
        return "Contact(" + bodyA + ", " + other + ", " + pointCount + " points)";
    }
}
