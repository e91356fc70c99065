/**
 * {@link org.emini.math.EMath}, the single class through which the engine takes square roots and
 * trigonometric functions. The double-precision flavour (emini-engine-double) is generated from the
 * engine's source by type rules alone; a fixed-point flavour would replace this class (how:
 * engine-double/README.md). Vectors are plain float pairs in the engine's arrays, not objects.
 */
package org.emini.math;
