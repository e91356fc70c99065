package org.emini.examples.manual;

import java.util.Vector;
import org.emini.constraint.Joint;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.shape.Shape;
import org.emini.world.World;

/**
 * The manual's "Create an application" listings (the shaker), ported with only the mechanical
 * changes of PORTING.md; each changed line keeps the original in a comment. The MIDlet and Canvas
 * classes become plain classes (no J2ME here); {@link Graphics} stands in for J2ME's.
 */
final class ShakerListing {
    private ShakerListing() {
    }

    /** The manual's GraphicsWorld: a world that draws its bodies and springs. */
    static class GraphicsWorld extends World {
        GraphicsWorld() {
        }

        public void draw(Graphics g) {
            int bodyCount = getBodyCount();
            Body[] bodies = getBodies();
            int constraintCount = getConstraintCount();
            Constraint[] constraints = getConstraints();
            g.setColor(255, 255, 255);
            g.fillRect(0, 0, g.getClipWidth(), g.getClipHeight());
            //draw bodies
            g.setColor(0, 0, 0);
            for (int i = 0; i < bodyCount; i++) {
                drawBody(g, bodies[i]);
            }
            //draw springs
            g.setColor(0, 0, 0);
            for (int i = 0; i < constraintCount; i++) {
                if (constraints[i] instanceof Spring) {
                    Spring spring = (Spring) constraints[i];
                    // spring.getPoint1().xAsInt(), ... getPoint2().yAsInt()
                    g.drawLine((int) spring.getAnchorAX(), (int) spring.getAnchorAY(),
                               (int) spring.getAnchorBX(), (int) spring.getAnchorBY());
                }
            }
        }

        private void drawBody(Graphics g, Body b) {
            float[] positions = b.getVertices();          // b.getVerticesFX()
            if (positions.length == 2) {                  // positions.length == 1: a circle
                // (the radius lines are lost from the manual: the vertex's distance from the centre)
                int radius = (int) Math.hypot(positions[0] - b.getX(), positions[1] - b.getY());
                g.drawArc((int) b.getX() - radius,        // b.positionFX().xAsInt() - radius
                          (int) b.getY() - radius,
                          radius * 2, radius * 2, 0, 360);
            } else {
                //draw the polygon
                int n = positions.length / 2;             // positions.length
                for (int i = 0; i < n - 1; i++) {
                    g.drawLine((int) positions[2 * i], (int) positions[2 * i + 1],
                               (int) positions[2 * i + 2], (int) positions[2 * i + 3]);
                }
                //draw the final segment
                g.drawLine((int) positions[2 * n - 2], (int) positions[2 * n - 1],
                           (int) positions[0], (int) positions[1]);
            }
        }
    }

    /** The manual's SimulationCanvas, less the J2ME canvas: the box elements and the keys. */
    static class SimulationCanvas {
        static final int UP = 1;
        static final int DOWN = 6;
        static final int LEFT = 2;
        static final int RIGHT = 5;
        private static final int force = 64;
        private final Vector<Body> boxElements = new Vector<>();
        GraphicsWorld world;

        public void setWorld(GraphicsWorld world) {
            this.world = world;
        }

        public void addBoxElement(Body b) {
            boxElements.addElement(b);
        }

        protected void keyPressed(int action) {
            switch (action) {
                case UP:
                    shake(0, -force);                     // shake(FXVector.newVector(0, -force))
                    break;
                case DOWN:
                    shake(0, force);
                    break;
                case LEFT:
                    shake(-force, 0);
                    break;
                case RIGHT:
                    shake(force, 0);
                    break;
                default:
                    break;
            }
        }

        private void shake(float x, float y) {
            for (int i = 0; i < boxElements.size(); i++) {
                Body boxElement = boxElements.elementAt(i);
                // boxElement.applyAcceleration(vector, World.getTimestepFX());
                boxElement.applyAcceleration(x, y, world.getTimestep());
            }
        }
    }

