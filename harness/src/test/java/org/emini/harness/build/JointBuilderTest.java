package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.emini.constraint.DistanceJoint;
import org.emini.constraint.Joint;
import org.emini.constraint.MotorJoint;
import org.emini.constraint.MouseJoint;
import org.emini.constraint.PrismaticJoint;
import org.emini.constraint.RevoluteJoint;
import org.emini.constraint.WheelJoint;
import org.emini.dynamics.Constraint;
import org.emini.harness.Scenes;
import org.emini.harness.convert.ScenarioToWorld;
import org.emini.harness.load.Problem;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/** Every joint type of the {@code joints} section, built with its settings; bad values refused where written. */
class JointBuilderTest {
    private static final String BODIES = "bodies: [{name: a, shape: {type: rectangle, width: 20, height: 20}, position: [0, 0], static: true},"
        + " {name: b, shape: {type: circle, radius: 5}, position: [30, 0]}]";

    private static Constraint only(String joint) throws Exception {
        World w = WorldBuilder.build(Scenes.valid("j.yaml", BODIES, "joints:", "  - " + joint,
            "run: {duration: 1}")).world();
        assertEquals(1, w.getConstraintCount());
        return w.getConstraint(0);
    }

    private static Problem refused(String joint) {
        return Scenes.onlyProblem(Scenes.load("j.yaml", BODIES, "joints:", "  - " + joint, "run: {duration: 1}"));
    }

    @Test
    void aJointWithoutATypeIsThePinJoint() throws Exception {
        Joint j = assertInstanceOf(Joint.class, only("{bodyA: a, bodyB: b, at: [0, 0]}"));
        assertFalse(j.isFixed());
    }

    @Test
    void aFixedPinJointTakesAWeldStiffnessAndABreakForce() throws Exception {
        Joint j = assertInstanceOf(Joint.class, only("{type: pin, bodyA: a, bodyB: b, at: [0, 0], fixed: true,"
            + " stiffness: {linearHertz: 5, angularHertz: 2, dampingRatio: 0.7}, breakForce: 1000}"));
        assertTrue(j.isFixed());
        assertEquals(5f, j.getLinearHertz());
        assertEquals(2f, j.getAngularHertz());
        assertEquals(0.7f, j.getDampingRatio());
        assertEquals(1000f, j.getBreakForce());
    }

    @Test
    void revoluteLimitsMotorAndSpring() throws Exception {
        RevoluteJoint r = assertInstanceOf(RevoluteJoint.class, only("{type: revolute, bodyA: a, bodyB: b, at: [10, 0],"
            + " limits: [-0.5, 1], motor: {speed: 2, maxTorque: 300}, spring: {hertz: 3, dampingRatio: 0.4}}"));
        assertTrue(r.isLimitEnabled());
        assertEquals(-0.5f, r.getLowerLimit());
        assertEquals(1f, r.getUpperLimit());
        assertEquals(2f, r.getMotorSpeed());
        assertEquals(300f, r.getMaxMotorTorque());
        assertEquals(3f, r.getSpringHertz());
        assertEquals(0.4f, r.getSpringDampingRatio());
        assertEquals(10f, r.getAnchorAX(), 1e-4f);
    }

    @Test
    void prismaticAxisIsAWorldDirectionAndLimitsAreLengths() throws Exception {
        PrismaticJoint p = assertInstanceOf(PrismaticJoint.class, only("{type: prismatic, bodyA: a, bodyB: b,"
            + " at: [30, 0], axis: [0, -2], limits: [0, 100], motor: {speed: 40, maxForce: 5000}}"));
        assertEquals(0f, p.getLocalAxisX(), 1e-6f);
        assertEquals(-1f, p.getLocalAxisY(), 1e-6f);
        assertEquals(0f, p.getLowerLimit());
        assertEquals(100f, p.getUpperLimit());
        assertTrue(p.isMotorEnabled());
    }

    @Test
    void wheelSpringAndMotor() throws Exception {
        WheelJoint w = assertInstanceOf(WheelJoint.class, only("{type: wheel, bodyA: a, bodyB: b, anchorA: [30, 0],"
            + " axis: [0, 1], spring: {hertz: 4, dampingRatio: 0.7}, motor: {speed: 10, maxTorque: 4e5}}"));
        assertEquals(4f, w.getSpringHertz());
        assertEquals(0.7f, w.getSpringDampingRatio());
        assertEquals(10f, w.getMotorSpeed());
    }

