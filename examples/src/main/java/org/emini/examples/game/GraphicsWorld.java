package org.emini.examples.game;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.shape.Circle;
import org.emini.shape.Shape;
import org.emini.world.World;

/**
 * The manual's GraphicsWorld for the game: a world (a copy of the loaded one) that draws its
 * landscape and bodies. Bodies are coloured by their shape id, which the level's shape set gives
 * them, where the manual picks an image from its GraphicsShapeSet.
 */
public class GraphicsWorld extends World {
    private static final Color[] COLOURS = {new Color(0x8B5A2B), new Color(0x2E7D32), new Color(0x1565C0), Color.GRAY};

    /**
     * Wraps a copy of a world.
     *
     * @param w the world, for example one loaded from a file
     */
    public GraphicsWorld(World w) {
        super(w);
    }

    /**
     * Draws the landscape and the bodies in world coordinates (the caller translates to follow the
     * sprite).
     *
     * @param g where to draw
     */
    public void draw(Graphics2D g) {
        g.setColor(Color.BLACK);
        Landscape land = getLandscape();
        for (int i = 0; i < land.getSegmentCount(); i++) {
            g.draw(new Line2D.Float(land.getStartX(i), land.getStartY(i), land.getEndX(i), land.getEndY(i)));
        }
        for (int i = 0; i < getBodyCount(); i++) {
            drawBody(g, getBody(i));
        }
    }

    private static void drawBody(Graphics2D g, Body b) {
        Shape shape = b.getShape();
        int id = shape.getId();
        g.setColor(id >= 0 && id < COLOURS.length ? COLOURS[id] : Color.DARK_GRAY);
        float[] v = b.getVertices();
        if (shape instanceof Circle) {
            float r = ((Circle) shape).getRadius();
            g.fill(new Ellipse2D.Float(b.getX() - r, b.getY() - r, 2 * r, 2 * r));
            g.setColor(Color.WHITE);
            g.draw(new Line2D.Float(b.getX(), b.getY(), v[0], v[1]));
            return;
        }
        Path2D.Float outline = new Path2D.Float();
        outline.moveTo(v[0], v[1]);
        for (int i = 2; i < v.length; i += 2) {
            outline.lineTo(v[i], v[i + 1]);
        }
        outline.closePath();
        g.fill(outline);
    }
}
