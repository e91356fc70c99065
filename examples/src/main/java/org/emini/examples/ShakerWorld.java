package org.emini.examples;

import org.emini.constraint.Joint;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;

/**
 * The manual's shaker ("Create an application"): a square box of four bars nailed together with
 * fixed joints, nine bouncy balls inside, and four springs from a static anchor that keep the box
 * floating in the middle of a phone-sized screen. Shaking accelerates the four bars; the balls
 * jump around inside. No graphics here, so it runs headless; {@link ShakerWindow} draws it.
 *
 * <p>The box does not come back upright, where the manual says its tilt wears off: upright is not
 * a stable rest state of these springs. The box's weight (4 × 10 × 100) stretches the upper spring
 * and compresses the lower one, both 40 px long at rest and attached 120 px from the box's centre.
 * Turning the box by θ, a spring under tension T at length L gives a torque of about
 * T·r·(1 + r/L)·θ, restoring when stretched and overturning when compressed, and the compressed
 * lower spring is the shorter: upright, with x and y at rest, the energy's curvature in θ is
 * −7.2·10⁵ (ShakerTiltTest). The box buckles to the side where the energy is least: at rest without
 * the balls it is tilted by ±0.1647 rad with its centre at (129.62, 188.91) or its mirror image,
 * which the engine reproduces to 0.001 rad and 0.1 px; the nine balls, lying to one side, add a
 * little (−0.171 after the headless run). The same holds on taller screens (±0.187 rad at 400 px
 * high): it is the layout, not the engine.
 */
public final class ShakerWorld {
    /** The screen the manual's example fills (a phone of its time), in px. */
    public static final int WIDTH = 240;
    /** The screen height, px. */
    public static final int HEIGHT = 320;
    /** The acceleration a held arrow key gives the box (px/s²). */
    public static final float SHAKE = 200f;

    private final World world = new World();
    private final Body[] bars = new Body[4];
    private final Body[] balls = new Body[9];
    private final Joint[] corners = new Joint[4];
    private final Spring[] springs = new Spring[4];

    /** Builds the world as the manual does, step by step. */
    public ShakerWorld() {
        world.setDampingLateral(0.005f);
        world.setDampingRotational(0.005f);
        final boolean isDynamic = true;
        final boolean fixedJoint = true;
        float width = WIDTH;
        float centerX = WIDTH / 2f;
        float centerY = HEIGHT / 2f;

        // Shapes: the bars ten times as heavy as a ball, bouncy balls, a small anchor.
        Shape boxRectangle = Shape.createRectangle(width, 10f);
        boxRectangle.setMass(10f);
        Shape ball = Shape.createCircle(10f);
        ball.setElasticity(0.8f);
        Shape smallBox = Shape.createRectangle(2f, 2f);

        // The bars; left and right turned by 90°.
        Body upper = new Body(centerX, centerY - width / 2f, boxRectangle, isDynamic);
        Body lower = new Body(centerX, centerY + width / 2f, boxRectangle, isDynamic);
        Body left = new Body(centerX - width / 2f, centerY, boxRectangle, isDynamic);
        left.setAngleDegrees(90f);
        Body right = new Body(centerX + width / 2f, centerY, boxRectangle, isDynamic);
        right.setAngleDegrees(90f);
        bars[0] = upper;
        bars[1] = lower;
        bars[2] = left;
        bars[3] = right;
        for (Body bar : bars) {
            world.addBody(bar);
        }

        // Fixed pin joints as nails at the corners; a shared layer lets the bars overlap there.
        corners[0] = new Joint(upper, left, -width / 2f, 0f, -width / 2f, 0f, fixedJoint);
        corners[1] = new Joint(upper, right, width / 2f, 0f, -width / 2f, 0f, fixedJoint);
        corners[2] = new Joint(lower, left, -width / 2f, 0f, width / 2f, 0f, fixedJoint);
        corners[3] = new Joint(lower, right, width / 2f, 0f, width / 2f, 0f, fixedJoint);
        for (Joint corner : corners) {
            world.addConstraint(corner);
            corner.setCollisionLayer(1);
        }

        // The balls, in a 3 × 3 grid inside the box.
        for (int i = 0; i < balls.length; i++) {
            balls[i] = new Body(centerX + 40f * (i % 3 - 1), centerY + 40f * (i / 3 - 1), ball, isDynamic);
            world.addBody(balls[i]);
        }

        // Springs from the anchor (at the origin, so its anchor points are screen points) to the
        // middle of each bar, at their length now.
        Body anchor = new Body(0f, 0f, smallBox, false);
        anchor.setInteracting(false);
        world.addBody(anchor);
        final float calculateDistance = Spring.MEASURE_DISTANCE;
        springs[0] = new Spring(anchor, upper, centerX, 0f, 0f, 0f, calculateDistance);
        springs[0].setCoefficient(120f);
        springs[1] = new Spring(anchor, lower, centerX, HEIGHT, 0f, 0f, calculateDistance);
        springs[1].setCoefficient(120f);
        springs[2] = new Spring(anchor, right, 0f, centerY, 0f, 0f, calculateDistance);
        springs[2].setCoefficient(100f);
        springs[3] = new Spring(anchor, left, width, centerY, 0f, 0f, calculateDistance);
        springs[3].setCoefficient(100f);
        for (Spring spring : springs) {
            world.addConstraint(spring);
        }
    }

