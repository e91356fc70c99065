package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.List;
import org.emini.event.Event;

/**
 * The elements of a general world on its bodies: joints, springs, motors, external forces, events,
 * particle emitters and removals during a tick, each drawn with the values a game uses.
 */
final class ElementGenerator {
    private final Rand rand;
    private final Recipe recipe;
    private final Features features;
    private final List<BodyRecipe> dynamic = new ArrayList<>();
    private int nextId;

    ElementGenerator(Rand rand, Recipe recipe, Features features) {
        this.rand = rand;
        this.recipe = recipe;
        this.features = features;
        for (BodyRecipe b : recipe.bodies) {
            if (b.dynamic) {
                dynamic.add(b);
            }
        }
    }

    void all() {
        if (dynamic.isEmpty()) {
            return;
        }
        repeat(rand.between(0, 4), this::joint);
        if (features.energySources()) {
            repeat(rand.between(0, 3), this::spring);
            repeat(rand.between(0, 2), this::motor);
            if (!features.sceneOnly()) {
                repeat(rand.between(0, 2), this::force);
            }
        }
        repeat(rand.between(0, 2), this::emitter);
        if (!features.sceneOnly()) {
            repeat(rand.between(0, 6), this::event);
            recipe.listener = !recipe.events.isEmpty() && rand.chance(0.85) || rand.chance(0.05);
            if (features.energySources() && rand.chance(0.05)) {
                removal();
            }
        }
    }

    private void repeat(int n, Runnable r) {
        for (int i = 0; i < n; i++) {
            r.run();
        }
    }

    private BodyRecipe anyDynamic() {
        return dynamic.get((int) (rand.unit() * dynamic.size()));
    }

    private BodyRecipe anyBody() {
        return recipe.bodies.get((int) (rand.unit() * recipe.bodies.size()));
    }

    /** A partner for b: a static body half the time when there is one, else another body. */
    private BodyRecipe partner(BodyRecipe b) {
        for (int attempt = 0; attempt < 10; attempt++) {
            BodyRecipe a = anyBody();
            if (a != b && (a.dynamic == rand.chance(0.5) || attempt > 5)) {
                return a;
            }
        }
        return null;
    }

    /** A pin or fixed joint where both bodies are (or, in worlds with energy sources, up to 20 px off). */
    private void joint() {
        BodyRecipe b = anyDynamic();
        BodyRecipe a = partner(b);
        if (a == null) {
            return;
        }
        JointRecipe j = new JointRecipe();
        j.id = nextId++;
        j.a = a.id;
        j.b = b.id;
        double t = rand.pick(new Double[] {0.0, 0.5, 1.0});
        float px = Rand.round(b.x + t * (a.x - b.x), Rand.LENGTH);
        float py = Rand.round(b.y + t * (a.y - b.y), Rand.LENGTH);
        j.fixed = rand.chance(0.3);
        j.collide = rand.chance(0.2);
        if (!features.energySources() || rand.chance(0.85)) {
            j.atPoint = true;
            j.x = px;
            j.y = py;
        } else {
            float[] la = local(a, px, py);
            float[] lb = local(b, px + rand.length(-14, 14), py + rand.length(-14, 14));
            j.ax = la[0];
            j.ay = la[1];
            j.bx = lb[0];
            j.by = lb[1];
        }
        recipe.joints.add(j);
    }

    private void spring() {
        BodyRecipe b = anyDynamic();
        BodyRecipe a = partner(b);
        if (a == null) {
            return;
        }
        SpringRecipe s = new SpringRecipe();
        s.id = nextId++;
        s.a = a.id;
        s.b = b.id;
        s.ax = rand.length(-8, 8);
        s.ay = rand.length(-8, 8);
        s.bx = rand.length(-8, 8);
        s.by = rand.length(-8, 8);
        if (rand.chance(0.5)) {
            s.restLength = rand.length(0, 1.5 * Math.hypot(a.x - b.x, a.y - b.y) + 10);
        }
        double kind = rand.unit();
        if (kind < 0.4) {
            s.stiffness = rand.logRange(1, 500, Rand.FACTOR);
            s.damping = rand.chance(0.5) ? rand.range(0, 5, Rand.FACTOR) : 0f;
        } else if (kind < 0.7 && !features.sceneOnly()) {
            s.hertz = rand.range(0.25, 8, Rand.FACTOR);
            s.dampingRatio = rand.range(0, 1.5, Rand.FACTOR);
        }
        s.collide = rand.chance(0.7);
        recipe.springs.add(s);
    }

    private void motor() {
        MotorRecipe m = new MotorRecipe();
        m.id = nextId++;
        m.body = anyDynamic().id;
        m.rotational = rand.chance(0.5);
        if (m.rotational) {
            m.omega = rand.range(-6, 6, Rand.ANGLE);
        } else {
            m.vx = rand.chance(0.7) ? rand.length(-120, 120) : 0f;
            m.vy = rand.chance(0.5) ? rand.length(-120, 120) : 0f;
            m.relative = !features.sceneOnly() && rand.chance(0.3);
            m.orthogonal = !features.sceneOnly() && rand.chance(0.3);
        }
        m.maxImpulse = rand.logRange(0.5, 500, Rand.FACTOR);
        recipe.motors.add(m);
    }

    private void force() {
        ForceRecipe f = new ForceRecipe();
        f.id = nextId++;
        f.kind = rand.pick(ForceRecipe.Kind.values());
        if (f.kind == ForceRecipe.Kind.wind) {
            f.fx = rand.length(-60, 60);
            f.fy = rand.length(-60, 60);
        } else {
            f.body = anyDynamic().id;
            f.fx = rand.length(-300, 300);
            f.fy = rand.length(-300, 300);
            f.px = rand.length(-10, 10);
            f.py = rand.length(-10, 10);
            f.torque = rand.length(-3000, 3000);
        }
        recipe.forces.add(f);
    }

