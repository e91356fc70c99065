package org.emini.shape;

import java.util.Arrays;

/**
 * The shapes of a world in a numbered list, the original's {@code ShapeSet}: a shape's index here
 * is its {@link Shape#getId() id}. A world loaded from a file holds the file's shapes in file order,
 * so the ids are the World Designer's shape numbers, and an application can keep one image per id.
 * An application may extend it (the manual's {@code GraphicsShapeSet}) to keep such data beside
 * the shapes.
 */
public class ShapeSet {
    private Shape[] shapes = new Shape[8];
    private int count;

    /** Creates an empty set. */
    public ShapeSet() {
    }

    /**
     * Adds a shape at the end of the list and gives it that index as its id. A shape already in the
     * set keeps its place.
     *
     * @param shape the shape
     * @return its id, the index in this set
     */
    public int register(Shape shape) {
        if (shape == null) {
            throw new IllegalArgumentException("ShapeSet.register: shape is null");
        }
        int known = indexOf(shape);
        if (known >= 0) {
            return known;
        }
        if (count == shapes.length) {
            shapes = Arrays.copyOf(shapes, 2 * count);
        }
        shapes[count] = shape;
        shape.setId(count);
        return count++;
    }

    /**
     * Puts a shape at a given id (a loaded world puts each shape at its index in the file, leaving
     * the ids of shapes it could not build empty) and gives it that id.
     *
     * @param id the id, &ge; 0; ids below it that hold nothing stay empty ({@link #getShape} gives null)
     * @param shape the shape
     */
    public void put(int id, Shape shape) {
        if (shape == null || id < 0) {
            throw new IllegalArgumentException("ShapeSet.put: needs a shape and an id >= 0, got " + shape + " and " + id);
        }
        if (id >= shapes.length) {
            shapes = Arrays.copyOf(shapes, Math.max(2 * shapes.length, id + 1));
        }
        shapes[id] = shape;
        shape.setId(id);
        count = Math.max(count, id + 1);
    }

    /**
     * The number of shapes.
     *
     * @return the count
     */
    public int getShapeCount() {
        return count;
    }

    /**
     * A shape by its id.
     *
     * @param id 0 to {@link #getShapeCount()} − 1
     * @return the shape, or null for an id left empty by {@link #put}
     */
    public Shape getShape(int id) {
        if (id < 0 || id >= count) {
            throw new IndexOutOfBoundsException("ShapeSet.getShape: id " + id + " of " + count);
        }
        return shapes[id];
    }

    /**
     * The index of a shape in this set (by identity).
     *
     * @param shape the shape
     * @return its index, or −1 when it is not in the set
     */
    public int indexOf(Shape shape) {
        for (int i = 0; i < count; i++) {
            if (shapes[i] == shape) {
                return i;
            }
        }
        return -1;
    }
}
