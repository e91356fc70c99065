package org.emini.harness.fuzz.world;

/**
 * Which features a profile's worlds may use (the generator draws among these).
 *
 * @param energySources motors, external forces, springs, elasticity and removals
 * @param sceneOnly only what a scene file can say, on the world file's grid
 * @param extreme values far outside a game's ranges
 */
record Features(boolean energySources, boolean sceneOnly, boolean extreme) {
    static Features of(Profile p) {
        return switch (p) {
            case PASSIVE -> new Features(false, false, false);
            case SCENE -> new Features(true, true, false);
            case EXTREME -> new Features(true, false, true);
            default -> new Features(true, false, false);
        };
    }
}
