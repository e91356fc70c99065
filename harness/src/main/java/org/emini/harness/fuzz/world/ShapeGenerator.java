package org.emini.harness.fuzz.world;


/**
 * Random shapes of every kind: circles (some off-centre), rectangles, regular polygons, convex
 * polygons around the origin, off it, or moved to their centroid by {@code centred()}, and
 * multi-shapes of two or three parts. Sizes are extents in px.
 */
final class ShapeGenerator {
    private final Rand rand;
    private final boolean sceneOnly;
    private int nextId;

    /**
     * @param sceneOnly only what a scene and a world file hold: whole-pixel circles on the origin, no
     *     {@code centred()}, circle parts only at a multi-shape's origin
     */
    ShapeGenerator(Rand rand, boolean sceneOnly, int firstId) {
        this.rand = rand;
        this.sceneOnly = sceneOnly;
        this.nextId = firstId;
    }

    /** A shape of any kind with extent in [min, max], mass in [0.25, 8] (sometimes 20× heavier). */
    ShapeRecipe any(double min, double max, double elasticity) {
        ShapeRecipe s = switch (rand.between(0, 4)) {
            case 0 -> circle(min, max, true);
            case 1 -> rectangle(min, max);
            case 2 -> regularPolygon(min, max);
            case 3 -> polygon(min, max, true);
            default -> multi(min, max);
        };
        s.id = nextId++;
        material(s, elasticity);
        return s;
    }

    /** A rectangle (for floors, walls and lanes). */
    ShapeRecipe box(float width, float height) {
        ShapeRecipe s = new ShapeRecipe();
        s.id = nextId++;
        s.kind = ShapeRecipe.Kind.rectangle;
        s.width = width;
        s.height = height;
        return s;
    }

    /** A circle on the origin. */
    ShapeRecipe circle(double min, double max) {
        ShapeRecipe s = circle(min, max, false);
        s.id = nextId++;
        return s;
    }

    /** A regular polygon. */
    ShapeRecipe regular(double min, double max) {
        ShapeRecipe s = regularPolygon(min, max);
        s.id = nextId++;
        return s;
    }

    void material(ShapeRecipe s, double elasticity) {
        s.mass = rand.logRange(0.25, 8, Rand.FACTOR) * (rand.chance(0.05) ? 20f : 1f);
        s.friction = rand.factor(1);
        s.elasticity = elasticity > 0 && rand.chance(0.4) ? rand.factor(elasticity) : 0f;
    }

    private ShapeRecipe circle(double min, double max, boolean offCentre) {
        ShapeRecipe s = new ShapeRecipe();
        s.kind = ShapeRecipe.Kind.circle;
        s.radius = sceneOnly ? Math.max(1, Math.round(rand.length(min / 2, max / 2))) : rand.length(min / 2, max / 2);
        if (offCentre && !sceneOnly && rand.chance(0.2)) {
            s.centerX = rand.length(-s.radius / 2, s.radius / 2);
            s.centerY = rand.length(-s.radius / 2, s.radius / 2);
        }
        return s;
    }

    private ShapeRecipe rectangle(double min, double max) {
        ShapeRecipe s = new ShapeRecipe();
        s.kind = ShapeRecipe.Kind.rectangle;
        s.width = rand.length(min, max);
        s.height = rand.length(min, max);
        return s;
    }

    private ShapeRecipe regularPolygon(double min, double max) {
        ShapeRecipe s = new ShapeRecipe();
        s.kind = ShapeRecipe.Kind.regularPolygon;
        s.radius = rand.length(min / 2, max / 2);
        s.sides = rand.between(3, 12);
        return s;
    }

    /**
     * A convex polygon: 3 to 8 points on an ellipse at sorted angles at least 0.35 rad apart (so the
     * rounding to 1/16 px keeps it convex), around the origin, moved off it, or moved and centred.
     */
    private ShapeRecipe polygon(double min, double max, boolean mayMove) {
        for (int attempt = 0; attempt < 20; attempt++) {
            ShapeRecipe s = new ShapeRecipe();
            s.kind = ShapeRecipe.Kind.polygon;
            double rx = Math.max(min, rand.length(min, max)) / 2;
            double ry = Math.max(min, rand.length(min, max)) / 2;
            int n = rand.between(3, 8);
            double[] angles = new double[n];
            double a = rand.unit() * 2 * Math.PI;
            double slack = 2 * Math.PI - 0.35 * n;
            double[] gaps = new double[n];
            double total = 0;
            for (int i = 0; i < n; i++) {
                gaps[i] = rand.unit();
                total += gaps[i];
            }
            for (int i = 0; i < n; i++) {
                angles[i] = a;
                a += 0.35 + slack * gaps[i] / total;
            }
            boolean move = mayMove && rand.chance(0.5);
            float ox = move ? rand.length(-rx, rx) : 0f;
            float oy = move ? rand.length(-ry, ry) : 0f;
            s.vertices = new float[2 * n];
            for (int i = 0; i < n; i++) {
                s.vertices[2 * i] = Rand.round(ox + rx * Math.cos(angles[i]), Rand.LENGTH);
                s.vertices[2 * i + 1] = Rand.round(oy + ry * Math.sin(angles[i]), Rand.LENGTH);
            }
            s.centred = move && !sceneOnly && rand.chance(0.5);
            if (valid(s)) {
                return s;
            }
        }
        return rectangle(min, max);
    }

    /** Two or three parts placed around the origin (the engine keeps them in one frame). */
    private ShapeRecipe multi(double min, double max) {
        ShapeRecipe s = new ShapeRecipe();
        s.kind = ShapeRecipe.Kind.multiShape;
        int n = rand.between(2, 3);
        double partMax = Math.max(min, max * 0.6);
        for (int i = 0; i < n; i++) {
            ShapeRecipe.Part p = new ShapeRecipe.Part();
            boolean circle = rand.chance(0.3) && (!sceneOnly || i == 0);
            p.shape = circle ? circle(min, partMax, false) : rand.chance(0.5) ? rectangle(min, partMax) : polygon(min, partMax, false);
            p.shape.mass = rand.logRange(0.25, 4, Rand.FACTOR);
            if (!(circle && sceneOnly)) {
                p.offsetX = rand.length(-partMax / 2, partMax / 2);
                p.offsetY = rand.length(-partMax / 2, partMax / 2);
                p.angle = rand.chance(0.5) ? rand.angle(-Math.PI, Math.PI) : 0f;
            }
            s.parts.add(p);
        }
        s.centred = !sceneOnly && rand.chance(0.5);
        return s;
    }

    private static boolean valid(ShapeRecipe s) {
        return ShapeBuilder.accepted(s);
    }
}
