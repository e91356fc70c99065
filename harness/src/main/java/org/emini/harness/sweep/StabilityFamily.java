package org.emini.harness.sweep;

import java.util.List;
import java.util.Locale;
import java.util.function.DoubleFunction;

/**
 * A family of stiff or extreme scenes along one parameter, for stability maps: each value gives a scene
 * (YAML text) run at every timestep of the grid. A cell is unstable when the state goes NaN or
 * infinite, the total energy rises by more than 1% of its scale, a watched body crosses a wall
 * (tunnelling), the deepest overlap exceeds {@code penetrationBound}, or a body that should rest moves
 * more than {@code moveBound} from where it started (a collapse).
 *
 * @param name family id
 * @param parameter what varies, with its unit
 * @param values the parameter values, ascending
 * @param scene the scene text for a value
 * @param penetrationBound deepest allowed overlap (px) for a value
 * @param moveBound largest allowed displacement of any dynamic body (px), or NaN for none
 * @param why where the bounds come from
 */
public record StabilityFamily(String name, String parameter, List<Double> values, DoubleFunction<String> scene,
                              DoubleFunction<Double> penetrationBound, double moveBound, String why) {

    private static String f(double v) {
        return String.format(Locale.ROOT, "%.6g", v);
    }

    private static final String GROUND = "  ground: {type: rectangle, width: %s, height: 20}\n";

    /** The six families, each run in both engines (springs included: the engine and pymunk both have them). */
    public static List<StabilityFamily> all() {
        return List.of(
                new StabilityFamily("massRatio", "mass of the top box / mass of the bottom box",
                        List.of(1.0, 10.0, 100.0, 1000.0, 10000.0), r -> "shapes:\n" + GROUND.formatted("400")
                        + "  light: {type: rectangle, width: 20, height: 20}\n"
                        + "  heavy: {type: rectangle, width: 20, height: 20, mass: " + f(r) + "}\n"
                        + "bodies:\n  - {name: ground, shape: ground, position: [0, 10], static: true}\n"
                        + "  - {name: light, shape: light, position: [0, -10]}\n"
                        + "  - {name: heavy, shape: heavy, position: [0, -30]}\n"
                        + "run: {duration: 3, record: {metrics: [penetration]}}\n",
                        r -> 2.0, 10, "overlap beyond 10% of the 20 px box; a box moving half its size has fallen"),
                new StabilityFamily("stackHeight", "boxes in a tower", List.of(5.0, 10.0, 20.0, 40.0),
                        n -> "shapes:\n" + GROUND.formatted("400") + "  box: {type: rectangle, width: 20, height: 20}\n"
                        + "bodies:\n  - {name: ground, shape: ground, position: [0, 10], static: true}\n"
                        + "generators:\n  - {type: tower, name: tower, shape: box, base: [0, -10], count: " + (int) n + "}\n"
                        + "run: {duration: 5, record: {metrics: [penetration]}}\n",
                        n -> 2.0, 10, "a box moving half its size means the tower fell"),
                new StabilityFamily("bodySpeed", "speed of a 2 px bullet against a 4 px wall (px/s)",
                        List.of(100.0, 1000.0, 10000.0, 100000.0),
                        v -> "world: {gravity: [0, 0]}\nshapes:\n  wall: {type: rectangle, width: 4, height: 200}\n"
                        + "  bullet: {type: circle, radius: 2}\n"
                        + "bodies:\n  - {name: wall, shape: wall, position: [0, 0], static: true}\n"
                        + "  - {name: bullet, shape: bullet, position: [-250, 0], velocity: [" + f(v) + ", 0]}\n"
                        + "run: {duration: 1, record: {metrics: [{tunnelling: {walls: [wall], bodies: [bullet]}}]}}\n",
                        v -> 2.0, Double.NaN, "the bullet's centre crossing the wall line is tunnelling"),
                new StabilityFamily("distance", "distance of a resting box from the origin (px)",
                        List.of(0.0, 1000.0, 10000.0, 100000.0, 1000000.0),
                        d -> "shapes:\n" + GROUND.formatted("400") + "  box: {type: rectangle, width: 20, height: 20}\n"
                        + "bodies:\n  - {name: ground, shape: ground, position: [" + f(d) + ", 10], static: true}\n"
                        + "  - {name: box, shape: box, position: [" + f(d) + ", -10]}\n"
                        + "run: {duration: 3, record: {metrics: [penetration]}}\n",
                        d -> 2.0, 2, "a resting box should not creep; float spacing at 1e6 px is 0.06 px"),
                new StabilityFamily("bodySize", "side of a resting box (px)", List.of(0.25, 1.0, 4.0, 20.0, 100.0),
                        s -> "shapes:\n" + GROUND.formatted(f(Math.max(400, 20 * s)))
                        + "  box: {type: rectangle, width: " + f(s) + ", height: " + f(s) + "}\n"
                        + "bodies:\n  - {name: ground, shape: ground, position: [0, 10], static: true}\n"
                        + "  - {name: box, shape: box, position: [0, " + f(-s / 2) + "]}\n"
                        + "run: {duration: 3, record: {metrics: [penetration]}}\n",
                        s -> 0.1 * s, 5, "overlap beyond 10% of the box's side"),
                new StabilityFamily("springStiffness", "spring stiffness k (mass 1, so omega = sqrt(k))",
                        List.of(100.0, 1000.0, 10000.0, 100000.0, 1000000.0),
                        k -> "world: {gravity: [0, 0]}\nshapes:\n  anchor: {type: rectangle, width: 10, height: 10}\n"
                        + "  weight: {type: circle, radius: 5}\n"
                        + "bodies:\n  - {name: anchor, shape: anchor, position: [0, 0], static: true}\n"
                        + "  - {name: weight, shape: weight, position: [60, 0]}\n"
                        + "springs:\n  - {bodyA: anchor, bodyB: weight, restLength: 50, stiffness: " + f(k) + "}\n"
                        + "run: {duration: 3, record: {metrics: [energy]}}\n",
                        k -> 2.0, Double.NaN, "the energy of an undamped spring can never rise; h omega < 2 is the explicit limit"));
    }
}
