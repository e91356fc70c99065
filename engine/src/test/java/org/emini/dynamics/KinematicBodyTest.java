package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.AllocationWindows;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Kinematic bodies: moved by the velocity the application sets and nothing else, infinite mass,
 * they push dynamic bodies and carry them by friction, and meet neither static nor kinematic bodies
 * nor the landscape.
 */
class KinematicBodyTest {

    private static Body kinematic(float x, float y, Shape shape) {
        Body b = new Body(x, y, shape, false);
        b.setKinematic(true);
        return b;
    }

    /** Moves by v·t and ω·t, whatever gravity and damping, with nothing touching it. */
    @Test
    void movesByItsVelocityAloneEveryTick() {
        World world = new World();
        world.setTicksPerSecond(60f);
        world.setDampingLateral(0.05f);
        world.setDampingRotational(0.05f);
        Body k = kinematic(10f, 20f, Shape.createRectangle(30f, 10f));
        k.setVelocity(40f, -25f);
        k.setAngularVelocity(1.5f);
        k.applyForce(1e6f, 0f);
        k.applyImpulse(1e6f, 0f);
        k.applyTorque(1e6f);
        world.addBody(k);
        Scenes.run(world, 2f);
        assertEquals(10f + 80f, k.getX(), 1e-3f);
        assertEquals(20f - 50f, k.getY(), 1e-3f);
        assertEquals(3f, k.getAngle(), 1e-4f);
        assertEquals(40f, k.getVelocityX(), "no damping, no gravity, no force: the velocity set");
        assertEquals(-25f, k.getVelocityY());
        assertEquals(1.5f, k.getAngularVelocity());
        assertTrue(k.isSimulated());
        assertTrue(k.isKinematic());
        assertFalse(k.isDynamic());
        assertFalse(k.isStatic());
        assertEquals(Float.POSITIVE_INFINITY, k.getMass());
        assertEquals(0f, k.getInverseMass());
        assertEquals(0f, k.getInverseInertia());
        assertEquals(0f, k.getKineticEnergy());
    }

    /**
     * A box set down on a platform that moves at constant speed V slides on it and is accelerated
     * by kinetic friction at μg until it moves with the platform, at T = V/(μg), having moved
     * V²/(2μg) while the platform moved V·T; from then on static friction carries it.
     */
    @ParameterizedTest
    @CsvSource({"50, 0.5, 60", "80, 0.4, 60", "30, 1.0, 20", "60, 0.25, 120"})
    void aPlatformCarriesABoxByFriction(float speed, float mu, float tps) {
        World world = new World();
        world.setTicksPerSecond(tps);
        float g = world.getGravityY();
        Shape deck = Shape.createRectangle(2000f, 20f);
        deck.setFriction(1f);
        Body platform = kinematic(0f, 10f, deck);
        world.addBody(platform);
        Shape crate = Shape.createRectangle(20f, 20f);
        crate.setFriction(mu);
        Body box = new Body(0f, -10f, crate, true);
        world.addBody(box);
        // Let the box settle at rest on the still platform.
        Scenes.run(world, 0.5f);
        assertEquals(-10f, box.getY(), 0.1f);
        float x0 = box.getX();
        float p0 = platform.getX();
        platform.setVelocity(speed, 0f);
        float a = mu * g;
        float matchTime = speed / a;
        float dt = world.getTimestep();
        int half = (int) Math.round(0.5f * matchTime / dt);
        for (int t = 0; t < half; t++) {
            world.tick();
        }
        float time = half * dt;
        assertEquals(a * time, box.getVelocityX(), 0.04f * speed, "half way: v = μg·t");
        assertEquals(x0 + 0.5f * a * time * time, box.getX(), 0.03f * speed * matchTime + 0.5f, "half way: x = μg·t²/2");
        // The time the box reaches the platform's speed.
        int ticks = half;
        while (box.getVelocityX() < speed - 0.01f * speed && ticks < 10 * half + 100) {
            world.tick();
            ticks++;
        }
        assertEquals(matchTime, ticks * dt, 0.04f * matchTime + dt, "T = V/(μg)");
        float slid = 0.5f * speed * matchTime;
        assertEquals(x0 + slid, box.getX(), 0.04f * slid + 1f, "distance while sliding: V²/(2μg)");
        // Carried: the offset to the platform stays, the box moves at V and stays on the deck.
        float offset = box.getX() - platform.getX();
        Scenes.run(world, 2f);
        assertEquals(offset, box.getX() - platform.getX(), 0.2f, "no more slip");
        assertEquals(speed, box.getVelocityX(), 0.01f * speed);
        assertEquals(-10f, box.getY(), 0.1f);
        assertEquals(p0 + speed * (ticks * dt + 2f), platform.getX(), 1e-3f * speed * 3f);
        assertEquals(10f, platform.getY(), "the box does not push the platform down");
        assertEquals(speed, platform.getVelocityX());
    }

