package org.emini.io;

/** Square shape records for tests. */
final class Squares {
    private Squares() {
    }

    /** A square of half-size half around the origin, in the original's vertex order. */
    static PhyShape square(float half) {
        return new PhyShape(PhyVector.of(half, half), PhyVector.of(half, -half), PhyVector.of(-half, -half),
                PhyVector.of(-half, half));
    }
}
