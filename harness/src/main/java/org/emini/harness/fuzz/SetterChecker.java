package org.emini.harness.fuzz;

import java.lang.reflect.InvocationTargetException;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * Runs a setter program on the base world, then ticks it. A refused value must come back as the
 * engine's IllegalArgumentException (or IndexOutOfBounds, IllegalState) naming the call; an accepted
 * one must leave a world that ticks without an exception and stays finite.
 */
final class SetterChecker implements Checker {
    private static final java.util.regex.Pattern CALL = java.util.regex.Pattern.compile("[A-Z]\\w*(\\.\\w+)?: ");

    private final int ticks;

    SetterChecker(int ticks) {
        this.ticks = ticks;
    }

    @Override
    public Verdict check(byte[] input) {
        List<SetterProgram.Line> lines;
        SetterWorld w;
        try {
            lines = SetterProgram.parse(new String(input, StandardCharsets.UTF_8));
            w = new SetterWorld();
        } catch (RuntimeException e) {
            return Verdict.thrown(Outcome.CRASH, "program", e);
        }
        Verdict refused = null;
        StringBuilder done = new StringBuilder();
        for (SetterProgram.Line line : lines) {
            Throwable t;
            try {
                SetterProgram.run(line, w);
                done.append(done.length() > 0 ? " then " : "").append(line.text());
                continue;
            } catch (InvocationTargetException e) {
                t = e.getCause();
            } catch (ReflectiveOperationException e) {
                return Verdict.thrown(Outcome.CRASH, "program", e);
            } catch (RuntimeException | Error e) {
                t = e;  // adding what a constructor made to the world
            }
            Verdict v = judge(line, t);
            if (v.outcome().failure()) {
                return v;
            }
            refused = v;
            done.append(done.length() > 0 ? " then " : "").append(line.text()).append(" (refused)");
        }
        Verdict bad = WorldState.tick(w.world, ticks, null, null, Verdict.ENGINE, false);
        if (bad != null) {
            return new Verdict(bad.outcome(), bad.blame(), bad.stage() + " after " + done, bad.message());
        }
        return refused != null ? refused : Verdict.accepted(done.toString());
    }

    private static Verdict judge(SetterProgram.Line line, Throwable t) {
        boolean refusal = t instanceof IllegalArgumentException || t instanceof IndexOutOfBoundsException
                || t instanceof IllegalStateException;
        if (!refusal) {
            return Verdict.thrown(Outcome.CRASH, line.text(), t);
        }
        String m = String.valueOf(t.getMessage());
        // The engine's convention: the message starts with the call (Body.setMass:) or the class (Polygon:).
        boolean named = m.contains(line.call().name()) || CALL.matcher(m).lookingAt();
        return named ? Verdict.clean(line.text(), m)
                : new Verdict(Outcome.UNLOCATED, Verdict.blame(t), line.text(), Verdict.oneLine(t));
    }
}
