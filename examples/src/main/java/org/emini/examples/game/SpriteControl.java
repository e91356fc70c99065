package org.emini.examples.game;

import org.emini.constraint.Motor;
import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.dynamics.SolverStep;
import org.emini.world.World;

/**
 * The manual's sprite control: a linear motor that walks the sprite, with a jump on top. Walking
 * sets the motor's target speed along x (y stays free, so gravity and jumps act); a jump gives the
 * body a vertical velocity change in {@link #prepare}, the original's {@code precalculate}, and is
 * allowed only while the sprite stands on something: a contact point more than 12 px below its
 * centre (its feet are 15 px below it), as in the manual, on a surface no steeper than 60°.
 */
public class SpriteControl extends Motor {
    /** The largest force the sprite's legs push with (mass·px/s²): ten times its weight at mass 1. */
    public static final float LEG_FORCE = 1000f;
    /** How far below the centre a contact point must be to count as ground under the feet (px). */
    public static final float FEET = 12f;
    /** The least vertical part of a contact's normal that counts as ground: slopes up to 60°. */
    public static final float MIN_GROUND_NORMAL = 0.5f;

    private final World world;
    private float targetSpeed;
    private float jumpSpeed;
    private float spriteForce = 20f;
    private int jumps;
    private int refusedJumps;

    /**
     * Creates the control of a sprite.
     *
     * @param world the world the sprite is in
     * @param body the sprite
     */
    public SpriteControl(World world, Body body) {
        super(body, 0f, 0f, LEG_FORCE);
        this.world = world;
    }

    /**
     * Walks: sets the target speed to {@code target} times the sprite's speed unit.
     *
     * @param target −1 left, 0 stop driving, 1 right (any factor)
     */
    public void move(int target) {
        targetSpeed = target * spriteForce;
        setTargetVelocity(targetSpeed, 0f);
    }

    /**
     * Jumps with {@code factor} times the sprite's speed unit, upwards, if the sprite stands on
     * something; otherwise nothing happens.
     *
     * @param factor the jump's strength
     * @return whether the sprite jumps
     */
    public boolean jump(int factor) {
        if (!isStanding()) {
            refusedJumps++;
            return false;
        }
        jumpSpeed = -spriteForce * factor;
        jumps++;
        return true;
    }

    /**
     * Whether the sprite stands on something: one of its touching contacts, on a surface no steeper
     * than 60°, has a point under its feet (the manual's test, for bodies and the landscape alike).
     *
     * @return true when standing
     */
    public boolean isStanding() {
        Body body = getBody();
        for (Contact c : world.getContactsForBody(body)) {
            if (!c.isTouching()) {
                continue;
            }
            // Ground, not a wall: the manual's test alone lets the sprite climb a wall by jumping,
            // since the corners of its feet touch the wall too.
            if (Math.abs(c.getNormalY()) < MIN_GROUND_NORMAL) {
                continue;
            }
            for (int i = 0; i < c.getPointCount(); i++) {
                if (c.getPointY(i) - body.getY() > FEET) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Sets the speed unit of walking and jumping (the manual's default 20 px/s).
     *
     * @param force the unit (px/s)
     */
    public void setForce(float force) {
        spriteForce = force;
    }

    /**
     * The jumps made.
     *
     * @return the count
     */
    public int getJumps() {
        return jumps;
    }

    /**
     * The jumps refused because the sprite was in the air.
     *
     * @return the count
     */
    public int getRefusedJumps() {
        return refusedJumps;
    }

    @Override
    public void prepare(SolverStep step) {
        if (jumpSpeed != 0f) {
            // The manual's applyAcceleration(jump, ONE_FX): a velocity change of jumpSpeed now.
            getBody().applyAcceleration(0f, jumpSpeed, 1f);
            jumpSpeed = 0f;
        }
        super.prepare(step);
    }
}
