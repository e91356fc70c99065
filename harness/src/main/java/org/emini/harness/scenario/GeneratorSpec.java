package org.emini.harness.scenario;

import java.util.List;
import org.emini.harness.load.JsonPath;

/**
 * A generator as written: expanded into bodies when the scene is read.
 *
 * @param kind which generator
 * @param name body name prefix: bodies are NAME[0], NAME[1], ...
 * @param shapes the shape (one) or, for rain, the shapes drawn from
 * @param anchor base (tower, pyramid), origin (grid) or start (row)
 * @param count bodies (tower, row, rain)
 * @param rows rows (pyramid, grid)
 * @param columns columns (grid)
 * @param spacing explicit spacing: [d] for tower, [dx, dy] otherwise; null for the default
 * @param min rain region minimum corner
 * @param max rain region maximum corner
 * @param seed rain seed
 * @param randomAngle rain: draw a random angle for each body
 * @param template flags and state of every generated body
 * @param path where the generator is written
 */
public record GeneratorSpec(Kind kind, String name, List<ShapeSpec> shapes, double[] anchor, int count, int rows,
                            int columns, double[] spacing, double[] min, double[] max, long seed,
                            boolean randomAngle, BodyState template, JsonPath path) {

    /** Generator kinds, named as in the scene files. */
    public enum Kind { tower, pyramid, grid, row, rain }
}
