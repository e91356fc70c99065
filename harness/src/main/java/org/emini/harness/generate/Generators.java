package org.emini.harness.generate;

import java.util.ArrayList;
import java.util.List;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.BodyState;
import org.emini.harness.scenario.GeneratorSpec;
import org.emini.harness.scenario.ShapeSpec;

/**
 * Expands generators into bodies. Body i of generator NAME is called {@code NAME[i]}; the placement
 * rules below are the ones scenarios/README.md documents (the oracle repeats them).
 */
public final class Generators {
    private Generators() {
    }

    /** How many bodies a generator makes, computed without making them (a long: rows² can pass 2³¹). */
    public static long size(GeneratorSpec g) {
        return switch (g.kind()) {
            case pyramid -> (long) g.rows() * (g.rows() + 1L) / 2;
            case grid -> (long) g.rows() * g.columns();
            default -> g.count();
        };
    }

    /** The bodies of one generator, in order. */
    public static List<BodySpec> expand(GeneratorSpec g) {
        switch (g.kind()) {
            case tower:
                return tower(g);
            case pyramid:
                return pyramid(g);
            case grid:
                return grid(g);
            case row:
                return row(g);
            default:
                return rain(g);
        }
    }

    /** A column of {@code count} bodies, body 0 at {@code base}, each next one {@code spacing} higher (−y). */
    static List<BodySpec> tower(GeneratorSpec g) {
        ShapeSpec shape = g.shapes().get(0);
        double dy = g.spacing() != null ? g.spacing()[0] : shape.size()[1];
        List<BodySpec> out = new ArrayList<>();
        for (int i = 0; i < g.count(); i++) {
            out.add(body(g, i, shape, g.anchor()[0], g.anchor()[1] - i * dy, g.template()));
        }
        return out;
    }

    /**
     * Rows from the bottom: row r (0 at the bottom) has {@code rows − r} bodies centred on base.x,
     * {@code dx} apart, at y = base.y − r·dy. Bodies are numbered row by row, left to right.
     */
    static List<BodySpec> pyramid(GeneratorSpec g) {
        ShapeSpec shape = g.shapes().get(0);
        double[] size = shape.size();
        double dx = g.spacing() != null ? g.spacing()[0] : size[0];
        double dy = g.spacing() != null ? g.spacing()[1] : size[1];
        List<BodySpec> out = new ArrayList<>();
        int i = 0;
        for (int r = 0; r < g.rows(); r++) {
            int n = g.rows() - r;
            for (int j = 0; j < n; j++) {
                double x = g.anchor()[0] + (j - (n - 1) / 2.0) * dx;
                out.add(body(g, i++, shape, x, g.anchor()[1] - r * dy, g.template()));
            }
        }
        return out;
    }

    /** Body (row r, column c) at origin + (c·dx, r·dy), numbered row by row; default spacing [w, −h]. */
    static List<BodySpec> grid(GeneratorSpec g) {
        ShapeSpec shape = g.shapes().get(0);
        double[] size = shape.size();
        double dx = g.spacing() != null ? g.spacing()[0] : size[0];
        double dy = g.spacing() != null ? g.spacing()[1] : -size[1];
        List<BodySpec> out = new ArrayList<>();
        int i = 0;
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.columns(); c++) {
                out.add(body(g, i++, shape, g.anchor()[0] + c * dx, g.anchor()[1] + r * dy, g.template()));
            }
        }
        return out;
    }

    /** Body i at start + i·spacing; default spacing [w, 0]. */
    static List<BodySpec> row(GeneratorSpec g) {
        ShapeSpec shape = g.shapes().get(0);
        double dx = g.spacing() != null ? g.spacing()[0] : shape.size()[0];
        double dy = g.spacing() != null ? g.spacing()[1] : 0;
        List<BodySpec> out = new ArrayList<>();
        for (int i = 0; i < g.count(); i++) {
            out.add(body(g, i, shape, g.anchor()[0] + i * dx, g.anchor()[1] + i * dy, g.template()));
        }
        return out;
    }

    /**
     * Random bodies in a region. For each body in order, from one SplitMix64 stream: x = min.x + u·(max.x −
     * min.x), then y likewise, then (only with more than one shape) shape index ⌊u·n⌋, then (only with
     * randomAngle) angle = u·2π.
     */
    static List<BodySpec> rain(GeneratorSpec g) {
        SplitMix64 random = new SplitMix64(g.seed());
        List<BodySpec> out = new ArrayList<>();
        int n = g.shapes().size();
        for (int i = 0; i < g.count(); i++) {
            double x = g.min()[0] + random.nextDouble() * (g.max()[0] - g.min()[0]);
            double y = g.min()[1] + random.nextDouble() * (g.max()[1] - g.min()[1]);
            ShapeSpec shape = n > 1 ? g.shapes().get((int) Math.floor(random.nextDouble() * n)) : g.shapes().get(0);
            BodyState state = g.template();
            if (g.randomAngle()) {
                double a = random.nextDouble() * 2 * Math.PI;
                state = new BodyState(state.isStatic(), a, state.vx(), state.vy(), state.angularVelocity(),
                        state.rotatable(), state.interacting(), state.gravity(), state.layers(),
                        state.sleepingAllowed());
            }
            out.add(body(g, i, shape, x, y, state));
        }
        return out;
    }

    private static BodySpec body(GeneratorSpec g, int i, ShapeSpec shape, double x, double y, BodyState state) {
        return new BodySpec(g.name() + "[" + i + "]", shape, x, y, state, g.path());
    }
}
