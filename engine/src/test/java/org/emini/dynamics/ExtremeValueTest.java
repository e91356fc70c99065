package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.function.Consumer;
import java.util.stream.Stream;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Finite but extreme values that the setters accept: the world either runs on with a finite state,
 * or tick() stops with its own documented error naming the body, never an internal error from deep
 * in the pipeline (the continuous pass queried the broadphase with NaN boxes) and never NaN left in
 * the world.
 */
class ExtremeValueTest {
    static Stream<Arguments> extremes() {
        Stream.Builder<Arguments> cases = Stream.builder();
        float[] values = {1e30f, -1e30f, 3.4e38f, -3.4e38f, Float.MAX_VALUE};
        for (float v : values) {
            cases.add(Arguments.of("velocity " + v, (Consumer<Scene>) s -> s.ball.setVelocity(v, v)));
            cases.add(Arguments.of("angular velocity " + v, (Consumer<Scene>) s -> s.box.setAngularVelocity(v)));
            cases.add(Arguments.of("force " + v, (Consumer<Scene>) s -> s.ball.applyForce(v, -v)));
            cases.add(Arguments.of("impulse " + v, (Consumer<Scene>) s -> s.box.applyImpulse(v, v)));
            cases.add(Arguments.of("torque " + v, (Consumer<Scene>) s -> s.box.applyTorque(v)));
            cases.add(Arguments.of("gravity " + v, (Consumer<Scene>) s -> s.world.setGravity(0f, v)));
            cases.add(Arguments.of("position " + v, (Consumer<Scene>) s -> s.ball.setPosition(v, 0f)));
            cases.add(Arguments.of("position and velocity " + v, (Consumer<Scene>) s -> {
                s.ball.setPosition(v, v);
                s.ball.setVelocity(-v, -v);
            }));
            if (v > 0f) {
                cases.add(Arguments.of("timestep " + v, (Consumer<Scene>) s -> s.world.setTimestep(v)));
                // Found by the setter fuzzer: the broadphase's displacement overflowed before the solve.
                cases.add(Arguments.of("impulse and timestep " + v, (Consumer<Scene>) s -> {
                    s.ball.applyImpulse(-v, 2f);
                    s.world.setTimestep(v);
                }));
            }
        }
        return cases.build();
    }

    /** A static ground, a landscape segment, a falling ball and a box on the ground. */
    static final class Scene {
        final World world = new World();
        final Body ball = new Body(0f, -50f, Shape.createCircle(5f), true);
        final Body box = new Body(30f, -5f, Shape.createRectangle(10f, 10f), true);

        Scene() {
            Scenes.ground(world, 0f, 400f);
            Landscape land = new Landscape();
            land.addSegment(-200f, -100f, 200f, -100f);
            world.setLandscape(land);
            world.addBody(ball);
            world.addBody(box);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("extremes")
    void anExtremeValueRunsOnOrStopsWithTheTicksOwnErrorNamingTheBody(String name, Consumer<Scene> change) {
        Scene scene = new Scene();
        change.accept(scene);
        for (int t = 0; t < 20; t++) {
            try {
                scene.world.tick();
            } catch (IllegalStateException e) {
                String m = e.getMessage();
                assertTrue(m.startsWith("World.tick: Body#") && m.contains("tick " + t), m);
                return;
            } catch (RuntimeException e) {
                fail("internal error instead of the tick's own: " + e, e);
            }
            for (int i = 0; i < scene.world.getBodyCount(); i++) {
                Body b = scene.world.getBody(i);
                float sum = b.getX() + b.getY() + b.getAngle() + b.getVelocityX() + b.getVelocityY() + b.getAngularVelocity();
                assertTrue(Float.isFinite(sum), b + " is not finite after tick " + t + " without an error");
            }
        }
    }
}
