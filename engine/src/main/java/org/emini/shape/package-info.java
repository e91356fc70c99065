/**
 * Collision shapes: {@link org.emini.shape.Circle circles}, convex
 * {@link org.emini.shape.Polygon polygons} of up to 12 vertices, and
 * {@link org.emini.shape.MultiShape multi-shapes} made of several of them (which may be concave),
 * with their material (friction, elasticity) and mass.
 *
 * <p>A shape is described in its local frame, whose origin is the position and centre of rotation
 * of every body that uses it. Shapes carry mass rather than density (as in the original engine);
 * the inertia follows from the mass assuming uniform density over the area. Geometry is immutable
 * after construction so one shape can be shared by many bodies.
 */
package org.emini.shape;