    /**
     * Shakes the box for the next tick: accelerates all four bars (the joints would share the push
     * out if only one were pushed, but that is needless work for the solver).
     *
     * @param ax x acceleration (px/s²)
     * @param ay y acceleration (px/s²)
     */
    public void shake(float ax, float ay) {
        for (Body bar : bars) {
            bar.applyAcceleration(ax, ay);
        }
    }

    /** Advances one tick. */
    public void tick() {
        world.tick();
    }

    /**
     * The simulated world, for drawing.
     *
     * @return the world
     */
    public World getWorld() {
        return world;
    }

    /**
     * The balls.
     *
     * @return the nine balls
     */
    public Body[] getBalls() {
        return balls.clone();
    }

    /**
     * The widest gap between the two anchors of a corner joint.
     *
     * @return the gap (px)
     */
    public float widestCornerGap() {
        float worst = 0f;
        for (Joint j : corners) {
            float dx = j.getAnchorBX() - j.getAnchorAX();
            float dy = j.getAnchorBY() - j.getAnchorAY();
            worst = Math.max(worst, (float) Math.sqrt(dx * dx + dy * dy));
        }
        return worst;
    }

    /**
     * The largest error of a corner's angle: bars meet at 90°.
     *
     * @return the error (rad)
     */
    public float worstCornerAngleError() {
        float worst = 0f;
        for (Joint j : corners) {
            float error = j.getBodyB().getAngle() - j.getBodyA().getAngle() - j.getReferenceAngle();
            worst = Math.max(worst, Math.abs(error));
        }
        return worst;
    }

    /**
     * The box's centre: the mean of the bars' centres.
     *
     * @return {x, y} (px)
     */
    public float[] boxCentre() {
        float x = 0f;
        float y = 0f;
        for (Body bar : bars) {
            x += bar.getX() / bars.length;
            y += bar.getY() / bars.length;
        }
        return new float[] {x, y};
    }

    /**
     * The box's tilt: the upper bar's angle.
     *
     * @return the angle (rad)
     */
    public float boxAngle() {
        return bars[0].getAngle();
    }

    /**
     * How many balls are inside the box, their centres within its inner square.
     *
     * @return the count, 0 to 9
     */
    public int ballsInside() {
        float[] centre = boxCentre();
        float c = (float) Math.cos(boxAngle());
        float s = (float) Math.sin(boxAngle());
        float inner = WIDTH / 2f - 5f;
        int n = 0;
        for (Body b : balls) {
            float dx = b.getX() - centre[0];
            float dy = b.getY() - centre[1];
            float lx = c * dx + s * dy;
            float ly = -s * dx + c * dy;
            if (Math.abs(lx) < inner && Math.abs(ly) < inner) {
                n++;
            }
        }
        return n;
    }

    /**
     * The springs' tensions.
     *
     * @return upper, lower, right and left spring tensions (mass·px/s²)
     */
    public float[] springTensions() {
        float[] t = new float[springs.length];
        for (int i = 0; i < springs.length; i++) {
            t[i] = springs[i].getTension();
        }
        return t;
    }

    /**
     * The springs, for drawing.
     *
     * @return the four springs
     */
    public Spring[] getSprings() {
        return springs.clone();
    }

    /**
     * The kinetic energy of all bodies.
     *
     * @return the energy (mass·px²/s²)
     */
    public float kineticEnergy() {
        float e = 0f;
        for (int i = 0; i < world.getBodyCount(); i++) {
            e += world.getBody(i).getKineticEnergy();
        }
        return e;
    }

    /**
     * The shaking of the headless run: right, up, left, down in turn, ten ticks each, with rests
     * between; none after tick 300.
     *
     * @param tick the tick number from 0
     * @return {ax, ay} for that tick
     */
    public static float[] scriptedShake(int tick) {
        if (tick >= 300 || tick % 40 < 20 || tick % 40 >= 30) {
            return new float[] {0f, 0f};
        }
        switch ((tick / 40) % 4) {
            case 0:
                return new float[] {SHAKE, 0f};
            case 1:
                return new float[] {0f, -SHAKE};
            case 2:
                return new float[] {-SHAKE, 0f};
            default:
                return new float[] {0f, SHAKE};
        }
    }
}