    /** A wall moving at constant speed pushes a tower ahead of it, upright, at the wall's speed. */
    @Test
    void aMovingWallPushesATower() {
        World world = new World();
        world.setTicksPerSecond(60f);
        Body[] tower = Scenes.tower(world, 5, 20f);
        Body wall = kinematic(-40f, -100f, Shape.createRectangle(20f, 200f));
        wall.setVelocity(30f, 0f);
        world.addBody(wall);
        Scenes.run(world, 4f);
        assertEquals(-40f + 120f, wall.getX(), 1e-3f);
        assertEquals(30f, wall.getVelocityX(), "not slowed by the tower it pushes");
        for (int i = 0; i < tower.length; i++) {
            Body b = tower[i];
            float gap = b.getX() - 10f - (wall.getX() + 10f);
            assertTrue(gap > -0.5f, "box " + i + " overlaps the wall by " + -gap + " px");
            assertTrue(gap < 1f, "box " + i + " is left behind by " + gap + " px");
            assertEquals(30f, b.getVelocityX(), 1f, "box " + i + " moves with the wall");
            assertEquals(-10f - 20f * i, b.getY(), 0.5f, "box " + i + " stays in the tower");
            assertEquals(0f, b.getAngle(), 0.02f);
        }
    }

    /** An elevator lifts a tower: every box rides up at its speed, none sinks into another. */
    @Test
    void anElevatorLiftsAStack() {
        World world = new World();
        world.setTicksPerSecond(60f);
        Body lift = kinematic(0f, 10f, Shape.createRectangle(200f, 20f));
        world.addBody(lift);
        Shape box = Shape.createRectangle(20f, 20f);
        Body[] stack = new Body[5];
        for (int i = 0; i < stack.length; i++) {
            stack[i] = new Body(0f, -10f - 20f * i, box, true);
            world.addBody(stack[i]);
        }
        Scenes.run(world, 0.5f);
        lift.setVelocity(0f, -40f);
        Scenes.run(world, 3f);
        assertEquals(10f - 120f, lift.getY(), 1e-3f);
        for (int i = 0; i < stack.length; i++) {
            assertEquals(lift.getY() - 20f - 20f * i, stack[i].getY(), 0.5f, "box " + i);
            assertEquals(-40f, stack[i].getVelocityY(), 0.5f, "box " + i);
        }
    }

