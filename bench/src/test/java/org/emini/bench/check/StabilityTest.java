package org.emini.bench.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.bench.scene.BenchScenes;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;

/** The scene check's verdicts on hand-made poses. */
class StabilityTest {
    private static final BenchScenes SCENES = BenchScenes.open();

    private static double[] poses(Scenario s) {
        double[] p = new double[3 * s.bodies().size()];
        for (int i = 0; i < s.bodies().size(); i++) {
            p[3 * i] = s.bodies().get(i).x();
            p[3 * i + 1] = s.bodies().get(i).y();
            p[3 * i + 2] = s.bodies().get(i).state().angle();
        }
        return p;
    }

    private static Stability judge(Scenario s, double[] now) {
        return Stability.judge(s, 1, poses(s), now, new double[s.bodies().size()]);
    }

    @Test
    void aPyramidThatSettlesIsStableOneThatSlidesDriftsOneThatFallsCollapsed() {
        Scenario s = SCENES.load("bench/pyramid-20");
        double[] now = poses(s);
        assertEquals("stable", judge(s, now).verdict());
        // The whole pyramid 15 px lower (sag, or Box2D's skin the other way) is still standing.
        for (int i = 1; i < s.bodies().size(); i++) {
            now[3 * i + 1] += 15;
        }
        Stability sag = judge(s, now);
        assertEquals("stable", sag.verdict());
        assertEquals(15, sag.maxDyPx(), 1e-9);
        now[3 * 100] += 8;
        assertEquals("drifted", judge(s, now).verdict());
        now[3 * 100] += 20;
        assertEquals("collapsed", judge(s, now).verdict());
        now = poses(s);
        now[3 * 50 + 2] = 0.7;
        assertEquals("collapsed", judge(s, now).verdict());
    }

    @Test
    void rainThatLeavesTheContainerEscapedAndNonFiniteIsNamed() {
        Scenario s = SCENES.load("bench/rain-100");
        double[] now = poses(s);
        // Everyone lands on the floor (its top is y = 0).
        for (int i = 3; i < s.bodies().size(); i++) {
            now[3 * i + 1] = -10;
        }
        assertEquals("stable", judge(s, now).verdict());
        now[3 * 10 + 1] = 30;
        Stability fell = judge(s, now);
        assertEquals("escaped", fell.verdict());
        assertEquals(1, fell.escaped());
        now[3 * 11] = Double.NaN;
        assertEquals("non-finite", judge(s, now).verdict());
    }

    @Test
    void aTumblerIsJudgedInItsBoxsFrameByItsEscapesPivotAndSpeed() {
        Scenario s = SCENES.load("bench/tumbler");
        int n = s.bodies().size();
        double[] now = poses(s);
        double[] omegas = new double[n];
        omegas[1] = 0.4;
        Stability st = Stability.judge(s, 1, poses(s), now, new double[n], omegas);
        assertEquals("stable", st.verdict(), st.toString());
        assertEquals(10, st.bodySize(), 1e-9, "b is a small body's size, not the box's");
        // The box turned a quarter (about its pin): everyone inside turned with it, still inside.
        double[] turned = poses(s);
        for (int i = 1; i < n; i++) {
            double dx = now[3 * i], dy = now[3 * i + 1] + 400;
            turned[3 * i] = -dy;
            turned[3 * i + 1] = -400 + dx;
            turned[3 * i + 2] += Math.PI / 2;
        }
        assertEquals("stable", Stability.judge(s, 1, poses(s), turned, new double[n], omegas).verdict());
        // A body beyond the outer walls (270 px from the centre) escaped; one in a wall did not.
        turned[3 * 5] = 265;
        turned[3 * 5 + 1] = -400;
        assertEquals("stable", Stability.judge(s, 1, poses(s), turned, new double[n], omegas).verdict());
        turned[3 * 5] = 275;
        Stability out = Stability.judge(s, 1, poses(s), turned, new double[n], omegas);
        assertEquals("escaped", out.verdict());
        assertEquals(1, out.escaped());
        // A box 6% slow, or moved off its pin by a quarter body (2.5 px) and more.
        omegas[1] = 0.376;
        Stability slow = Stability.judge(s, 1, poses(s), now, new double[n], omegas);
        assertEquals("slowed", slow.verdict());
        assertEquals(0.06, slow.motorSpeedError(), 1e-9);
        omegas[1] = 0.4;
        now[3 * 1] += 3;
        assertEquals("stretched", Stability.judge(s, 1, poses(s), now, new double[n], omegas).verdict());
    }

    @Test
    void particlesAreCountedAndJudgedLikeRain() {
        Scenario s = SCENES.load("bench/particles-10000");
        double[] now = poses(s);
        double[] xy = {0, -5, 100, -300, -590, -1};
        Stability st = Stability.judge(s, 1, poses(s), now, new double[s.bodies().size()], null, xy, 3);
        assertEquals("stable", st.verdict());
        assertEquals(3, st.particles());
        xy[3] = 5;
        assertEquals("escaped", Stability.judge(s, 1, poses(s), now, new double[s.bodies().size()], null, xy, 3).verdict());
        xy[4] = Double.NaN;
        assertEquals("non-finite", Stability.judge(s, 1, poses(s), now, new double[s.bodies().size()], null, xy, 3).verdict());
        assertEquals(10000, Stability.moving(s));
    }
}