    /** The manual's Shaker MIDlet: createShakerWorld. */
    static final class Shaker {
        GraphicsWorld shakerWorld;
        final SimulationCanvas simulationCanvas = new SimulationCanvas();
        private final int width;
        private final int height;

        Shaker(int width, int height) {
            this.width = width;                           // simulationCanvas.getWidth()
            this.height = height;
            createShakerWorld();
            simulationCanvas.setWorld(shakerWorld);
        }

        private void createShakerWorld() {
            shakerWorld = new GraphicsWorld();
            // shakerWorld.setDampingFX((FXUtil.ONE_FX * 995) / 1000): a retention of 0.995
            shakerWorld.setDampingLateral(1f - 0.995f);
            shakerWorld.setDampingRotational(1f - 0.995f);

            final boolean isDynamic = true;
            final boolean isStatic = false;
            final boolean fixedJoint = true;
            final int calculateDistance = -1;

            int centerx = width / 2;
            int centery = height / 2;

            Shape boxRectangle = Shape.createRectangle(width, 10);
            boxRectangle.setMass(10);
            Shape ball = Shape.createCircle(10);
            ball.setElasticityPercent(80);                // ball.setElasticity(80)
            Shape smallbox = Shape.createRectangle(2, 2);

            Body upper = new Body(centerx, centery - width / 2, boxRectangle, isDynamic);
            Body lower = new Body(centerx, centery + width / 2, boxRectangle, isDynamic);
            Body left = new Body(centerx - width / 2, centery, boxRectangle, isDynamic);
            left.setAngleDegrees(90);                     // left.setRotationDeg(90)
            Body right = new Body(centerx + width / 2, centery, boxRectangle, isDynamic);
            right.setAngleDegrees(90);
            shakerWorld.addBody(upper);
            shakerWorld.addBody(lower);
            shakerWorld.addBody(left);
            shakerWorld.addBody(right);

            // new Joint(upper, left, FXVector.newVector(-width / 2, 0), FXVector.newVector(-width / 2, 0), fixedJoint)
            Joint upperLeft = new Joint(upper, left, -width / 2, 0, -width / 2, 0, fixedJoint);
            Joint upperRight = new Joint(upper, right, width / 2, 0, -width / 2, 0, fixedJoint);
            Joint lowerLeft = new Joint(lower, left, -width / 2, 0, width / 2, 0, fixedJoint);
            Joint lowerRight = new Joint(lower, right, width / 2, 0, width / 2, 0, fixedJoint);
            shakerWorld.addConstraint(upperLeft);
            shakerWorld.addConstraint(upperRight);
            shakerWorld.addConstraint(lowerLeft);
            shakerWorld.addConstraint(lowerRight);
            upper.addCollisionLayer(1);
            lower.addCollisionLayer(1);
            left.addCollisionLayer(1);
            right.addCollisionLayer(1);

            // (the anchor's creation is lost from the manual: a static body at the origin)
            Body anchor = new Body(0, 0, smallbox, isStatic);
            shakerWorld.addBody(anchor);
            // new Spring(anchor, upper, FXVector.newVector(centerx, 0), new FXVector(), calculateDistance)
            Spring upperSpring = new Spring(anchor, upper, centerx, 0, 0, 0, calculateDistance);
            upperSpring.setCoefficient(120);
            Spring lowerSpring = new Spring(anchor, lower, centerx, height, 0, 0, calculateDistance);
            lowerSpring.setCoefficient(120);
            Spring rightSpring = new Spring(anchor, right, 0, centery, 0, 0, calculateDistance);
            rightSpring.setCoefficient(100);
            Spring leftSpring = new Spring(anchor, left, width, centery, 0, 0, calculateDistance);
            leftSpring.setCoefficient(100);
            shakerWorld.addConstraint(upperSpring);
            shakerWorld.addConstraint(lowerSpring);
            shakerWorld.addConstraint(leftSpring);
            shakerWorld.addConstraint(rightSpring);

            simulationCanvas.addBoxElement(upper);
            simulationCanvas.addBoxElement(lower);
            simulationCanvas.addBoxElement(right);
            simulationCanvas.addBoxElement(left);
        }
    }
}
