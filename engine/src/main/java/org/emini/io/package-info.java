/**
 * Original world files (<code>.phy</code>, <code>.world</code>, made with the original World
 * Designer): a document model with every record's raw values ({@link org.emini.io.PhyWorld}), a
 * reader for versions 1 to 10 ({@link org.emini.io.PhyReader}) that refuses damaged files with a
 * located {@link org.emini.io.PhyFormatException}, a writer whose output reads back to the same
 * document and, for a file read unchanged, the same bytes ({@link org.emini.io.PhyWriter}), and
 * a builder that turns a document into an engine world ({@link org.emini.io.WorldBuilder}) with
 * the original's user-data hook ({@link org.emini.io.UserData}).
 *
 * <p>Fixed point converts to engine units as the original reads it: FX (12 fractional bits,
 * lengths, speeds, factors, masses, times) is raw / 4096, 2FX (24 fractional bits, angles and
 * angular speeds) raw / 2²⁴ ({@link org.emini.io.PhyFixed}). The conventions that differ between
 * the original and this engine, and how the builder maps them, are listed in
 * <code>phy-mapping.md</code> next to this file:
 * <ul>
 * <li>angular velocity: the original advances angle ← angle − ω·dt, the engine
 * angle ← angle + ω·dt, with the same rotation matrix [c −s; s c] on a y-down screen, so angles
 * carry over and angular velocities (and motor, script and event rates) change sign;</li>
 * <li>a one-vertex shape is a circle whose radius is the vertex's distance from the origin,
 * truncated to whole pixels; a two-vertex shape is a line, built as a thin slab;</li>
 * <li>joint and spring anchors are body-local, unrotated offsets from the body's position.</li>
 * </ul>
 */
package org.emini.io;
