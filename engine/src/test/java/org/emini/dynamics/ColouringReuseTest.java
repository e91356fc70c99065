package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.EverythingScene;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * A tick whose contact graph is the last tick's keeps the last colouring ({@link ContactGraphKey}):
 * that must give bit for bit what colouring afresh gives, in scenes where the graph changes in every
 * way the key watches (contacts begin and end, bodies are added and removed, become kinematic, static
 * or dynamic, stop rotating), and it must actually be kept in a settled pile.
 */
class ColouringReuseTest {
    private static ContactSolver contacts(World world) {
        return ((Simulation) world).solver.contactSolver();
    }

    private static long everything(boolean keep) {
        EverythingScene scene = new EverythingScene(false);
        contacts(scene.world).keepColouring = keep;
        scene.run(500);
        return scene.hash();
    }

    @Test
    void theEverythingSceneIsTheSameWithTheColouringKept() {
        assertEquals(everything(false), everything(true));
    }

    private static long changingPile(boolean keep, int[] colourings) {
        World world = new World();
        world.setTicksPerSecond(60);
        contacts(world).keepColouring = keep;
        Scenes.ground(world, 0f, 2000f);
        Body[] boxes = Scenes.pyramid(world, 10, 20f);
        Body extra = null;
        for (int t = 0; t < 400; t++) {
            switch (t) {
                case 100:
                    boxes[3].setKinematic(true);
                    break;
                case 140:
                    boxes[3].setDynamic(true);
                    break;
                case 180:
                    boxes[boxes.length - 1].setRotatable(false);
                    break;
                case 220:
                    extra = new Body(30f, -400f, Shape.createCircle(8f), true);
                    world.addBody(extra);
                    break;
                case 300:
                    world.removeBody(extra);
                    break;
                case 340:
                    boxes[0].setDynamic(false);
                    break;
                default:
                    break;
            }
            world.tick();
        }
        colourings[0] = contacts(world).colourings;
        return EverythingScene.bodyHash(world);
    }

    @Test
    void aPileWhoseGraphChangesIsTheSameWithTheColouringKept() {
        int[] fresh = new int[1];
        int[] kept = new int[1];
        assertEquals(changingPile(false, fresh), changingPile(true, kept));
        assertEquals(400, fresh[0]);
        // Settled between the changes, the pile keeps its colouring in most ticks.
        assertTrue(kept[0] < 200, "colourings computed with reuse: " + kept[0]);
    }

    @Test
    void aBodyThatStopsMovingIsColouredAgain() {
        World world = new World();
        world.setTicksPerSecond(60);
        Scenes.ground(world, 0f, 400f);
        Body[] tower = Scenes.tower(world, 3, 20f);
        Scenes.run(world, 2f);
        ContactSolver contacts = contacts(world);
        int settled = contacts.colourings;
        world.tick();
        assertEquals(settled, contacts.colourings, "a settled tower keeps its colouring");
        // The same contacts between the same slots, but the middle box no longer moves: its level
        // and the colours of its contacts change.
        tower[1].setKinematic(true);
        world.tick();
        assertEquals(settled + 1, contacts.colourings, "coloured again after the kind changed");
        world.tick();
        assertEquals(settled + 1, contacts.colourings, "then kept again");
    }
}
