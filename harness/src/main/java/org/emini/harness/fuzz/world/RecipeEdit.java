package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Removes parts of a recipe, keeping it buildable: a removed body takes the joints, springs,
 * motors, forces, emitters, events and removals that name it along; an event filtering on a removed
 * constraint goes too; shapes no body or event uses are dropped.
 */
public final class RecipeEdit {
    private RecipeEdit() {
    }

    /** Every removable part, bodies last (removing one removes what depends on it). */
    public static List<ElementRef> parts(Recipe r) {
        List<ElementRef> refs = new ArrayList<>();
        r.removals.forEach(e -> refs.add(new ElementRef("removals", e.id)));
        r.events.forEach(e -> refs.add(new ElementRef("events", e.id)));
        r.forces.forEach(e -> refs.add(new ElementRef("forces", e.id)));
        r.emitters.forEach(e -> refs.add(new ElementRef("emitters", e.id)));
        r.motors.forEach(e -> refs.add(new ElementRef("motors", e.id)));
        r.springs.forEach(e -> refs.add(new ElementRef("springs", e.id)));
        r.joints.forEach(e -> refs.add(new ElementRef("joints", e.id)));
        r.segments.forEach(e -> refs.add(new ElementRef("segments", e.id)));
        if (r.area != null) {
            refs.add(new ElementRef("area", -1));
        }
        if (r.listener) {
            refs.add(new ElementRef("listener", -1));
        }
        r.bodies.forEach(e -> refs.add(new ElementRef("bodies", e.id)));
        return refs;
    }

    /** A copy without the given parts. */
    public static Recipe without(Recipe original, Set<ElementRef> removed) {
        Recipe r = original.copy();
        Set<Integer> bodies = ids(removed, "bodies");
        r.bodies.removeIf(b -> bodies.contains(b.id));
        r.segments.removeIf(s -> removed.contains(new ElementRef("segments", s.id)));
        r.joints.removeIf(j -> removed.contains(new ElementRef("joints", j.id)) || bodies.contains(j.a) || bodies.contains(j.b));
        r.springs.removeIf(s -> removed.contains(new ElementRef("springs", s.id)) || bodies.contains(s.a) || bodies.contains(s.b));
        r.motors.removeIf(m -> removed.contains(new ElementRef("motors", m.id)) || bodies.contains(m.body));
        r.emitters.removeIf(e -> removed.contains(new ElementRef("emitters", e.id)) || bodies.contains(e.body));
        r.forces.removeIf(f -> removed.contains(new ElementRef("forces", f.id)) || bodies.contains(f.body));
        r.removals.removeIf(m -> removed.contains(new ElementRef("removals", m.id)) || bodies.contains(m.body));
        r.events.removeIf(e -> removed.contains(new ElementRef("events", e.id)) || bodies.contains(e.body)
                || bodies.contains(e.sensor) || e.constraintKind != null && !constraintExists(r, e));
        if (removed.contains(new ElementRef("area", -1))) {
            r.area = null;
        }
        if (removed.contains(new ElementRef("listener", -1))) {
            r.listener = false;
        }
        Set<Integer> used = new HashSet<>();
        r.bodies.forEach(b -> used.add(b.shape));
        r.events.forEach(e -> used.add(e.shape));
        r.shapes.removeIf(s -> !used.contains(s.id));
        return r;
    }

    private static boolean constraintExists(Recipe r, EventRecipe e) {
        return switch (e.constraintKind) {
            case "joint" -> r.joints.stream().anyMatch(j -> j.id == e.constraint);
            case "spring" -> r.springs.stream().anyMatch(s -> s.id == e.constraint);
            default -> r.motors.stream().anyMatch(m -> m.id == e.constraint);
        };
    }

    private static Set<Integer> ids(Set<ElementRef> refs, String list) {
        Set<Integer> ids = new HashSet<>();
        for (ElementRef ref : refs) {
            if (ref.list().equals(list)) {
                ids.add(ref.id());
            }
        }
        return ids;
    }
}