    /**
     * A frictionless ball touching a paddle that spins at ω about its centre is struck at radius r0
     * and slides out along it as a bead on a turning rod: r = r0·cosh(ωt) along the rod. It leaves
     * the paddle's end R with the velocity (ω√(R² − r0²) − ωd) along the rod and ωR across it (d,
     * the distance of its centre from the rod's axis), and flies on at that speed.
     */
    @Test
    void aSpinningPaddleFlingsABallAsABeadOnARod() {
        World world = new World();
        world.setGravity(0f, 0f);
        world.setTicksPerSecond(120f);
        Shape rod = Shape.createRectangle(200f, 10f);
        rod.setFriction(0f);
        Body paddle = kinematic(0f, 0f, rod);
        float omega = 2f;
        paddle.setAngularVelocity(omega);
        world.addBody(paddle);
        Shape bead = Shape.createCircle(5f);
        bead.setFriction(0f);
        float r0 = 60f;
        float d = 10f;
        Body ball = new Body(r0, d, bead, true);
        world.addBody(ball);
        float worst = 0f;
        boolean left = false;
        for (int t = 0; t < 240; t++) {
            world.tick();
            // The ball's centre in the paddle's frame, until it leaves the paddle's end: never
            // inside the rod.
            float along = paddle.toLocalX(ball.getX(), ball.getY());
            float across = paddle.toLocalY(ball.getX(), ball.getY());
            left |= along > 105f;
            if (!left) {
                worst = Math.max(worst, d - across);
            }
        }
        assertTrue(left, "the ball left the paddle");
        assertTrue(worst < 0.5f, "the ball sank " + worst + " px into the paddle");
        assertEquals(omega * 2f, paddle.getAngle(), 1e-3f);
        assertEquals(omega, paddle.getAngularVelocity());
        assertEquals(0f, paddle.getX());
        float r1 = 100f;
        double alongRod = omega * (Math.sqrt(r1 * r1 - r0 * r0) - d);
        double across = omega * r1;
        double expected = Math.hypot(alongRod, across);
        double speed = Math.hypot(ball.getVelocityX(), ball.getVelocityY());
        assertEquals(expected, speed, 0.05 * expected, "speed at which the ball leaves the paddle");
    }

