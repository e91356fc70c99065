package org.emini.io;

import org.emini.dynamics.Landscape;

/** The landscape of a world file as the engine's landscape (see phy-mapping.md). */
final class LandscapeMapping {
    private LandscapeMapping() {
    }

    /** Builds the landscape; a segment the engine cannot take is listed. */
    static Landscape build(PhyLandscape l, BuildResult r) {
        Landscape landscape = new Landscape();
        PhyShape m = l.getMaterial();
        landscape.setFriction(WorldBuilder.unit(m.getFriction(), UnsupportedElement.Kind.LANDSCAPE_SEGMENT, 0,
                "landscape friction", r));
        landscape.setElasticity(WorldBuilder.unit(m.getElasticity(), UnsupportedElement.Kind.LANDSCAPE_SEGMENT, 0,
                "landscape elasticity", r));
        for (int i = 0; i < l.getSegments().size(); i++) {
            PhySegment s = l.getSegments().get(i);
            int face = s.getFace();
            if (face > PhySegment.FACE_RIGHT) {
                if (s.getEnd().getXRaw() <= s.getStart().getXRaw()) {
                    // The original swaps this segment and makes any other face right; the engine
                    // swaps it too and flips left to right.
                    face = PhySegment.FACE_LEFT;
                } else {
                    face = PhySegment.FACE_NONE;
                    r.approximated(UnsupportedElement.Kind.LANDSCAPE_SEGMENT, i, "face byte " + s.getFace()
                            + " is neither left nor right; built solid from both sides");
                }
            }
            // As stored: the engine applies the original's rule (end x ≤ start x swaps and flips).
            landscape.addSegment(s.getStart().getX(), s.getStart().getY(), s.getEnd().getX(), s.getEnd().getY(), face);
        }
        return landscape;
    }
}
