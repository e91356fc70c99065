package org.emini.harness.fuzz;

import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.emini.dynamics.Body;

/**
 * A setter fuzz input: one or two calls on the base world, one per line, as
 * {@code receiver.name(types,) <- arg ; arg}. Text, so that a finding is a file a person can read and
 * the worker can run again ({@code harness fuzz setters --replay FILE}).
 */
final class SetterProgram {
    static final float[] FLOATS = {Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, 1e30f, -1e30f,
        Float.MAX_VALUE, -Float.MAX_VALUE, Float.MIN_VALUE, -Float.MIN_VALUE, 0f, -0f, -1f, 1e-30f};
    static final float[] PLAIN_FLOATS = {1f, 10f, 0.5f, 100f, 2f};
    static final int[] INTS = {0, -1, Integer.MAX_VALUE, Integer.MIN_VALUE, 100_000_000, 31, 32, 1001, 13};
    static final int[] PLAIN_INTS = {1, 3, 5, 10};
    static final long[] LONGS = {0L, -1L, Long.MAX_VALUE, Long.MIN_VALUE};
    static final String[] BODIES = {"box", "ball", "ground", "fresh"};

    private static final String ARROW = " <- ";
    private static final String SEP = " ; ";

    private SetterProgram() {
    }

    /** The program of input {@code index} of {@code seed}. */
    static String generate(List<SetterCatalog.Call> catalog, long seed, long index) {
        SplittableRandom r = Inputs.random(seed, index);
        StringBuilder out = new StringBuilder();
        int calls = 1 + r.nextInt(2);
        for (int i = 0; i < calls; i++) {
            SetterCatalog.Call c = catalog.get(r.nextInt(catalog.size()));
            out.append(c.signature()).append(ARROW);
            Class<?>[] types = c.member().getParameterTypes();
            for (int k = 0; k < types.length; k++) {
                out.append(k > 0 ? SEP : "").append(value(types[k], r));
            }
            out.append('\n');
        }
        return out.toString();
    }

    private static String value(Class<?> t, SplittableRandom r) {
        boolean extreme = r.nextInt(10) < 6;
        if (t == float.class || t == double.class) {
            return Float.toString(extreme ? FLOATS[r.nextInt(FLOATS.length)] : PLAIN_FLOATS[r.nextInt(PLAIN_FLOATS.length)]);
        }
        if (t == int.class) {
            return Integer.toString(extreme ? INTS[r.nextInt(INTS.length)] : PLAIN_INTS[r.nextInt(PLAIN_INTS.length)]);
        }
        if (t == long.class) {
            return Long.toString(extreme ? LONGS[r.nextInt(LONGS.length)] : 7L);
        }
        if (t == boolean.class) {
            return Boolean.toString(r.nextBoolean());
        }
        if (t == Body.class) {
            return BODIES[r.nextInt(BODIES.length)];
        }
        if (t == org.emini.shape.Shape.class) {
            return r.nextBoolean() ? "rect" : "circle";
        }
        if (t == org.emini.shape.Shape[].class) {
            return "[rect circle]";
        }
        // float[]: a polygon's coordinates, a triangle with one of them extreme, or too few.
        List<String> xy = new ArrayList<>(List.of("0.0", "0.0", "10.0", "0.0", "0.0", "10.0"));
        if (extreme) {
            xy.set(r.nextInt(xy.size()), Float.toString(FLOATS[r.nextInt(FLOATS.length)]));
        }
        int n = r.nextInt(8) == 0 ? 2 * r.nextInt(3) : xy.size();
        return "[" + String.join(" ", xy.subList(0, Math.min(n, xy.size()))) + "]";
    }

    /** One parsed line: the call and its arguments as written. */
    record Line(String text, SetterCatalog.Call call, String[] args) {
    }

    /** The lines of a program; a line whose call the engine no longer has is an error of the input. */
    static List<Line> parse(String program) {
        List<Line> lines = new ArrayList<>();
        for (String text : program.split("\n")) {
            if (text.isBlank() || text.startsWith("#")) {
                continue;
            }
            int arrow = text.indexOf(ARROW);
            SetterCatalog.Call call = SetterCatalog.find(text.substring(0, arrow));
            if (call == null) {
                throw new IllegalArgumentException("no such call in this engine: " + text);
            }
            lines.add(new Line(text, call, text.substring(arrow + ARROW.length()).split(SEP)));
        }
        return lines;
    }

    /** Makes the call on the base world; what a constructor or factory makes is added to it. */
    static void run(Line line, SetterWorld w) throws ReflectiveOperationException {
        Class<?>[] types = line.call().member().getParameterTypes();
        Object[] args = new Object[types.length];
        for (int k = 0; k < types.length; k++) {
            args[k] = argument(types[k], line.args()[k].trim(), w);
        }
        if (line.call().member() instanceof Constructor<?> c) {
            w.add(c.newInstance(args));
            return;
        }
        Method m = (Method) line.call().member();
        Object made = m.invoke(java.lang.reflect.Modifier.isStatic(m.getModifiers()) ? null : w.objects.get(line.call().receiver()), args);
        if (java.lang.reflect.Modifier.isStatic(m.getModifiers())) {
            w.add(made);
        }
    }

    private static Object argument(Class<?> t, String v, SetterWorld w) {
        if (t == float.class) {
            return Float.parseFloat(v);
        }
        if (t == double.class) {
            return (double) Float.parseFloat(v);
        }
        if (t == int.class) {
            return Integer.parseInt(v);
        }
        if (t == long.class) {
            return Long.parseLong(v);
        }
        if (t == boolean.class) {
            return Boolean.parseBoolean(v);
        }
        if (t == Body.class) {
            return w.body(v);
        }
        if (t == org.emini.shape.Shape.class) {
            return SetterWorld.shape(v);
        }
        String[] items = v.substring(1, v.length() - 1).trim().split(" ");
        if (t == org.emini.shape.Shape[].class) {
            return new org.emini.shape.Shape[] {SetterWorld.shape("rect"), SetterWorld.shape("circle")};
        }
        float[] xy = new float[items[0].isEmpty() ? 0 : items.length];
        for (int i = 0; i < xy.length; i++) {
            xy[i] = Float.parseFloat(items[i]);
        }
        return xy;
    }
}
