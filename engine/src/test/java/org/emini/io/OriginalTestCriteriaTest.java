package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The original's own tests of its test worlds (format document section 7, copied here): each world
 * is run for the test's ticks with an event listener, and each criterion names an event (its index
 * in the file), whether it must or must not occur, and an inclusive tick range (tick 0 is the first
 * tick()).
 */
class OriginalTestCriteriaTest {
    static Stream<Arguments> criteria() {
        return Stream.of(
                Arguments.of("test_basic.world", 1, "e0 occurs 0-1; e0 never 2-100"),
                Arguments.of("BoxTunnelTest.world", 400, "e0 never 0-400"),
                Arguments.of("CirclePolyCollisionTest.world", 40, "e0 occurs 0-40"),
                Arguments.of("ElasticityTest.world", 500, "e0 never 0-1000"),
                Arguments.of("FixJointTest.world", 100, "e0 never 0-80; e1 never 0-80; e2 never 0-80; e3 occurs 70-80"),
                Arguments.of("LandscapeFacesTest.world", 60,
                        "e0 occurs 0-60; e2 occurs 0-60; e4 occurs 0-60; e6 occurs 0-60; e1 never 0-60; e3 never 0-60; "
                                + "e5 never 0-60"),
                Arguments.of("PerformanceTest.world", 200, "e0 never 0-20"),
                Arguments.of("StackTest5.world", 4000, "e0 never 0-4000; e1 never 0-4000"));
    }

    @ParameterizedTest(name = "{0}: {2}")
    @MethodSource("criteria")
    void theOriginalsCriteriaHold(String file, int ticks, String criteria) throws Exception {
        BuildResult r = new WorldBuilder().build(ReferenceWorlds.read(file));
        World world = r.getWorld();
        int events = r.getDocument().getEvents().size();
        assertEquals(events, world.getEventCount(), file + ": every event is built " + r.getUnsupported());
        List<List<Integer>> fired = new ArrayList<>();
        for (int i = 0; i < events; i++) {
            fired.add(new ArrayList<>());
        }
        int[] tick = {0};
        world.setPhysicsEventListener((event, parameter) -> {
            for (int i = 0; i < events; i++) {
                if (r.getEvent(i) == event && !fired.get(i).contains(tick[0])) {
                    fired.get(i).add(tick[0]);
                }
            }
        });
        for (tick[0] = 0; tick[0] < ticks; tick[0]++) {
            world.tick();
        }
        for (String criterion : criteria.split("; ")) {
            String[] p = criterion.split(" ");
            int event = Integer.parseInt(p[0].substring(1));
            String[] range = p[2].split("-");
            int from = Integer.parseInt(range[0]);
            int to = Integer.parseInt(range[1]);
            boolean occurred = fired.get(event).stream().anyMatch(t -> t >= from && t <= to);
            assertEquals(p[1].equals("occurs"), occurred, file + ": " + criterion + "; fired at ticks " + fired.get(event));
        }
        assertTrue(fired.stream().allMatch(l -> l.stream().allMatch(t -> t < ticks)));
    }
}
