package org.emini.examples.manual;

import java.io.IOException;
import java.io.InputStream;
import java.util.Vector;
import org.emini.constraint.Motor;
import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.dynamics.SolverStep;
import org.emini.examples.game.GameLevel;
import org.emini.examples.game.PhysicsGame;
import org.emini.io.WorldBuilder;
import org.emini.shape.Shape;
import org.emini.shape.ShapeSet;
import org.emini.world.World;

/**
 * The manual's "Physics Game" listings, ported with only the mechanical changes of PORTING.md;
 * each changed line keeps the original in a comment. J2ME's images are plain objects here.
 */
final class GameListing {
    private GameListing() {
    }

    /** The manual's GraphicsWorld: wraps a loaded world. */
    static class GraphicsWorld extends World {
        GraphicsWorld(World w) {
            super(w);
        }

        public void draw(Graphics g, int width, int height) {
            int bodyCount = getBodyCount();
            Body[] bodies = getBodies();

            g.setColor(0x000000);
            for (int i = 0; i < bodyCount; i++) {
                drawBody(g, bodies[i]);
            }
            drawLandscape(g);
        }

        private void drawBody(Graphics g, Body b) {
            Object image = ((GraphicsShapeSet) getShapeSet()).getImage(b);
            if (image != null) {
                g.drawArc((int) b.getX(), (int) b.getY(), 1, 1, 0, 360);   // g.drawRegion(image, ...)
            }
        }

        private void drawLandscape(Graphics g) {
            for (int i = 0; i < getLandscape().getSegmentCount(); i++) {
                g.drawLine((int) getLandscape().getStartX(i), (int) getLandscape().getStartY(i),
                           (int) getLandscape().getEndX(i), (int) getLandscape().getEndY(i));
            }
        }
    }

    /** The manual's GraphicsShapeSet: one image per shape id. */
    static class GraphicsShapeSet extends ShapeSet {
        private final Vector<Object> images = new Vector<>();

        public void registerImage(Object image, int index) {
            images.setSize(Math.max(images.size(), index + 1));
            if (index < images.size()) {
                images.setElementAt(image, index);
            }
        }

        public Object getImage(Body b) {
            int id = b.getShape().getId();                // b.shape().getId()
            Object image = id >= 0 && id < images.size() ? images.elementAt(id) : null;
            if (image == null) {
                return null;
            }
            return image;
        }
    }

    /** The manual's SpriteControl: a motor that walks and jumps. */
    static class SpriteControl extends Motor {
        private float targetSpeedFX = 0;
        private float jumpSpeedFX = 0;
        private float spriteForceFX = 20;                 // FXUtil.ONE_FX * 20
        private final World world;

        SpriteControl(Body body, World world) {
            super(body, 0, 0, 1000);                      // super(body, 0, 0, 0); setRotation(false)
            this.world = world;                           // (the manual's world field)
        }

        public void move(int target) {
            targetSpeedFX = target * spriteForceFX;
            setTargetVelocity(targetSpeedFX, 0);          // setParameter(targetSpeedFX, 0, false)
        }

        public void jump(int factor) {
            boolean canJump = false;
            Body body = getBody();                        // the field body
            Contact[] contacts = world.getContactsForBody(body);
            for (int i = 0; !canJump && i < contacts.length && contacts[i] != null; i++) {
                if (contacts[i].getBodyA() == body) {     // contacts[i].body1() == body
                    // contacts[i].getContactPosition1().yFX > FXUtil.ONE_FX * 12 (relative to body1)
                    canJump = contacts[i].isTouching() && contacts[i].getPointY(0) - body.getY() > 12;
                } else if (contacts[i].getBodyB() == body) {
                    canJump = contacts[i].isTouching() && contacts[i].getPointY(0) - body.getY() > 12;
                }
            }
            if (canJump) {
                jumpSpeedFX = -spriteForceFX * factor;
            }
        }

        public void setForce(float forceFX) {
            spriteForceFX = forceFX;
        }

        boolean jumpPending() {
            return jumpSpeedFX != 0;
        }

        @Override
        public void prepare(SolverStep step) {            // precalculate()
            if (jumpSpeedFX != 0) {
                // FXVector jump = new FXVector(0, jumpSpeedFX); body.applyAcceleration(jump, FXUtil.ONE_FX);
                getBody().applyAcceleration(0, jumpSpeedFX, 1);
                jumpSpeedFX = 0;
            }
            super.prepare(step);                          // super.precalculate()
        }
    }

    /** The manual's PhysicsGame MIDlet: createWorld. */
    static final class Game {
        static Shape spriteRectangle = Shape.createRectangle(20, 30);
        GraphicsWorld world;
        Body sprite;
        SpriteControl control;

        void createWorld() throws IOException {
            spriteRectangle.setFrictionPercent(98);       // setFriction(98)
            spriteRectangle.setElasticityPercent(0);      // setElasticity(0)
            // PhysicsFileReader reader = new PhysicsFileReader("game world test");
            try (InputStream reader = PhysicsGame.class.getResourceAsStream(GameLevel.RESOURCE)) {
                // new GraphicsWorld(World.loadWorld(reader))
                world = new GraphicsWorld(WorldBuilder.loadWorld(reader, null).getWorld());
            }
            world.setShapeSet(new GraphicsShapeSet());    // "uses GraphicShapeSet instead of the default"
            sprite = new Body(100, 100, spriteRectangle, true);
            sprite.setRotatable(false);
            world.addBody(sprite);
            control = new SpriteControl(sprite, world);
            world.addConstraint(control);
        }
    }
}
