package org.emini.examples.game;

import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import org.emini.constraint.Joint;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.io.WorldWriter;
import org.emini.shape.Shape;
import org.emini.world.World;

/**
 * The game's level as the manual's World Designer session builds it: a landscape drawn on a grid
 * (floor, walls, a ramp up to a ledge and down again), a few crates of one square shape (shape id 0,
 * the id the game draws them by), a pendulum on a solid spring (no coefficient) from a static anchor
 * under the ceiling, and a see-saw. {@link #main} saves it as the world file the game loads,
 * {@code level.phy} next to this class in the resources: the file is made by the engine's
 * {@link WorldWriter} in place of the designer.
 */
public final class GameLevel {
    /** Where the floor is (px, y down). */
    public static final float FLOOR = 200f;
    /** The goal: the sprite has won once its x is beyond this (px). */
    public static final float GOAL_X = 1100f;
    /** The level's left wall (px). */
    public static final float LEFT_WALL = -100f;
    /** The level's right wall (px). */
    public static final float RIGHT_WALL = 1200f;
    /** The resource the game loads, next to this class. */
    public static final String RESOURCE = "level.phy";

    private GameLevel() {
    }

    /**
     * Builds the level.
     *
     * @return the world, as a designer would have saved it
     */
    public static World build() {
        World world = new World();
        Landscape land = world.getLandscape();
        // The landscape tool: floor, ramp up, ledge, ramp down, floor; walls and ceiling.
        land.addSegment(LEFT_WALL, FLOOR, 300, FLOOR);
        land.addSegment(300, FLOOR, 420, FLOOR - 30);
        land.addSegment(420, FLOOR - 30, 560, FLOOR - 30);
        land.addSegment(560, FLOOR - 30, 680, FLOOR);
        land.addSegment(680, FLOOR, RIGHT_WALL, FLOOR);
        land.addSegment(LEFT_WALL, FLOOR, LEFT_WALL, -200);
        land.addSegment(RIGHT_WALL, -200, RIGHT_WALL, FLOOR);
        land.addSegment(LEFT_WALL, -200, RIGHT_WALL, -200);

        // The shape panel: a square, id 0.
        Shape crate = Shape.createRectangle(24, 24);
        crate.setFrictionPercent(50);
        world.getShapeSet().register(crate);
        Shape plank = Shape.createRectangle(160, 8);
        plank.setMass(3);
        world.getShapeSet().register(plank);
        Shape bob = Shape.createCircle(12);
        bob.setMass(4);
        world.getShapeSet().register(bob);
        Shape anchorShape = Shape.createRectangle(4, 4);
        world.getShapeSet().register(anchorShape);

        // The new-body tool: crates, one on the ledge.
        world.addBody(new Body(220, FLOOR - 12, crate, true));
        world.addBody(new Body(250, FLOOR - 12, crate, true));
        world.addBody(new Body(235, FLOOR - 36, crate, true));
        world.addBody(new Body(500, FLOOR - 42, crate, true));

        // The pendulum: an anchor made static, a bob, and a spring without a coefficient (solid).
        Body anchor = new Body(800, -60, anchorShape, false);
        anchor.setInteracting(false);
        world.addBody(anchor);
        Body pendulum = new Body(860, 60, bob, true);
        world.addBody(pendulum);
        world.addConstraint(new Spring(anchor, pendulum, 0, 0, 0, 0, Spring.MEASURE_DISTANCE));

        // The see-saw: a plank pinned to a static pivot.
        Body pivot = new Body(980, FLOOR - 10, Shape.createRectangle(8, 20), false);
        world.addBody(pivot);
        Body board = new Body(980, FLOOR - 24, plank, true);
        world.addBody(board);
        Joint pin = new Joint(pivot, board, 0, -14, 0, 0, false);
        pin.setCollisionLayer(1);
        world.addConstraint(pin);
        return world;
    }

    /**
     * Saves the level as a world file (what the designer's "save" does).
     *
     * @param args the file to write, by default the resource in examples/src/main/resources
     * @throws IOException when the file cannot be written
     */
    public static void main(String[] args) throws IOException {
        String path = args.length > 0 ? args[0] : "examples/src/main/resources/org/emini/examples/game/" + RESOURCE;
        WorldWriter writer = new WorldWriter();
        try (OutputStream out = new FileOutputStream(path)) {
            writer.write(build(), out);
        }
        System.out.println("wrote " + path + (writer.getNotSaved().isEmpty() ? "" : "; not saved: " + writer.getNotSaved()));
    }
}