    @Test
    void distanceRangeAndRope() throws Exception {
        DistanceJoint d = assertInstanceOf(DistanceJoint.class, only("{type: distance, bodyA: a, bodyB: b,"
            + " length: 25, range: [20, 40]}"));
        assertEquals(25f, d.getLength());
        assertEquals(20f, d.getMinLength());
        assertEquals(40f, d.getMaxLength());
        assertFalse(d.isRigid());
        DistanceJoint rigid = assertInstanceOf(DistanceJoint.class, only("{type: distance, bodyA: a, bodyB: b}"));
        assertTrue(rigid.isRigid());
        assertEquals(30f, rigid.getLength(), 1e-4f);
        DistanceJoint rope = assertInstanceOf(DistanceJoint.class, only("{type: rope, bodyA: a, bodyB: b, length: 50}"));
        assertEquals(0f, rope.getMinLength());
        assertEquals(50f, rope.getMaxLength());
    }

    @Test
    void motorJointOffsetsAndCaps() throws Exception {
        MotorJoint m = assertInstanceOf(MotorJoint.class, only("{type: motorJoint, bodyA: a, bodyB: b,"
            + " offset: [50, 0], angularOffset: 1, maxForce: 2000, maxTorque: 9000}"));
        assertEquals(50f, m.getLinearOffsetX());
        assertEquals(1f, m.getAngularOffset());
        assertEquals(2000f, m.getMaxForce());
        assertEquals(9000f, m.getMaxTorque());
    }

    @Test
    void mouseGrabsAPointAndPullsItToTheTarget() throws Exception {
        MouseJoint m = assertInstanceOf(MouseJoint.class, only("{type: mouse, body: b, at: [30, 0], target: [60, -10],"
            + " maxForce: 500, spring: {hertz: 2, dampingRatio: 1}}"));
        assertEquals(60f, m.getTargetX());
        assertEquals(-10f, m.getTargetY());
        assertEquals(500f, m.getMaxForce());
        assertEquals(2f, m.getSpringHertz());
    }

    @Test
    void engineRefusalsAreReportedAtTheirKey() {
        Problem limits = refused("{type: revolute, bodyA: a, bodyB: b, limits: [1, -1]}");
        assertEquals("$.joints[0].limits", limits.path());
        assertTrue(limits.message().startsWith("the engine refuses it: "), limits.message());
        assertEquals("$.joints[0].range", refused("{type: distance, bodyA: a, bodyB: b, range: [40, 20]}").path());
        assertEquals("$.joints[0]", refused("{type: wheel, bodyA: a, bodyB: b, axis: [0, 0]}").path());
        assertEquals("$.joints[0].stiffness",
            refused("{bodyA: a, bodyB: b, stiffness: {linearHertz: 5}}").path(), "a loose pin has no stiffness");
    }

    @Test
    void theSchemaRefusesAKeyOfAnotherTypeAndAMissingAxis() {
        assertTrue(refused("{type: rope, bodyA: a, bodyB: b, length: 5, motor: {speed: 1, maxTorque: 1}}")
            .path().startsWith("$.joints[0]"));
        assertTrue(refused("{type: prismatic, bodyA: a, bodyB: b}").message().contains("axis"));
        List<Problem> motor = Scenes.load("j.yaml", BODIES, "joints:",
            "  - {type: prismatic, bodyA: a, bodyB: b, axis: [1, 0], motor: {speed: 1, maxTorque: 1}}",
            "run: {duration: 1}").problems();
        assertTrue(motor.stream().anyMatch(q -> q.path().equals("$.joints[0].motor.maxTorque")), motor::toString);
    }

    @Test
    void aJoinedPairDoesNotCollideButAMouseJointHasNoPair() throws Exception {
        World w = WorldBuilder.build(Scenes.valid("j.yaml", BODIES, "joints:",
            "  - {type: wheel, bodyA: a, bodyB: b, axis: [0, 1]}",
            "  - {type: mouse, body: b, at: [30, 0]}", "run: {duration: 1}")).world();
        assertEquals(2, w.getConstraintCount());
        assertTrue(w.isCollisionDisabled(w.getConstraint(0).getBody(0), w.getConstraint(0).getBody(1)));
    }

    @Test
    void worldFilesSkipTheGameJointsSayingWhy() {
        ScenarioToWorld.Result r = ScenarioToWorld.convert(Scenes.valid("j.yaml", BODIES, "joints:",
            "  - {bodyA: a, bodyB: b, at: [0, 0]}",
            "  - {type: revolute, bodyA: a, bodyB: b, at: [0, 0]}",
            "  - {bodyA: a, bodyB: b, at: [0, 0], fixed: true, stiffness: {angularHertz: 2}}", "run: {duration: 1}"));
        assertEquals(2, r.world().getConstraints().size());
        assertTrue(r.approximated().stream().anyMatch(s -> s.startsWith("joint 1: stiffness")), r.approximated()::toString);
        List<String> skipped = new ArrayList<>(r.notConverted());
        assertTrue(skipped.stream().anyMatch(s -> s.startsWith("joint 1: type revolute")), skipped::toString);
    }
}
