package org.emini.harness.fuzz;

import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.dynamics.SolverSettings;
import org.emini.world.World;
import org.emini.particle.ParticleEmitter;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * The engine's public calls the setter fuzzer makes, found by reflection so that a setter the engine
 * gains is fuzzed without a change here: the mutators ({@code set…}, {@code add…}, {@code apply…},
 * {@code remove…}, {@code emit}) of the objects of {@link SetterWorld}, the shape and constraint
 * factories, and the constructors. Only calls whose parameters are numbers, booleans, bodies, shapes
 * and arrays of them are taken; sorted, so that a seed names the same calls on every JVM.
 */
final class SetterCatalog {
    /** A call: on a named object of the base world, a static factory ("Shape"), or a constructor ("new"). */
    record Call(String receiver, Executable member) {
        String name() {
            return member instanceof Constructor<?> c ? c.getDeclaringClass().getSimpleName() : member.getName();
        }

        String signature() {
            StringBuilder s = new StringBuilder(receiver).append('.').append(name()).append('(');
            for (Class<?> p : member.getParameterTypes()) {
                s.append(p.getSimpleName()).append(',');
            }
            return s.append(')').toString();
        }
    }

    static final Set<Class<?>> VALUE_TYPES = Set.of(float.class, double.class, int.class, long.class, boolean.class,
            Body.class, Shape.class, float[].class, Shape[].class);

    /** The receivers of the base world and their types. */
    static final Map<String, Class<?>> RECEIVERS = Map.ofEntries(Map.entry("world", World.class),
            Map.entry("box", Body.class), Map.entry("ball", Body.class), Map.entry("ground", Body.class),
            Map.entry("boxShape", Polygon.class), Map.entry("ballShape", Circle.class), Map.entry("joint", Joint.class),
            Map.entry("spring", Spring.class), Map.entry("motor", Motor.class), Map.entry("emitter", ParticleEmitter.class),
            Map.entry("landscape", Landscape.class), Map.entry("solver", SolverSettings.class));

    private static final List<Class<?>> FACTORIES = List.of(Shape.class, Joint.class, Spring.class, Motor.class);
    private static final List<Class<?>> MADE = List.of(Body.class, Circle.class, Polygon.class, MultiShape.class,
            Joint.class, Spring.class, Motor.class, ParticleEmitter.class);

    private SetterCatalog() {
    }

    /** Every call, sorted by signature (found once per JVM). */
    static List<Call> all() {
        return Holder.CALLS;
    }

    private static final class Holder {
        static final List<Call> CALLS = List.copyOf(find());
    }

    private static List<Call> find() {
        List<Call> calls = new ArrayList<>();
        for (Map.Entry<String, Class<?>> r : RECEIVERS.entrySet()) {
            for (Method m : r.getValue().getMethods()) {
                if (!Modifier.isStatic(m.getModifiers()) && mutator(m.getName()) && takes(m)) {
                    calls.add(new Call(r.getKey(), m));
                }
            }
        }
        for (Class<?> c : FACTORIES) {
            for (Method m : c.getMethods()) {
                if (Modifier.isStatic(m.getModifiers()) && m.getDeclaringClass() == c && takes(m)) {
                    calls.add(new Call(c.getSimpleName(), m));
                }
            }
        }
        for (Class<?> c : MADE) {
            for (Constructor<?> k : c.getConstructors()) {
                if (takes(k)) {
                    calls.add(new Call("new", k));
                }
            }
        }
        calls.sort(Comparator.comparing(Call::signature));
        return calls;
    }

    private static boolean mutator(String name) {
        return name.startsWith("set") || name.startsWith("add") || name.startsWith("apply") || name.startsWith("remove")
                || name.equals("emit");
    }

    private static boolean takes(Executable e) {
        if (!e.getDeclaringClass().getName().startsWith("org.emini.") || e.getParameterCount() == 0) {
            return false;
        }
        for (Class<?> p : e.getParameterTypes()) {
            if (!VALUE_TYPES.contains(p)) {
                return false;
            }
        }
        return true;
    }

    /** The call with this signature, or null (the engine no longer has it). */
    static Call find(String signature) {
        for (Call c : all()) {
            if (c.signature().equals(signature)) {
                return c;
            }
        }
        return null;
    }
}
