package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** Fixed joints make bodies act as one: no relative motion beyond half a pixel under load. */
class FixedJointTest {
    /** Relative drift of a fixed joint: the anchors' gap plus the angle error at the farther rim. */
    private static double drift(Joint j) {
        double angle = j.getBodyB().getAngle() - j.getBodyA().getAngle() - j.getReferenceAngle();
        double rim = Math.max(j.getBodyA().getShape().getBoundingRadius(), j.getBodyB().getShape().getBoundingRadius());
        return Rigs.gap(j) + Math.abs(angle) * rim;
    }

    @Test
    void cantileverOfTwoBeamsHoldsALoadWithoutRelativeDrift() {
        // A wall, two 40 px beams welded end to end, and a load four times a beam's mass at the tip.
        World world = Rigs.world(20f, 10);
        Body wall = new Body(-5f, 0f, Shape.createRectangle(10f, 100f), false);
        world.addBody(wall);
        Shape beam = Shape.createRectangle(40f, 10f);
        Body inner = new Body(20f, 0f, beam, true);
        Body outer = new Body(60f, 0f, beam, true);
        Shape weight = Shape.createRectangle(10f, 10f);
        weight.setMass(4f);
        Body load = new Body(85f, 0f, weight, true);
        world.addBody(inner);
        world.addBody(outer);
        world.addBody(load);
        Joint root = Joint.atWorldPoint(wall, inner, 0f, 0f, true);
        Joint middle = Joint.atWorldPoint(inner, outer, 40f, 0f, true);
        Joint tip = Joint.atWorldPoint(outer, load, 80f, 0f, true);
        root.setCollisionLayer(0);
        middle.setCollisionLayer(1);
        tip.setCollisionLayer(2);
        world.addConstraint(root);
        world.addConstraint(middle);
        world.addConstraint(tip);

        double worst = 0.0;
        for (int t = 0; t < 200; t++) {
            world.tick();
            worst = Math.max(worst, drift(middle));
        }
        System.out.printf("welded cantilever, load 4x: beam-to-beam drift ≤ %.4f px, tip sag %.3f px%n", worst, load.getY());
        assertTrue(worst < 0.5, "relative drift " + worst);
        // Statics: the wall joint carries the whole weight and its moment Σ m·g·x.
        float g = world.getGravityY();
        assertEquals((1f + 1f + 4f) * g, root.getForce(), 0.01 * 6f * g);
        float moment = g * (1f * 20f + 1f * 60f + 4f * 85f);
        assertEquals(moment, root.getTorque(), 0.01 * moment);
        assertEquals(4f * g, tip.getForce(), 0.01 * 4f * g);
    }

    @Test
    void twoBodiesWeldedIntoAnLLandAndRestAsOneBody() {
        World world = Rigs.world(20f, 10);
        world.addBody(new Body(0f, 10f, Shape.createRectangle(400f, 20f), false));
        Body foot = new Body(0f, -50f, Shape.createRectangle(60f, 10f), true);
        Body leg = new Body(-25f, -80f, Shape.createRectangle(10f, 50f), true);
        leg.setAngle(0.3f);
        foot.setAngle(0.3f);
        leg.setPosition(foot.toWorldX(-25f, -30f), foot.toWorldY(-25f, -30f));
        world.addBody(foot);
        world.addBody(leg);
        Joint weld = Joint.atWorldPoint(foot, leg, foot.toWorldX(-25f, -5f), foot.toWorldY(-25f, -5f), true);
        weld.setCollisionLayer(3);
        world.addConstraint(weld);

        double worst = 0.0;
        for (int t = 0; t < 200; t++) {
            world.tick();
            worst = Math.max(worst, drift(weld));
        }
        System.out.printf("welded L dropped on the ground: drift ≤ %.4f px%n", worst);
        // An impact, not a steady load: the ground stops the foot in the tick's last relax pass,
        // after the weld's, and the fast-body pass puts the foot alone back to its time of impact,
        // so the weld catches up one tick later (measured 0.49 px).
        assertTrue(worst < 1.0, "relative drift " + worst);
        // It came to rest on the ground.
        assertTrue(Math.abs(foot.getVelocityY()) < 1f && Math.abs(leg.getAngularVelocity()) < 0.05f);
        assertEquals(foot.getAngle() + weld.getReferenceAngle(), leg.getAngle(), 0.01);
    }

    @Test
    void bodyWeldedToAStaticBodyHoldsItsAngleAgainstAMotor() {
        World world = Rigs.world(20f, 10);
        world.setGravity(0f, 0f);
        Body wall = Rigs.anchor(world, 0f, 0f);
        Body arm = new Body(30f, 0f, Shape.createRectangle(40f, 6f), true);
        world.addBody(arm);
        Joint weld = Joint.atWorldPoint(wall, arm, 10f, 0f, true);
        world.addConstraint(weld);
        float torque = 5000f;
        world.addConstraint(new Motor(arm, 10f, torque));
        Rigs.run(world, 100);
        System.out.printf("weld against a %.0f torque motor: angle %.6f rad, gap %.5f px%n", torque, arm.getAngle(), Rigs.gap(weld));
        assertEquals(0.0, arm.getAngle(), 0.005);
        assertTrue(Rigs.gap(weld) < 0.5);
        // The weld's torque balances the motor's.
        assertEquals(torque, weld.getTorque(), 0.01 * torque);
    }
}
