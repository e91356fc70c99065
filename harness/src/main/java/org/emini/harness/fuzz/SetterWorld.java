package org.emini.harness.fuzz;

import java.util.HashMap;
import java.util.Map;
import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.world.World;
import org.emini.particle.ParticleEmitter;
import org.emini.shape.Shape;

/**
 * The base world every setter program starts from: a ground, a box and a ball joined by a joint and a
 * spring, a motor on the ball, an emitter on the box and a landscape segment, so that every kind of
 * object a setter reaches is in a world that ticks. Written out in each reproduction file.
 */
final class SetterWorld {
    /** The same world as Java, for the reproduction files. */
    static final String JAVA = String.join("\n",
            "World world = new World();",
            "Body ground = new Body(0, 10, Shape.createRectangle(400, 20), false);",
            "Shape boxShape = Shape.createRectangle(20, 20);",
            "Body box = new Body(0, -20, boxShape, true);",
            "Shape ballShape = Shape.createCircle(10);",
            "Body ball = new Body(30, -50, ballShape, true);",
            "world.addBody(ground); world.addBody(box); world.addBody(ball);",
            "Joint joint = Joint.atWorldPoint(box, ball, 15, -35, false); world.addConstraint(joint);",
            "Spring spring = new Spring(ground, ball, 0, 0, 0, 0); spring.setCoefficient(50); world.addConstraint(spring);",
            "Motor motor = new Motor(ball, 2f, 1000f); world.addConstraint(motor);",
            "ParticleEmitter emitter = new ParticleEmitter(50, box); world.addParticleEmitter(emitter);",
            "Landscape landscape = world.getLandscape(); landscape.addSegment(-500, 50, 500, 50);",
            "SolverSettings solver = world.getSolverSettings();");

    final World world = new World();
    final Map<String, Object> objects = new HashMap<>();

    SetterWorld() {
        Body ground = new Body(0, 10, Shape.createRectangle(400, 20), false);
        Shape boxShape = Shape.createRectangle(20, 20);
        Body box = new Body(0, -20, boxShape, true);
        Shape ballShape = Shape.createCircle(10);
        Body ball = new Body(30, -50, ballShape, true);
        world.addBody(ground);
        world.addBody(box);
        world.addBody(ball);
        Joint joint = Joint.atWorldPoint(box, ball, 15, -35, false);
        world.addConstraint(joint);
        Spring spring = new Spring(ground, ball, 0, 0, 0, 0);
        spring.setCoefficient(50);
        world.addConstraint(spring);
        Motor motor = new Motor(ball, 2f, 1000f);
        world.addConstraint(motor);
        ParticleEmitter emitter = new ParticleEmitter(50, box);
        world.addParticleEmitter(emitter);
        world.getLandscape().addSegment(-500, 50, 500, 50);
        objects.put("world", world);
        objects.put("ground", ground);
        objects.put("box", box);
        objects.put("ball", ball);
        objects.put("boxShape", boxShape);
        objects.put("ballShape", ballShape);
        objects.put("joint", joint);
        objects.put("spring", spring);
        objects.put("motor", motor);
        objects.put("emitter", emitter);
        objects.put("landscape", world.getLandscape());
        objects.put("solver", world.getSolverSettings());
    }

    /** A body argument: one of the world's, or a fresh one outside it. */
    Body body(String name) {
        return name.equals("fresh") ? new Body(100, -100, Shape.createRectangle(5, 5), true) : (Body) objects.get(name);
    }

    /** A shape argument: always a fresh one (shapes are shared by reference). */
    static Shape shape(String name) {
        return name.equals("circle") ? Shape.createCircle(4) : Shape.createRectangle(8, 6);
    }

    /** Puts what a constructor or factory made into the world, as a program using it would. */
    void add(Object made) {
        if (made instanceof Body b) {
            world.addBody(b);
        } else if (made instanceof Shape s) {
            world.addBody(new Body(-60, -80, s, true));
        } else if (made instanceof Constraint c) {
            world.addConstraint(c);
        } else if (made instanceof ParticleEmitter e) {
            world.addParticleEmitter(e);
        }
    }
}
