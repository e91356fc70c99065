package org.emini.examples.game;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.geom.AffineTransform;
import java.awt.geom.Rectangle2D;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import org.emini.dynamics.Body;

/**
 * The manual's SimulationCanvas for the game, in Swing: ticks in real time, follows the sprite,
 * arrow keys walk (pressed: move, released: stop driving) and jump.
 */
final class GameWindow extends JPanel {
    private static final long serialVersionUID = 1L;
    private static final int WIDTH = 640;
    private static final int HEIGHT = 400;

    private final transient PhysicsGame game;

    private GameWindow(PhysicsGame game) {
        this.game = game;
        setPreferredSize(new Dimension(WIDTH, HEIGHT));
        setBackground(Color.WHITE);
        setFocusable(true);
        addKeyListener(new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                switch (e.getKeyCode()) {
                    case KeyEvent.VK_RIGHT:
                        game.getControl().move(1);
                        break;
                    case KeyEvent.VK_LEFT:
                        game.getControl().move(-1);
                        break;
                    case KeyEvent.VK_UP:
                        game.getControl().jump(PhysicsGame.JUMP);
                        break;
                    default:
                        break;
                }
            }

            @Override
            public void keyReleased(KeyEvent e) {
                if (e.getKeyCode() == KeyEvent.VK_RIGHT || e.getKeyCode() == KeyEvent.VK_LEFT) {
                    game.getControl().move(0);
                }
            }
        });
    }

    /** Opens the window and starts ticking at the world's rate. */
    static void open(PhysicsGame game) {
        SwingUtilities.invokeLater(() -> {
            JFrame frame = new JFrame("Emini: the manual's physics game (arrows walk, up jumps)");
            GameWindow panel = new GameWindow(game);
            frame.setDefaultCloseOperation(JFrame.EXIT_ON_CLOSE);
            frame.add(panel);
            frame.pack();
            frame.setVisible(true);
            panel.requestFocusInWindow();
            int millis = Math.max(1, Math.round(1000f * game.getWorld().getTimestep()));
            new Timer(millis, e -> {
                game.tick();
                panel.repaint();
            }).start();
        });
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        super.paintComponent(graphics);
        Graphics2D g = (Graphics2D) graphics;
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        Body sprite = game.getSprite();
        AffineTransform screen = g.getTransform();
        // The camera follows the sprite, as the manual's paint() translates.
        g.translate(-sprite.getX() + getWidth() / 2.0, -sprite.getY() + getHeight() / 2.0);
        g.setColor(new Color(0xFFF3C4));
        g.fill(new Rectangle2D.Float(GameLevel.GOAL_X, -200, GameLevel.RIGHT_WALL - GameLevel.GOAL_X, GameLevel.FLOOR + 200));
        game.getWorld().draw(g);
        g.setColor(Color.RED);
        g.fill(new Rectangle2D.Float(sprite.getX() - 10, sprite.getY() - 15, 20, 30));
        g.setTransform(screen);
        g.setColor(Color.BLACK);
        g.drawString(game.isWon() ? "goal reached" : "reach the yellow area", 10, 20);
    }
}
