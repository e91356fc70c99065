package org.emini.examples.game;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.emini.dynamics.Body;
import org.emini.io.WorldWriter;
import org.emini.world.World;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The manual's jump'n'run, headless: the level comes from its world file, the sprite walks and jumps only when standing. */
class PhysicsGameTest {
    @BeforeAll
    static void headless() {
        System.setProperty("java.awt.headless", "true");
    }

    /** A game whose sprite has fallen from (100, 100) onto the floor. */
    private static PhysicsGame landed() {
        PhysicsGame game = new PhysicsGame();
        for (int t = 0; t < 40; t++) {
            game.tick();
        }
        assertTrue(game.getControl().isStanding(), "landed at y " + game.getSprite().getY());
        assertEquals(GameLevel.FLOOR - 15f, game.getSprite().getY(), 0.2f, "the sprite's feet on the floor");
        return game;
    }

    @Test
    void theLevelIsTheWorldFileTheLevelBuilderSaves() throws IOException {
        ByteArrayOutputStream saved = new ByteArrayOutputStream();
        WorldWriter writer = new WorldWriter();
        writer.write(GameLevel.build(), saved);
        assertEquals(0, writer.getNotSaved().size(), writer.getNotSaved().toString());
        byte[] resource;
        try (InputStream in = PhysicsGame.class.getResourceAsStream(GameLevel.RESOURCE)) {
            resource = in.readAllBytes();
        }
        assertArrayEquals(saved.toByteArray(), resource, "level.phy is stale: run GameLevel's main");
        World level = PhysicsGame.loadLevel();
        assertEquals(8, level.getBodyCount());
        assertEquals(2, level.getConstraintCount());
        assertEquals(8, level.getLandscape().getSegmentCount());
        // The crates' square is shape 0 of the file, the id the game draws them by.
        assertEquals(0, level.getBody(0).getShape().getId());
        assertEquals(level.getBody(0).getShape(), level.getShapeSet().getShape(0));
    }

    @Test
    void theSpriteWalksAtTheMotorsSpeedAndFrictionStopsItWhenReleased() {
        PhysicsGame game = landed();
        Body sprite = game.getSprite();
        float x0 = sprite.getX();
        // Left, where the floor is clear up to the wall.
        game.getControl().move(-1);
        for (int t = 0; t < 20; t++) {
            game.tick();
        }
        assertEquals(-PhysicsGame.SPEED_UNIT, sprite.getVelocityX(), 0.5f);
        assertTrue(x0 - sprite.getX() > 0.8f * PhysicsGame.SPEED_UNIT, "walked " + (x0 - sprite.getX()));
        assertEquals(0f, sprite.getAngle(), "the sprite does not rotate");
        game.getControl().move(0);
        for (int t = 0; t < 20; t++) {
            game.tick();
        }
        // Released, it slides: friction 0.98 × 0.25 under gravity 100 takes 24.5 px/s off each second.
        float mu = 0.98f * 0.25f;
        assertEquals(-(PhysicsGame.SPEED_UNIT - mu * 100f), sprite.getVelocityX(), 1.5f);
        for (int t = 0; t < 40; t++) {
            game.tick();
        }
        assertEquals(0f, sprite.getVelocityX(), 0.01f);
    }

    @Test
    void theSpriteJumpsOnlyWhileStanding() {
        PhysicsGame game = landed();
        Body sprite = game.getSprite();
        assertTrue(game.getControl().jump(PhysicsGame.JUMP));
        game.tick();
        float up = -PhysicsGame.JUMP * PhysicsGame.SPEED_UNIT;
        assertEquals(up + game.getWorld().getGravityY() * game.getWorld().getTimestep(), sprite.getVelocityY(), 0.5f);
        game.tick();
        assertFalse(game.getControl().isStanding());
        float vy = sprite.getVelocityY();
        assertFalse(game.getControl().jump(PhysicsGame.JUMP), "no jump in the air");
        game.tick();
        assertEquals(vy + game.getWorld().getGravityY() * game.getWorld().getTimestep(), sprite.getVelocityY(), 0.01f,
            "only gravity acted");
        assertEquals(1, game.getControl().getJumps());
        assertEquals(1, game.getControl().getRefusedJumps());
        // Back on the floor it may jump again.
        for (int t = 0; t < 60; t++) {
            game.tick();
        }
        assertTrue(game.getControl().jump(PhysicsGame.JUMP));
    }

    @Test
    void aWallIsNotGroundToJumpFrom() {
        PhysicsGame game = landed();
        Body sprite = game.getSprite();
        sprite.setPosition(GameLevel.LEFT_WALL + 10.5f, 100);
        sprite.setVelocity(0, 0);
        game.getControl().move(-1);
        for (int t = 0; t < 3; t++) {
            game.tick();
        }
        assertTrue(sprite.getY() < GameLevel.FLOOR - 40, "still in the air beside the wall");
        assertFalse(game.getControl().isStanding(), "pressed against the wall, not standing");
    }

    @Test
    void theHeadlessRunReachesTheGoalTheSameWayEveryTime() {
        String first = print(500);
        assertEquals(first, print(500));
        assertTrue(first.contains("goal reached at tick"), first);
        assertTrue(first.contains("  500 "), first);
    }

    private static String print(int ticks) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PhysicsGame.runHeadless(ticks, new PrintStream(bytes, true, StandardCharsets.UTF_8));
        return bytes.toString(StandardCharsets.UTF_8);
    }
}
