package org.example;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;

public class Main {
    public static void main(String[] args) {
        World world = new World();                 // 20 ticks/s, 10 iterations, gravity (0, 100) px/s²
        world.addBody(new Body(0, 10, Shape.createRectangle(400, 20), false));   // static ground

        Shape box = Shape.createRectangle(20, 20); // mass 1, friction 0.25, elasticity 0 (the defaults)
        box.setFriction(0.5f);
        Body body = new Body(0, -100, box, true);  // dynamic; y points down the screen
        world.addBody(body);

        for (int i = 0; i < 60; i++) {
            world.tick();                          // one timestep (1/20 s)
        }
        System.out.println(body.getX() + ", " + body.getY() + " angle " + body.getAngle());
    }
}
