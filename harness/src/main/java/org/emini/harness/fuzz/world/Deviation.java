package org.emini.harness.fuzz.world;

/**
 * The largest difference between two runs of corresponding worlds over their common ticks: the
 * distance between each dynamic body's positions (the second run mapped back by a sign for x and
 * angle, and a shift), and between its angles.
 *
 * @param distance the largest position difference (px)
 * @param angle the largest angle difference (rad)
 * @param tick the tick of the largest position difference
 * @param body the recipe id of that body
 * @param path the largest distance a body moved from its start in the first run (px), the motion scale
 */
record Deviation(double distance, double angle, int tick, int body, double path) {
    /**
     * Compares run b, mapped as x → sign·(x − dx), y → y − dy, angle → sign·angle, with run a.
     */
    static Deviation of(Trajectory a, Trajectory b, int sign, double dx, double dy) {
        int n = Math.min(a.ticks, b.ticks);
        double worst = 0;
        double angle = 0;
        double path = 0;
        int tick = 0;
        int body = -1;
        for (int k = 0; k <= n; k++) {
            for (int i = 0; i < a.bodies(); i++) {
                if (!a.recipe.bodies.get(i).dynamic) {
                    continue;
                }
                double ax = a.get(k, i, 0);
                double ay = a.get(k, i, 1);
                double d = Math.hypot(ax - sign * (b.get(k, i, 0) - dx), ay - (b.get(k, i, 1) - dy));
                path = Math.max(path, Math.hypot(ax - a.get(0, i, 0), ay - a.get(0, i, 1)));
                angle = Math.max(angle, Math.abs(a.get(k, i, 2) - sign * b.get(k, i, 2)));
                if (d > worst || Double.isNaN(d)) {
                    worst = Double.isNaN(d) ? Double.POSITIVE_INFINITY : d;
                    tick = k - 1;
                    body = a.recipe.bodies.get(i).id;
                }
            }
        }
        return new Deviation(worst, angle, tick, body, path);
    }

    @Override
    public String toString() {
        return String.format("body %d is %.4g px off after tick %d (largest angle difference %.4g rad; bodies move up to %.4g px)",
                body, distance, tick, angle, path);
    }
}
