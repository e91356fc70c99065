package org.emini.dynamics;

import org.emini.event.Event;
import org.emini.particle.ParticleEmitter;

/**
 * The structural changes asked for while a tick runs (from an external force, a constraint or an
 * event listener), applied in the order they were asked for when the tick ends. Until then the
 * world's lists stay as they were when the tick began, so nothing that walks them mid-tick (the
 * solver, the events) sees an element vanish under it.
 */
final class PendingChanges {
    static final int ADD_BODY = 0;
    static final int REMOVE_BODY = 1;
    static final int ADD_CONSTRAINT = 2;
    static final int REMOVE_CONSTRAINT = 3;
    static final int ADD_FORCE = 4;
    static final int REMOVE_FORCE = 5;
    static final int ADD_EVENT = 6;
    static final int REMOVE_EVENT = 7;
    static final int ADD_EMITTER = 8;
    static final int REMOVE_EMITTER = 9;
    static final int SET_LANDSCAPE = 10;
    static final int SHAPE_CHANGED = 11;

    private int[] ops = new int[8];
    private Object[] items = new Object[8];
    private int count;

    void add(int op, Object item) {
        if (count == ops.length) {
            ops = java.util.Arrays.copyOf(ops, 2 * count);
            items = java.util.Arrays.copyOf(items, 2 * count);
        }
        ops[count] = op;
        items[count++] = item;
    }

    /**
     * Whether the item ends up in the world's list for this kind, given that it is in it now or
     * not: the last pending add or remove of it decides.
     */
    boolean willContain(int addOp, Object item, boolean containedNow) {
        boolean contained = containedNow;
        for (int i = 0; i < count; i++) {
            if (items[i] == item) {
                if (ops[i] == addOp) {
                    contained = true;
                } else if (ops[i] == addOp + 1) {
                    contained = false;
                }
            }
        }
        return contained;
    }

    /** Applies the changes in order and forgets them, also when one of them fails. */
    void applyTo(World world) {
        int n = count;
        int[] o = ops;
        Object[] it = items;
        try {
            for (int i = 0; i < n; i++) {
                applyOne(world, o[i], it[i]);
            }
        } finally {
            count = 0;
            java.util.Arrays.fill(it, 0, n, null);
        }
    }

    private static void applyOne(World world, int op, Object item) {
        switch (op) {
            case ADD_BODY:
                world.addBody((Body) item);
                break;
            case REMOVE_BODY:
                world.removeBody((Body) item);
                break;
            case ADD_CONSTRAINT:
                world.addConstraint((Constraint) item);
                break;
            case REMOVE_CONSTRAINT:
                world.removeConstraint((Constraint) item);
                break;
            case ADD_FORCE:
                world.addExternalForce((ExternalForce) item);
                break;
            case REMOVE_FORCE:
                world.removeExternalForce((ExternalForce) item);
                break;
            case ADD_EVENT:
                world.addEvent((Event) item);
                break;
            case REMOVE_EVENT:
                world.removeEvent((Event) item);
                break;
            case ADD_EMITTER:
                world.addParticleEmitter((ParticleEmitter) item);
                break;
            case REMOVE_EMITTER:
                world.removeParticleEmitter((ParticleEmitter) item);
                break;
            case SET_LANDSCAPE:
                world.setLandscape((Landscape) item);
                break;
            default:
                Body b = (Body) item;
                if (b.world == world) {
                    world.bodyShapeChanged(b);
                }
                break;
        }
    }
}
