package org.emini.harness.scenario;

import org.emini.harness.load.JsonPath;

/**
 * One body of the scene, written out or produced by a generator.
 *
 * @param name unique name ({@code ball}, {@code tower[3]}); generated when the file gives none
 * @param shape the body's shape
 * @param x initial position (px)
 * @param y initial position (px)
 * @param state flags and initial velocities
 * @param path where the body (or its generator) is written
 */
public record BodySpec(String name, ShapeSpec shape, double x, double y, BodyState state, JsonPath path) {
}
