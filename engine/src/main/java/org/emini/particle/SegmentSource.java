package org.emini.particle;

/**
 * Fixed line segments that particles bounce off from either side (the original ignores landscape
 * facing for particles), besides the bodies: the world's landscape.
 */
interface SegmentSource {
    int getSegmentCount();

    float getStartX(int index);

    float getStartY(int index);

    float getEndX(int index);

    float getEndY(int index);
}
