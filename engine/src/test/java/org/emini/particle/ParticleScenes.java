package org.emini.particle;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.math.EMath;
import org.emini.shape.Shape;

/** Small scene builders shared by the particle tests. */
final class ParticleScenes {
    private ParticleScenes() {
    }

    /**
     * Four static walls closing the square |x'|, |y'| &lt;= half, where (x', y') is the world
     * point turned by −angle about the origin.
     */
    static Body[] box(World world, float half, float thickness, float angle) {
        float c = EMath.cos(angle);
        float s = EMath.sin(angle);
        float mid = half + 0.5f * thickness;
        float length = 2f * half + 2f * thickness;
        Shape across = Shape.createRectangle(length, thickness);
        Shape upright = Shape.createRectangle(thickness, length);
        float[][] walls = {{0f, -mid}, {0f, mid}, {-mid, 0f}, {mid, 0f}};
        Body[] bodies = new Body[4];
        for (int i = 0; i < 4; i++) {
            float lx = walls[i][0];
            float ly = walls[i][1];
            Body b = new Body(c * lx - s * ly, s * lx + c * ly, i < 2 ? across : upright, false);
            b.setAngle(angle);
            world.addBody(b);
            bodies[i] = b;
        }
        return bodies;
    }

    /** Whether every particle lies in the box built by {@link #box} with that half size and angle. */
    static int countOutsideBox(ParticleEmitter e, float half, float angle) {
        float c = EMath.cos(angle);
        float s = EMath.sin(angle);
        int outside = 0;
        for (int i = 0; i < e.getParticleCount(); i++) {
            float x = e.getX(i);
            float y = e.getY(i);
            float lx = c * x + s * y;
            float ly = -s * x + c * y;
            if (!(Math.abs(lx) <= half && Math.abs(ly) <= half)) {
                outside++;
            }
        }
        return outside;
    }

    /** Crates and balls in alternation, n of them from x = left in steps, in four staggered rows up from y = bottom. */
    static void cratesAndBalls(World world, int n, float left, float step, float bottom) {
        Shape crate = Shape.createRectangle(24f, 18f);
        Shape ball = Shape.createCircle(10f);
        for (int i = 0; i < n; i++) {
            world.addBody(new Body(left + step * i, bottom - 30f * (i % 4), i % 2 == 0 ? crate : ball, true));
        }
    }

    /** A fixed emitter that sprays in every direction from the origin. */
    static ParticleEmitter spray(int max, float rate, float lifetime, float speed, float speedDeviation) {
        ParticleEmitter e = new ParticleEmitter(max);
        e.setCreationRate(rate, 0f);
        e.setLifetime(lifetime, 0f);
        e.setSpeed(speed, speedDeviation);
        e.setAngle(0f, EMath.TWO_PI);
        return e;
    }

    /** An emitter in the world with one particle emitted now from (x, y) at (vx, vy), living long. */
    static ParticleEmitter one(World world, float x, float y, float vx, float vy) {
        ParticleEmitter e = new ParticleEmitter(1);
        e.setCreationRate(0f, 0f);
        e.setLifetime(1000f, 0f);
        e.setEmitPoint(x, y);
        e.setSpeed(EMath.sqrt(vx * vx + vy * vy), 0f);
        e.setAngle(EMath.atan2(vy, vx), 0f);
        world.addParticleEmitter(e);
        e.emit(1);
        return e;
    }

    static void run(World world, int ticks) {
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
    }
}
