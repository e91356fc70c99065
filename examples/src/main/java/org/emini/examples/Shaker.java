package org.emini.examples;

import java.io.PrintStream;
import java.util.Locale;

/**
 * The manual's shaker example. {@code Shaker} opens a window (arrow keys shake the box);
 * {@code Shaker --headless N} runs N ticks with a scripted shaking instead and prints the state.
 */
public final class Shaker {
    private Shaker() {
    }

    /**
     * Runs the example.
     *
     * @param args none for the window, or {@code --headless N}
     */
    public static void main(String[] args) {
        if (args.length >= 1 && args[0].equals("--headless")) {
            int ticks = args.length > 1 ? Integer.parseInt(args[1]) : 400;
            runHeadless(ticks, System.out);
        } else if (args.length == 0) {
            ShakerWindow.open(new ShakerWorld());
        } else {
            System.err.println("usage: Shaker [--headless TICKS]");
            System.exit(2);
        }
    }

    /**
     * Runs the shaker without a window and prints its state every 50 ticks and at the end.
     *
     * @param ticks how many ticks to run
     * @param out where to print
     * @return the world after the run
     */
    public static ShakerWorld runHeadless(int ticks, PrintStream out) {
        ShakerWorld shaker = new ShakerWorld();
        out.println("shaker: 4 bars on fixed joints, 9 balls, 4 springs; 20 ticks/s, 10 iterations");
        out.println(" tick   box x    box y   tilt(rad)  corner gap  balls in  spring tension (up, down, right, left)   energy");
        float worstGap = 0f;
        float worstAngle = 0f;
        for (int t = 0; t < ticks; t++) {
            float[] a = ShakerWorld.scriptedShake(t);
            shaker.shake(a[0], a[1]);
            shaker.tick();
            worstGap = Math.max(worstGap, shaker.widestCornerGap());
            worstAngle = Math.max(worstAngle, shaker.worstCornerAngleError());
            if ((t + 1) % 50 == 0 || t == ticks - 1) {
                float[] c = shaker.boxCentre();
                float[] s = shaker.springTensions();
                out.println(String.format(Locale.ROOT, "%5d %8.2f %8.2f %10.5f %10.4f %7d     %8.1f %8.1f %8.1f %8.1f   %10.1f",
                    t + 1, c[0], c[1], shaker.boxAngle(), shaker.widestCornerGap(), shaker.ballsInside(),
                    s[0], s[1], s[2], s[3], shaker.kineticEnergy()));
            }
        }
        out.println(String.format(Locale.ROOT, "widest corner gap in the run %.4f px, largest corner angle error %.5f rad",
            worstGap, worstAngle));
        return shaker;
    }
}
