package org.emini.collision;

import org.emini.math.EMath;

/** The broadphase's argument checks: boxes and values that name the call and the bad value. */
final class BoxChecks {
    private BoxChecks() {
    }

    static void query(
            String method, float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        box(method, minX, minY, maxX, maxY);
        if (callback == null) {
            throw new IllegalArgumentException(method + ": callback is null");
        }
    }

    static void box(String method, float minX, float minY, float maxX, float maxY) {
        finite(method, "minX", minX);
        finite(method, "minY", minY);
        finite(method, "maxX", maxX);
        finite(method, "maxY", maxY);
        if (minX > maxX) {
            throw new IllegalArgumentException(
                    method + ": minX (" + minX + ") > maxX (" + maxX + ")");
        }
        if (minY > maxY) {
            throw new IllegalArgumentException(
                    method + ": minY (" + minY + ") > maxY (" + maxY + ")");
        }
    }

    static void finite(String method, String name, float value) {
        if (!EMath.isFinite(value)) {
            throw new IllegalArgumentException(
                    method + ": " + name + " (" + value + ") is not finite");
        }
    }
}
