package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.world.World;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.junit.jupiter.api.Test;

/** The landscape and multishapes of a world file in the engine. */
class LandscapeMappingTest {
    @Test
    void segmentsKeepTheOriginalsOrderFacesAndMaterial() {
        PhyWorld doc = new PhyWorld();
        PhyLandscape l = new PhyLandscape();
        l.getSegments().add(new PhySegment(PhyVector.of(0, 0), PhyVector.of(100, 0), PhySegment.FACE_LEFT));
        l.getSegments().add(new PhySegment(PhyVector.of(50, 0), PhyVector.of(50, -80), PhySegment.FACE_LEFT));
        l.getSegments().add(new PhySegment(PhyVector.of(300, 0), PhyVector.of(200, 0), 9));
        l.getSegments().add(new PhySegment(PhyVector.of(400, 0), PhyVector.of(500, 0), 9));
        l.getMaterial().setFrictionRaw(4096);
        l.getMaterial().setElasticityRaw(2048);
        doc.setLandscape(l);
        BuildResult r = new WorldBuilder().build(doc);
        Landscape built = r.getWorld().getLandscape();
        assertEquals(4, built.getSegmentCount());
        assertEquals(1f, built.getFriction());
        assertEquals(0.5f, built.getElasticity());
        assertEquals(PhySegment.FACE_LEFT, built.getFace(0));
        // Vertical: the original swaps the ends and flips the face on insertion; so does the engine.
        assertEquals(-80f, built.getStartY(1));
        assertEquals(PhySegment.FACE_RIGHT, built.getFace(1));
        assertEquals(PhySegment.FACE_RIGHT, built.getFace(2), "another face turns right when swapped");
        assertEquals(200f, built.getStartX(2));
        assertEquals(PhySegment.FACE_NONE, built.getFace(3));
        assertEquals("landscape segment 3: face byte 9 is neither left nor right; built solid from both sides",
                r.getApproximations().get(0).toString());
        assertTrue(r.getUnsupported().isEmpty());
    }

    @Test
    void theRhabarberLevelsKeepTheirBodiesInside() throws Exception {
        for (String file : new String[] {"rhabarber-small.phy", "rhabarber-testWorld.phy"}) {
            PhyWorld doc = ReferenceWorlds.read(file);
            float minX = Float.MAX_VALUE;
            float minY = Float.MAX_VALUE;
            float maxX = -Float.MAX_VALUE;
            float maxY = -Float.MAX_VALUE;
            for (PhySegment s : doc.getLandscape().getSegments()) {
                minX = Math.min(minX, Math.min(s.getStart().getX(), s.getEnd().getX()));
                maxX = Math.max(maxX, Math.max(s.getStart().getX(), s.getEnd().getX()));
                minY = Math.min(minY, Math.min(s.getStart().getY(), s.getEnd().getY()));
                maxY = Math.max(maxY, Math.max(s.getStart().getY(), s.getEnd().getY()));
            }
            World world = new WorldBuilder().build(doc).getWorld();
            for (int t = 0; t < 600; t++) {
                world.tick();
            }
            for (int i = 0; i < world.getBodyCount(); i++) {
                Body b = world.getBody(i);
                assertTrue(b.getX() > minX && b.getX() < maxX && b.getY() > minY && b.getY() < maxY,
                        file + ": " + b + " stays inside the level's walls");
            }
        }
    }

    @Test
    void aMultishapeIsBuiltFromItsParts() {
        PhyWorld doc = new PhyWorld();
        PhyShape arm = new PhyShape(PhyVector.of(0, -2), PhyVector.of(30, -2), PhyVector.of(30, 2), PhyVector.of(0, 2));
        arm.setMassRaw(3 * 4096);
        arm.setFrictionRaw(4096);
        doc.getShapes().add(arm);
        doc.getShapes().add(new PhyShape(PhyVector.of(0, 5)));
        doc.getShapes().add(new PhyShape(PhyVector.of(-20, 0), PhyVector.of(20, 0)));
        doc.getShapes().add(new PhyMultiShape(0, 1));
        doc.getShapes().add(new PhyMultiShape(3, 2));
        doc.getShapes().add(new PhyShape(PhyVector.of(0.1f, 0)));
        doc.getShapes().add(new PhyMultiShape(0, 5));
        BuildResult r = new WorldBuilder().build(doc);
        MultiShape m = (MultiShape) r.getShape(3);
        assertEquals(2, m.getShapeCount());
        assertEquals(4f, m.getMass(), "the sum of the parts' masses");
        assertEquals(0.25f, m.getFriction(), "a multishape's material is the default, as in the original");
        MultiShape nested = (MultiShape) r.getShape(4);
        assertEquals(3, nested.getShapeCount(), "a multishape part gives its own parts");
        assertTrue(nested.getShape(2) instanceof Polygon, "the line's slab");
        assertNull(r.getShape(6));
        assertEquals("multi shape 6: its part 5 is not built", r.getUnsupported().get(1).toString());
    }
}
