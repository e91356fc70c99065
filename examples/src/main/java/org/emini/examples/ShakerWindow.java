package org.emini.examples;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Circle;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * A Swing window for the shaker: draws the bodies and springs (the manual's GraphicsWorld) and
 * ticks the world in real time; held arrow keys shake the box (the manual's SimulationCanvas).
 */
final class ShakerWindow extends JPanel {
    private static final long serialVersionUID = 1L;
    private static final float SCALE = 1.6f;
    private static final int MARGIN = 60;

    private final transient ShakerWorld shaker;
    private boolean up;
    private boolean down;
    private boolean left;
    private boolean right;

    private ShakerWindow(ShakerWorld shaker) {
        this.shaker = shaker;
        setPreferredSize(new Dimension(Math.round((ShakerWorld.WIDTH + 2 * MARGIN) * SCALE),
            Math.round((ShakerWorld.HEIGHT + 2 * MARGIN) * SCALE)));
        setBackground(Color.WHITE);
        setFocusable(true);
        addKeyListener(new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                setKey(e.getKeyCode(), true);
            }

            @Override
            public void keyReleased(KeyEvent e) {
                setKey(e.getKeyCode(), false);
            }
        });
    }

    private void setKey(int code, boolean pressed) {
        switch (code) {
            case KeyEvent.VK_UP:
                up = pressed;
                break;
            case KeyEvent.VK_DOWN:
                down = pressed;
                break;
            case KeyEvent.VK_LEFT:
                left = pressed;
                break;
            case KeyEvent.VK_RIGHT:
                right = pressed;
                break;
            default:
                break;
        }
    }

    /** Opens the window and starts ticking at the world's rate. */
    static void open(ShakerWorld shaker) {
        SwingUtilities.invokeLater(() -> {
            ShakerWindow panel = new ShakerWindow(shaker);
            JFrame frame = new JFrame("Emini shaker: arrow keys shake the box");
            frame.setDefaultCloseOperation(JFrame.EXIT_ON_CLOSE);
            frame.add(panel);
            frame.pack();
            frame.setLocationRelativeTo(null);
            frame.setVisible(true);
            panel.requestFocusInWindow();
            int millis = Math.round(1000f * shaker.getWorld().getTimestep());
            new Timer(millis, e -> panel.step()).start();
        });
    }

    private void step() {
        float ax = (right ? ShakerWorld.SHAKE : 0f) - (left ? ShakerWorld.SHAKE : 0f);
        float ay = (down ? ShakerWorld.SHAKE : 0f) - (up ? ShakerWorld.SHAKE : 0f);
        shaker.shake(ax, ay);
        shaker.tick();
        repaint();
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        super.paintComponent(graphics);
        Graphics2D g = (Graphics2D) graphics;
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.scale(SCALE, SCALE);
        g.translate(MARGIN, MARGIN);
        g.setStroke(new BasicStroke(1f / SCALE));
        g.setColor(Color.LIGHT_GRAY);
        g.drawRect(0, 0, ShakerWorld.WIDTH, ShakerWorld.HEIGHT);
        g.setColor(Color.GRAY);
        for (Spring spring : shaker.getSprings()) {
            g.draw(new Line2D.Float(spring.getAnchorAX(), spring.getAnchorAY(), spring.getAnchorBX(), spring.getAnchorBY()));
        }
        World world = shaker.getWorld();
        g.setColor(Color.BLACK);
        for (int i = 0; i < world.getBodyCount(); i++) {
            drawBody(g, world.getBody(i));
        }
    }

    private static void drawBody(Graphics2D g, Body b) {
        Shape shape = b.getShape();
        if (shape instanceof Circle) {
            Circle c = (Circle) shape;
            float r = c.getRadius();
            float x = b.toWorldX(c.getCenterX(), c.getCenterY());
            float y = b.toWorldY(c.getCenterX(), c.getCenterY());
            g.draw(new Ellipse2D.Float(x - r, y - r, 2 * r, 2 * r));
            // A spoke, to see the ball turn.
            g.draw(new Line2D.Float(x, y, b.toWorldX(c.getCenterX() + r, c.getCenterY()), b.toWorldY(c.getCenterX() + r, c.getCenterY())));
        } else if (shape instanceof Polygon) {
            Polygon p = (Polygon) shape;
            Path2D.Float path = new Path2D.Float();
            for (int k = 0; k < p.getVertexCount(); k++) {
                float x = b.toWorldX(p.getVertexX(k), p.getVertexY(k));
                float y = b.toWorldY(p.getVertexX(k), p.getVertexY(k));
                if (k == 0) {
                    path.moveTo(x, y);
                } else {
                    path.lineTo(x, y);
                }
            }
            path.closePath();
            g.draw(path);
        }
    }
}
