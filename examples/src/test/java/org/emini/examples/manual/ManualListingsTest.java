package org.emini.examples.manual;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.examples.ShakerWorld;
import org.junit.jupiter.api.Test;

/** The manual's listings, ported mechanically (PORTING.md), run: they build and behave as the text says. */
class ManualListingsTest {
    @Test
    void theShakerListingBuildsTheExamplesBoxAndDrawsIt() {
        ShakerListing.Shaker shaker = new ShakerListing.Shaker(ShakerWorld.WIDTH, ShakerWorld.HEIGHT);
        ShakerListing.GraphicsWorld world = shaker.shakerWorld;
        assertEquals(5, world.getBodyCount());
        assertEquals(8, world.getConstraintCount());
        // The listing's box and springs are the example's: the same bars, the same rest lengths.
        ShakerWorld example = new ShakerWorld();
        for (int i = 0; i < 4; i++) {
            assertEquals(example.getWorld().getBody(i).getX(), world.getBody(i).getX());
            assertEquals(example.getWorld().getBody(i).getY(), world.getBody(i).getY());
            assertEquals(example.getWorld().getBody(i).getAngle(), world.getBody(i).getAngle());
        }
        Graphics g = new Graphics(240, 320);
        world.draw(g);
        assertEquals(4 * 4 + 4 * 1 + 4, g.count("line"), "four bars of four edges, the anchor's four, four springs");
        // A key press shakes the box: the bars gain 64 px/s² × one tick of velocity at once.
        shaker.simulationCanvas.keyPressed(ShakerListing.SimulationCanvas.RIGHT);
        for (int i = 0; i < 4; i++) {
            assertEquals(64f * world.getTimestep(), world.getBody(i).getVelocityX(), 1e-5f);
        }
        for (int t = 0; t < 400; t++) {
            world.tick();
        }
        float gap = 0f;
        for (int i = 0; i < 4; i++) {
            gap = Math.max(gap, Math.abs(world.getBody(i).getX() - ShakerWorld.WIDTH / 2f));
        }
        assertTrue(gap < 200f, "the box stays in the middle of the screen, " + gap);
    }

    @Test
    void theGameListingLoadsTheWorldWalksAndJumpsOnlyFromTheGround() throws Exception {
        GameListing.Game game = new GameListing.Game();
        game.createWorld();
        GameListing.GraphicsShapeSet images = (GameListing.GraphicsShapeSet) game.world.getShapeSet();
        Object crateImage = new Object();
        images.registerImage(crateImage, 0);
        assertSame(crateImage, images.getImage(game.world.getBody(0)), "the crates' shape is id 0 of the file");
        assertNull(images.getImage(game.sprite), "no image for the sprite: drawn by the canvas");
        Graphics g = new Graphics(240, 320);
        game.world.draw(g, 240, 320);
        assertEquals(game.world.getLandscape().getSegmentCount(), g.count("line"));
        assertEquals(4, g.count("arc"), "the four crates have an image");

        game.control.jump(5);
        assertFalse(game.control.jumpPending(), "in the air at the start: no jump");
        for (int t = 0; t < 40; t++) {
            game.world.tick();
        }
        Body sprite = game.sprite;
        game.control.jump(5);
        assertTrue(game.control.jumpPending(), "standing: the jump is set");
        game.world.tick();
        assertEquals(-100f + 100f * game.world.getTimestep(), sprite.getVelocityY(), 0.5f, "jump(5) at 20 px/s a unit");
        game.control.move(-1);
        for (int t = 0; t < 60; t++) {
            game.world.tick();
        }
        assertEquals(-20f, sprite.getVelocityX(), 0.5f, "walks at move(-1) × 20 px/s");
    }
}
