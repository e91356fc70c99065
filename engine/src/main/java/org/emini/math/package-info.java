/**
 * Float vectors, rotations and transforms, and {@link org.emini.math.EMath}, the single class
 * through which the engine takes square roots and trigonometric functions.
 */
package org.emini.math;
