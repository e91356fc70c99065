package org.emini.harness.fuzz.world;

/**
 * Smooth worlds: no contact at all (every body non-interacting, no landscape), no damping, only
 * smooth forces: projectiles, pendulums of one or two links swinging up to 1.1 rad (a triple or
 * wide double pendulum is chaotic, and its error need not fall with the step), bodies on soft springs, bodies spun or
 * pushed by motors and bodies under constant external forces, 200 px apart. Their motion depends
 * smoothly on the timestep, so halving it must bring a run closer to finer runs.
 */
final class SmoothGenerator {
    private final Rand rand;
    private final RecipeDraft draft = new RecipeDraft();
    private final Recipe r = draft.recipe;
    private final ShapeGenerator shapes;

    private SmoothGenerator(Rand rand) {
        this.rand = rand;
        this.shapes = new ShapeGenerator(rand, false, 0);
    }

    static Recipe generate(Rand rand) {
        return new SmoothGenerator(rand).build();
    }

    private Recipe build() {
        r.ticksPerSecond = rand.chance(0.5) ? 20 : 60;
        r.ticks = 2 * r.ticksPerSecond;
        r.iterations = rand.pick(4, 8, 10);
        if (rand.chance(0.3)) {
            r.gravityX = rand.length(-30, 30);
        }
        int systems = rand.between(1, 4);
        for (int i = 0; i < systems; i++) {
            float x = Rand.round((i - (systems - 1) / 2.0) * 200, Rand.LENGTH);
            switch (rand.between(0, 4)) {
                case 0 -> projectile(x);
                case 1 -> pendulum(x);
                case 2 -> spring(x);
                case 3 -> motor(x);
                default -> pushed(x);
            }
        }
        // Nothing touches: every body, pivots included, is non-interacting.
        r.bodies.forEach(b -> b.interacting = false);
        return r;
    }

    private void projectile(float x) {
        BodyRecipe b = free(x, -200);
        b.vx = rand.length(-80, 80);
        b.vy = rand.length(-150, 50);
        b.omega = rand.range(-5, 5, Rand.ANGLE);
    }

    private void pendulum(float x) {
        BodyRecipe previous = draft.body(shapes.box(6, 6), x, -300, false);
        float px = x;
        float py = -300;
        double angle = rand.angle(-0.8, 0.8);
        for (int i = rand.between(1, 2); i > 0; i--) {
            float length = rand.length(20, 50);
            float bx = Rand.round(px + length * Math.sin(angle), Rand.LENGTH);
            float by = Rand.round(py + length * Math.cos(angle), Rand.LENGTH);
            BodyRecipe b = free(bx, by);
            draft.pin(previous, b, px, py).fixed = rand.chance(0.15);
            previous = b;
            px = bx;
            py = by;
            angle += rand.angle(-0.3, 0.3);
        }
    }

    private void spring(float x) {
        BodyRecipe anchor = draft.body(shapes.box(6, 6), x, -300, false);
        BodyRecipe b = free(x + rand.length(-30, 30), -300 + rand.length(30, 80));
        SpringRecipe s = new SpringRecipe();
        s.id = draft.otherId();
        s.a = anchor.id;
        s.b = b.id;
        s.restLength = rand.length(20, 60);
        if (rand.chance(0.5)) {
            s.stiffness = rand.logRange(2, 100, Rand.FACTOR) * shapes0Mass(b);
            s.damping = rand.chance(0.5) ? rand.range(0, 2, Rand.FACTOR) : 0f;
        } else {
            s.hertz = rand.range(0.25, 2, Rand.FACTOR);
            s.dampingRatio = rand.range(0, 0.5, Rand.FACTOR);
        }
        r.springs.add(s);
    }

    private float shapes0Mass(BodyRecipe b) {
        return r.shape(b.shape).mass;
    }

    private void motor(float x) {
        BodyRecipe b = free(x, -200);
        b.gravity = rand.chance(0.5);
        MotorRecipe m = new MotorRecipe();
        m.id = draft.otherId();
        m.body = b.id;
        m.rotational = rand.chance(0.5);
        m.omega = rand.range(-4, 4, Rand.ANGLE);
        m.vx = rand.length(-60, 60);
        m.vy = rand.length(-60, 60);
        m.maxImpulse = rand.logRange(0.5, 20, Rand.FACTOR);
        r.motors.add(m);
    }

    private void pushed(float x) {
        BodyRecipe b = free(x, -200);
        ForceRecipe f = new ForceRecipe();
        f.id = draft.otherId();
        f.body = b.id;
        f.kind = rand.pick(new ForceRecipe.Kind[] {ForceRecipe.Kind.force, ForceRecipe.Kind.forceAt, ForceRecipe.Kind.torque});
        f.fx = rand.length(-100, 100);
        f.fy = rand.length(-100, 100);
        f.px = rand.length(-5, 5);
        f.py = rand.length(-5, 5);
        f.torque = rand.length(-500, 500);
        r.forces.add(f);
    }

    private BodyRecipe free(float x, float y) {
        ShapeRecipe s = shapes.any(6, 30, 0);
        r.shapes.add(s);
        BodyRecipe b = draft.body(s, x, y, true);
        b.angle = rand.angle(-Math.PI, Math.PI);
        return b;
    }

}