    /** Not pushed by anything: a heavy fast box hits it and it keeps its velocity and path. */
    @Test
    void isNotPushedByADynamicBody() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body k = kinematic(0f, 0f, Shape.createRectangle(20f, 20f));
        k.setVelocity(10f, 0f);
        world.addBody(k);
        Shape heavy = Shape.createRectangle(20f, 20f);
        heavy.setMass(1e4f);
        Body ram = new Body(100f, 0f, heavy, true);
        ram.setVelocity(-200f, 0f);
        world.addBody(ram);
        Scenes.run(world, 2f);
        assertEquals(10f, k.getVelocityX());
        assertEquals(0f, k.getVelocityY());
        assertEquals(20f, k.getX(), 1e-3f);
        assertEquals(0f, k.getY());
        assertEquals(0f, k.getAngle());
        assertTrue(ram.getX() >= k.getX() + 19.5f, "the ram stopped at the kinematic box: " + ram.getX());
    }

    /** Static, kinematic and the landscape: passed through, and no contact made for them. */
    @Test
    void meetsNeitherStaticNorKinematicBodiesNorTheLandscape() {
        World world = new World();
        world.addBody(new Body(0f, 0f, Shape.createRectangle(40f, 40f), false));
        Landscape land = new Landscape();
        land.addSegment(-200f, 50f, 200f, 50f);
        world.setLandscape(land);
        Body a = kinematic(-100f, 0f, Shape.createRectangle(20f, 200f));
        a.setVelocity(100f, 0f);
        Body b = kinematic(100f, 0f, Shape.createCircle(15f));
        b.setVelocity(-100f, 10f);
        world.addBody(a);
        world.addBody(b);
        for (int t = 0; t < 40; t++) {
            world.tick();
            assertEquals(0, world.getContactCount(), "tick " + t);
        }
        assertEquals(100f, a.getX(), 1e-3f);
        assertEquals(-100f, b.getX(), 1e-3f);
        assertEquals(20f, b.getY(), 1e-3f);
    }

    /**
     * Inside the simulation area it moves and pushes; past its edge it freezes with its velocity
     * kept, as a dynamic body does, and goes on when the area reaches it again.
     */
    @Test
    void freezesOutsideTheSimulationAreaAndGoesOnWhenTheAreaReturns() {
        World world = new World();
        world.setGravity(0f, 0f);
        world.setSimulationArea(0f, -100f, 200f, 100f);
        Body k = kinematic(50f, 0f, Shape.createRectangle(20f, 20f));
        k.setVelocity(100f, 0f);
        world.addBody(k);
        Body ball = new Body(100f, 0f, Shape.createCircle(5f), true);
        world.addBody(ball);
        Body outside = kinematic(400f, 0f, Shape.createRectangle(20f, 20f));
        outside.setVelocity(-100f, 0f);
        world.addBody(outside);
        Scenes.run(world, 1f);
        assertEquals(400f, outside.getX(), "outside the area: frozen");
        assertFalse(outside.isSimulated());
        assertTrue(ball.getVelocityX() > 90f, "pushed inside the area: " + ball.getVelocityX());
        Scenes.run(world, 2f);
        // Frozen once its box no longer overlaps the area: within one tick's travel past the edge.
        float stop = k.getX();
        assertFalse(k.isSimulated());
        assertTrue(stop - 10f > 200f && stop - 10f <= 200f + 100f * world.getTimestep() + 1e-3f, "stopped at " + stop);
        assertEquals(100f, k.getVelocityX(), "keeps its velocity while frozen");
        world.tick();
        assertEquals(stop, k.getX());
        world.setSimulationArea(stop - 100f, -100f, stop + 100f, 100f);
        Scenes.run(world, 1f);
        assertEquals(stop + 100f, k.getX(), 1e-3f, "moves on with the area");
        assertTrue(k.isSimulated());
    }

    /** A fast ball does not tunnel through a thin kinematic wall, still or moving towards it. */
    @ParameterizedTest
    @CsvSource({"0", "-200", "200"})
    void aFastBallStopsAtAThinKinematicWall(float wallSpeed) {
        int crossed = 0;
        for (int k = 0; k < 32; k++) {
            World world = new World();
            world.setGravity(0f, 0f);
            world.setTicksPerSecond(20f);
            Body wall = kinematic(1f, 0f, Shape.createRectangle(2f, 400f));
            wall.setVelocity(wallSpeed, 0f);
            world.addBody(wall);
            float travel = 20000f / 20f;
            Body ball = new Body(-40f - travel * (3f + k / 32f), 0f, Shape.createCircle(2.5f), true);
            ball.setVelocity(20000f, 0f);
            world.addBody(ball);
            for (int t = 0; t < 10; t++) {
                world.tick();
            }
            if (ball.getX() > wall.getX()) {
                crossed++;
            }
        }
        assertEquals(0, crossed, "balls through a wall moving at " + wallSpeed + " px/s");
    }

    /**
     * The fast-body sweep covers kinematic bodies as it covers static ones: a rod spinning at up to
     * 100 rad/s does not pass through a thin kinematic plate, still or moving (without the sweep in
     * the plate's frame 12 to 32 of the 32 rods of each case went through).
     */
    @ParameterizedTest
    @CsvSource({"50, 20, 60, 0", "50, 60, 60, -30", "30, 20, 90, 30", "100, 20, 60, 0", "50, 20, 60, 30"})
    void aSpinningRodDoesNotPassThroughAKinematicPlate(float spin, int tps, float distance, float plateSpeed) {
        Body plate = kinematic(1f, 0f, Shape.createRectangle(2f, 600f));
        plate.setVelocity(plateSpeed, 0f);
        int crossed = BodyKindTest.spinningRodsThrough(spin, tps, distance, false, plate);
        assertEquals(0, crossed, "rod spinning at " + spin + " rad/s, plate at " + plateSpeed + " px/s");
    }

    /**
     * A fast thin kinematic wall sweeps a resting box ahead of it (the pair's speculative contact,
     * whose margin grows with the wall's speed, catches it); wall speeds of 10 to 100 px per tick.
     */
    @ParameterizedTest
    @CsvSource({"200", "800", "2000"})
    void aFastThinKinematicWallSweepsABoxAhead(float speed) {
        int passed = 0;
        for (int k = 0; k < 16; k++) {
            World world = new World();
            world.setGravity(0f, 0f);
            world.setTicksPerSecond(20f);
            Body box = new Body(100f, 0f, Shape.createRectangle(10f, 10f), true);
            world.addBody(box);
            Body wall = kinematic(-100f - k * speed / 20f / 16f, 0f, Shape.createRectangle(2f, 100f));
            wall.setVelocity(speed, 0f);
            world.addBody(wall);
            Scenes.run(world, 2f * 400f / speed + 0.5f);
            if (box.getX() < wall.getX()) {
                passed++;
            }
        }
        assertEquals(0, passed, "the wall at " + speed + " px/s went through the box");
    }

    @Test
    void velocityOnAStaticBodyIsAnErrorNamingTheCall() {
        Body wall = new Body(0f, 0f, Shape.createRectangle(10f, 10f), false);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> wall.setVelocity(5f, 0f));
        assertTrue(e.getMessage().startsWith("Body.setVelocity: "), e.getMessage());
        assertTrue(e.getMessage().contains("setKinematic(true)"), e.getMessage());
        e = assertThrows(IllegalStateException.class, () -> wall.setAngularVelocity(1f));
        assertTrue(e.getMessage().startsWith("Body.setAngularVelocity: "), e.getMessage());
        // Zero is the static body's velocity: accepted.
        wall.setVelocity(0f, 0f);
        wall.setAngularVelocity(0f);
        assertThrows(IllegalArgumentException.class, () -> wall.setVelocity(Float.NaN, 0f));
    }

    @Test
    void changingKindKeepsOrDropsTheVelocity() {
        World world = new World();
        Body b = new Body(0f, 0f, Shape.createRectangle(10f, 10f), true);
        world.addBody(b);
        b.setVelocity(30f, 0f);
        b.setKinematic(true);
        assertTrue(b.isKinematic() && !b.isDynamic());
        assertEquals(30f, b.getVelocityX(), "a dynamic body made kinematic keeps its velocity");
        world.tick();
        assertEquals(0f, b.getVelocityY(), "no gravity once kinematic");
        b.setDynamic(true);
        assertTrue(b.isDynamic() && !b.isKinematic());
        b.setKinematic(false);
        assertTrue(b.isDynamic(), "setKinematic(false) leaves a dynamic body dynamic");
        world.tick();
        assertTrue(b.getVelocityY() > 0f, "falls once dynamic");
        b.setKinematic(true);
        b.setKinematic(false);
        assertTrue(b.isStatic(), "setKinematic(false) makes a kinematic body static");
        assertEquals(0f, b.getVelocityX(), "made static: no velocity");
        Body copy = new Body(b);
        b.setKinematic(true);
        assertTrue(new Body(b).isKinematic());
        assertTrue(copy.isStatic());
        assertTrue(b.toString().contains("kinematic"), b.toString());
        b.setDynamic(false);
        assertTrue(b.isStatic(), "setDynamic(false) makes any body static");
    }

    /** Kinematic bodies pushing and spinning through a pile, with the sweep in their frame: no allocation. */
    @Test
    void ticksWithKinematicBodiesAllocateNothing() {
        World world = DeterminismTest.rain(6);
        Body paddle = kinematic(0f, -60f, Shape.createRectangle(160f, 6f));
        paddle.setAngularVelocity(3f);
        world.addBody(paddle);
        Body sweeper = kinematic(-250f, -30f, Shape.createRectangle(8f, 60f));
        sweeper.setVelocity(40f, 0f);
        world.addBody(sweeper);
        for (int t = 0; t < 300; t++) {
            world.tick();
        }
        AllocationWindows allocated = AllocationWindows.measure(5, () -> {
            for (int t = 0; t < 100; t++) {
                world.tick();
            }
        });
        assertEquals(0L, allocated.least(), "100 ticks with kinematic bodies, " + allocated);
    }

    @Test
    void isDeterministic() {
        assertEquals(run(), run());
    }

    private static long run() {
        World world = new World();
        world.setTicksPerSecond(60f);
        Scenes.pyramid(world, 6, 20f);
        Body sweeper = kinematic(-200f, -40f, Shape.createRectangle(10f, 80f));
        sweeper.setVelocity(60f, 0f);
        sweeper.setAngularVelocity(0.3f);
        world.addBody(sweeper);
        Scenes.run(world, 4f);
        long h = 1;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            h = 31 * h + Float.floatToIntBits(b.getX());
            h = 31 * h + Float.floatToIntBits(b.getY());
            h = 31 * h + Float.floatToIntBits(b.getAngle());
        }
        return h;
    }
}
