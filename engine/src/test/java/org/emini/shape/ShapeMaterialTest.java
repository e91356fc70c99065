package org.emini.shape;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Material defaults and the validation of the material and mass setters. */
class ShapeMaterialTest {
    @Test
    void newShapesHaveTheOriginalDefaults() {
        for (Shape s : new Shape[] {Shape.createCircle(5f), Shape.createRectangle(2f, 3f)}) {
            assertEquals(1f, s.getMass());
            assertEquals(1f, s.getInverseMass());
            assertEquals(0.25f, s.getFriction());
            assertEquals(0f, s.getElasticity());
        }
    }

    @Test
    void percentSettersScaleToFractions() {
        Shape s = Shape.createCircle(1f);
        s.setFrictionPercent(25);
        s.setElasticityPercent(100);
        assertEquals(0.25f, s.getFriction());
        assertEquals(1f, s.getElasticity());
        s.setFrictionPercent(0);
        assertEquals(0f, s.getFriction());
    }

    @Test
    void badMassIsRefusedWithTheSetterAndValueInTheMessage() {
        Shape s = Shape.createCircle(1f);
        for (float bad : new float[] {0f, -1f, Float.NaN, Float.POSITIVE_INFINITY}) {
            IllegalArgumentException e =
                    assertThrows(IllegalArgumentException.class, () -> s.setMass(bad));
            assertTrue(e.getMessage().contains("Shape.setMass"), e.getMessage());
            assertTrue(e.getMessage().contains(String.valueOf(bad)), e.getMessage());
        }
        assertEquals(1f, s.getMass());
    }

    @Test
    void frictionAndElasticityOutsideZeroToOneAreRefused() {
        Shape s = Shape.createCircle(1f);
        for (float bad : new float[] {-0.01f, 1.01f, Float.NaN}) {
            IllegalArgumentException f =
                    assertThrows(IllegalArgumentException.class, () -> s.setFriction(bad));
            assertTrue(f.getMessage().contains("Shape.setFriction"), f.getMessage());
            assertTrue(f.getMessage().contains(String.valueOf(bad)), f.getMessage());
            IllegalArgumentException e =
                    assertThrows(IllegalArgumentException.class, () -> s.setElasticity(bad));
            assertTrue(e.getMessage().contains("Shape.setElasticity"), e.getMessage());
        }
        IllegalArgumentException p =
                assertThrows(IllegalArgumentException.class, () -> s.setFrictionPercent(101));
        assertTrue(p.getMessage().contains("Shape.setFrictionPercent"), p.getMessage());
        assertTrue(p.getMessage().contains("101"), p.getMessage());
        assertThrows(IllegalArgumentException.class, () -> s.setElasticityPercent(-1));
    }

    @Test
    void badCircleRadiusIsRefusedWithARule() {
        InvalidShapeException zero =
                assertThrows(InvalidShapeException.class, () -> new Circle(0f));
        assertEquals(InvalidShapeException.Rule.DEGENERATE, zero.getRule());
        InvalidShapeException nan =
                assertThrows(InvalidShapeException.class, () -> new Circle(1f, Float.NaN, 0f));
        assertEquals(InvalidShapeException.Rule.NOT_FINITE, nan.getRule());
    }

    @Test
    void badFactoryArgumentsAreRefusedNamingTheFactory() {
        IllegalArgumentException w = assertThrows(IllegalArgumentException.class,
                () -> Shape.createRectangle(-2f, 3f));
        assertTrue(w.getMessage().contains("Shape.createRectangle"), w.getMessage());
        assertTrue(w.getMessage().contains("width"), w.getMessage());
        InvalidShapeException few = assertThrows(InvalidShapeException.class,
                () -> Shape.createRegularPolygon(5f, 2));
        assertEquals(InvalidShapeException.Rule.TOO_FEW_VERTICES, few.getRule());
        InvalidShapeException many = assertThrows(InvalidShapeException.class,
                () -> Shape.createRegularPolygon(5f, 13));
        assertEquals(InvalidShapeException.Rule.TOO_MANY_VERTICES, many.getRule());
    }
}