    private void event() {
        EventRecipe e = new EventRecipe();
        e.id = nextId++;
        e.type = rand.pick(Event.POSITION, Event.VELOCITY, Event.ANGLE, Event.ANGULAR_VELOCITY, Event.COLLISION,
                Event.SENSOR, Event.RELATIVE_COLLISION, Event.CONSTRAINT_FORCE);
        if (e.type != Event.CONSTRAINT_FORCE) {
            e.body = rand.chance(0.3) ? anyBody().id : -1;
            e.shape = rand.chance(0.2) ? anyBody().shape : -1;
        }
        e.triggerOnce = rand.chance(0.3);
        switch (e.type) {
            case Event.POSITION -> {
                e.p1 = rand.length(-300, 200);
                e.p2 = rand.length(-500, 0);
                e.p3 = e.p1 + rand.length(0, 300);
                e.p4 = e.p2 + rand.length(0, 300);
            }
            case Event.VELOCITY -> range(e, 0, 100, 1000);
            case Event.ANGLE -> range(e, 0, 2 * Math.PI, 2 * Math.PI);
            case Event.ANGULAR_VELOCITY -> range(e, -5, 5, 10);
            case Event.COLLISION -> {
                e.p1 = rand.chance(0.5) ? 1f : 0f;
                e.p2 = rand.chance(0.5) ? 1f : 0f;
                e.p3 = rand.chance(0.5) ? 1f : 0f;
                e.p4 = rand.chance(0.5) ? 1f : 0f;
            }
            case Event.RELATIVE_COLLISION -> range(e, -Math.PI, Math.PI, Math.PI);
            case Event.SENSOR -> {
                BodyRecipe sensor = anyBody();
                if (sensor.id == e.body) {
                    e.body = -1;
                }
                e.sensor = sensor.id;
            }
            default -> {
                constraintFilter(e);
                range(e, 0, 100, 5000);
            }
        }
        recipe.events.add(e);
    }

    private void range(EventRecipe e, double min, double max, double width) {
        e.p1 = rand.range(min, max, Rand.ANGLE);
        e.p2 = e.p1 + rand.range(0, width, Rand.ANGLE);
    }

    private void constraintFilter(EventRecipe e) {
        List<String> kinds = new ArrayList<>();
        recipe.joints.forEach(j -> kinds.add("joint:" + j.id));
        recipe.springs.forEach(s -> kinds.add("spring:" + s.id));
        recipe.motors.forEach(m -> kinds.add("motor:" + m.id));
        if (!kinds.isEmpty() && rand.chance(0.7)) {
            String[] k = kinds.get((int) (rand.unit() * kinds.size())).split(":");
            e.constraintKind = k[0];
            e.constraint = Integer.parseInt(k[1]);
        }
    }

    private void emitter() {
        EmitterRecipe e = new EmitterRecipe();
        e.id = nextId++;
        boolean onBody = rand.chance(0.5);
        e.body = onBody ? anyBody().id : -1;
        float cx = onBody ? 0f : rand.length(-250, 250);
        float cy = onBody ? 0f : rand.length(-400, -50);
        e.x1 = cx + rand.length(-10, 10);
        e.y1 = cy + rand.length(-10, 10);
        e.x2 = rand.chance(0.5) ? e.x1 : cx + rand.length(-10, 10);
        e.y2 = rand.chance(0.5) ? e.y1 : cy + rand.length(-10, 10);
        e.maxCount = rand.between(1, 300);
        e.rate = rand.range(0, 200, Rand.FACTOR);
        e.rateSpread = rand.chance(0.5) ? rand.range(0, e.rate, Rand.FACTOR) : 0f;
        e.lifetime = rand.range(0.25, 3, Rand.FACTOR);
        e.lifetimeSpread = rand.chance(0.5) ? rand.range(0, e.lifetime, Rand.FACTOR) : 0f;
        e.speed = rand.length(0, 300);
        e.speedSpread = rand.chance(0.5) ? rand.length(0, 100) : 0f;
        e.angleDeg = rand.range(-180, 180, Rand.FACTOR);
        e.angleSpreadDeg = rand.chance(0.5) ? rand.range(0, 90, Rand.FACTOR) : 0f;
        e.axesFixed = onBody && rand.chance(0.3);
        e.elasticity = rand.factor(1);
        e.gravityFactor = rand.range(-0.5, 2, Rand.FACTOR);
        e.damping = rand.chance(0.3) ? rand.factor(0.1) : 0f;
        e.collide = rand.chance(0.8);
        e.seed = rand.nextLong() & 0xFFFFFFFFL;
        recipe.emitters.add(e);
    }

    private void removal() {
        RemovalRecipe r = new RemovalRecipe();
        r.id = nextId++;
        r.body = anyBody().id;
        r.tick = rand.between(0, Math.max(1, recipe.ticks / 2));
        r.via = rand.pick(RemovalRecipe.Via.values());
        recipe.removals.add(r);
    }

    /** A world point in a body's own frame, rounded to the length step. */
    static float[] local(BodyRecipe b, double x, double y) {
        double c = Math.cos(b.angle);
        double s = Math.sin(b.angle);
        double dx = x - b.x;
        double dy = y - b.y;
        return new float[] {Rand.round(c * dx + s * dy, Rand.LENGTH), Rand.round(-s * dx + c * dy, Rand.LENGTH)};
    }
}
