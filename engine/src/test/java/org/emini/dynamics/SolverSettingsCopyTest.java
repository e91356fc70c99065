package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/** Copying settings (and so {@code World(World)}) must carry every setting, including ones added later. */
class SolverSettingsCopyTest {
    @Test
    void setCopiesEveryField() throws Exception {
        SolverSettings from = new SolverSettings();
        int k = 0;
        for (Field field : fields()) {
            k++;
            if (field.getType() == float.class) {
                field.setFloat(from, 1000f + k);
            } else {
                field.setInt(from, 1000 + k);
            }
        }
        assertTrue(k > 20, "fields " + k);
        SolverSettings to = new SolverSettings();
        to.set(from);
        for (Field field : fields()) {
            assertEquals(field.get(from), field.get(to), field.getName());
        }
    }

    @Test
    void aCopiedWorldKeepsItsManifoldReuseDistance() {
        World world = new World();
        world.getSolverSettings().setManifoldReuseDistance(0f);
        assertEquals(0f, new World(world).getSolverSettings().getManifoldReuseDistance());
    }

    private static Field[] fields() {
        Field[] all = SolverSettings.class.getDeclaredFields();
        java.util.List<Field> out = new java.util.ArrayList<>();
        for (Field f : all) {
            if (!Modifier.isStatic(f.getModifiers())) {
                f.setAccessible(true);
                out.add(f);
            }
        }
        return out.toArray(new Field[0]);
    }
}
