package org.emini.examples.game;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.util.Locale;
import org.emini.dynamics.Body;
import org.emini.io.BuildResult;
import org.emini.io.WorldBuilder;
import org.emini.shape.Shape;
import org.emini.world.World;

/**
 * The manual's jump'n'run ("Physics Game"): a level loaded from a world file, a sprite that walks
 * and jumps through it with a {@link SpriteControl}, drawn by a {@link GraphicsWorld}.
 * {@code PhysicsGame} opens a window (arrow keys: walk, up: jump); {@code PhysicsGame --headless N}
 * plays N ticks with scripted keys and prints the state.
 */
public final class PhysicsGame {
    /** The walking and jumping speed unit of this game (px/s); the manual's default is 20. */
    public static final float SPEED_UNIT = 60f;
    /** The jump's strength in speed units: 120 px/s up, about 70 px high under gravity 100. */
    public static final int JUMP = 2;

    private final GraphicsWorld world;
    private final Body sprite;
    private final SpriteControl control;

    /** Loads the level and puts the sprite into it, as the manual's createWorld does. */
    public PhysicsGame() {
        Shape spriteRectangle = Shape.createRectangle(20, 30);
        spriteRectangle.setFrictionPercent(98);
        spriteRectangle.setElasticityPercent(0);
        world = new GraphicsWorld(loadLevel());
        sprite = new Body(100, 100, spriteRectangle, true);
        sprite.setRotatable(false);
        world.addBody(sprite);
        control = new SpriteControl(world, sprite);
        control.setForce(SPEED_UNIT);
        world.addConstraint(control);
    }

    /**
     * Loads the level's world file from the class path.
     *
     * @return the loaded world
     * @throws IllegalStateException when the file holds records the engine cannot build
     */
    public static World loadLevel() {
        try (InputStream in = PhysicsGame.class.getResourceAsStream(GameLevel.RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("PhysicsGame: the level " + GameLevel.RESOURCE + " is not on the class path");
            }
            BuildResult loaded = WorldBuilder.loadWorld(in, null);
            if (!loaded.getUnsupported().isEmpty()) {
                throw new IllegalStateException("PhysicsGame: the level has records the engine cannot build: " + loaded.getUnsupported());
            }
            return loaded.getWorld();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * The world being played.
     *
     * @return the world
     */
    public GraphicsWorld getWorld() {
        return world;
    }

    /**
     * The player's body.
     *
     * @return the sprite
     */
    public Body getSprite() {
        return sprite;
    }

    /**
     * The player's control.
     *
     * @return the sprite control
     */
    public SpriteControl getControl() {
        return control;
    }

    /**
     * Whether the sprite has reached the goal area.
     *
     * @return true once it is past {@link GameLevel#GOAL_X}
     */
    public boolean isWon() {
        return sprite.getX() > GameLevel.GOAL_X;
    }

    /** Advances one tick. */
    public void tick() {
        world.tick();
    }

    /**
     * Runs the game.
     *
     * @param args none for the window, or {@code --headless N}
     */
    public static void main(String[] args) {
        if (args.length >= 1 && args[0].equals("--headless")) {
            int ticks = args.length > 1 ? Integer.parseInt(args[1]) : 600;
            runHeadless(ticks, System.out);
        } else if (args.length == 0) {
            GameWindow.open(new PhysicsGame());
        } else {
            System.err.println("usage: PhysicsGame [--headless TICKS]");
            System.exit(2);
        }
    }

    /**
     * Plays without a window: walks right from tick 20 until the goal is reached, presses jump at
     * tick 10 (in the air: refused) and every 40 ticks from tick 30; prints the state every 50
     * ticks and at the end.
     *
     * @param ticks how many ticks to play
     * @param out where to print
     * @return the game after the run
     */
    public static PhysicsGame runHeadless(int ticks, PrintStream out) {
        PhysicsGame game = new PhysicsGame();
        out.println("physics game: level " + GameLevel.RESOURCE + " (" + game.world.getBodyCount() + " bodies, "
            + game.world.getLandscape().getSegmentCount() + " landscape segments), goal at x > " + GameLevel.GOAL_X);
        out.println(" tick        x        y       vx       vy  standing  jumps  refused");
        int wonAt = -1;
        for (int t = 0; t < ticks; t++) {
            if (t == 20) {
                game.control.move(1);
            }
            if (t == 10 || (t >= 30 && t % 40 == 30)) {
                game.control.jump(JUMP);
            }
            game.tick();
            if (wonAt < 0 && game.isWon()) {
                wonAt = t + 1;
                game.control.move(0);
            }
            if ((t + 1) % 50 == 0 || t == ticks - 1) {
                Body s = game.sprite;
                out.println(String.format(Locale.ROOT, "%5d %8.2f %8.2f %8.2f %8.2f  %-8s %6d %8d", t + 1, s.getX(), s.getY(),
                    s.getVelocityX(), s.getVelocityY(), game.control.isStanding(), game.control.getJumps(),
                    game.control.getRefusedJumps()));
            }
        }
        out.println(wonAt >= 0 ? "goal reached at tick " + wonAt : "goal not reached");
        return game;
    }
}
