package org.emini.harness.fuzz;

import org.emini.harness.convert.WorldToScenario;
import org.emini.harness.load.ScenarioLoader;
import org.emini.io.BuildResult;
import org.emini.io.PhyFormatException;
import org.emini.io.PhyReader;
import org.emini.io.PhyWorld;
import org.emini.io.WorldBuilder;

/**
 * An original world file both ways it is read: by the engine ({@code PhyReader}, {@code WorldBuilder},
 * a few ticks) and by the harness ({@code harness run x.phy}: the scene {@code convert} makes, loaded
 * and run as a scene). The reader must refuse a damaged file with a {@code PhyFormatException} naming
 * the byte; whatever it accepts must build and tick finitely on both paths.
 */
final class PhyChecker implements Checker {
    private final ScenarioLoader loader;
    private final int ticks;

    PhyChecker(ScenarioLoader loader, int ticks) {
        this.loader = loader;
        this.ticks = ticks;
    }

    @Override
    public Verdict check(byte[] input) {
        PhyWorld doc;
        try {
            doc = new PhyReader().read(input);
        } catch (PhyFormatException e) {
            return e.getOffset() >= 0 ? Verdict.clean("read", e.getMessage())
                    : new Verdict(Outcome.UNLOCATED, Verdict.ENGINE, "read", e.getMessage());
        } catch (RuntimeException | Error e) {
            return Verdict.thrown(Outcome.CRASH, "read", e);
        }
        Verdict engine = engine(doc);
        if (engine != null) {
            return along("engine path", engine);
        }
        return along("harness path", harness(doc));
    }

    /** The verdict with the path it was met on in its stage (both paths tick). */
    private static Verdict along(String path, Verdict v) {
        return new Verdict(v.outcome(), v.blame(), path + ": " + v.stage(), v.message());
    }

    private Verdict engine(PhyWorld doc) {
        BuildResult built;
        try {
            built = new WorldBuilder().build(doc);
        } catch (RuntimeException | Error e) {
            return Verdict.thrown(Outcome.CRASH, "build", e);
        }
        return WorldState.tick(built.getWorld(), ticks, null, null, Verdict.ENGINE, false);
    }

    private Verdict harness(PhyWorld doc) {
        String yaml;
        try {
            yaml = WorldToScenario.convert(doc, "mutant.phy", ScenarioLoader.WORLD_FILE_SECONDS).yaml();
        } catch (RuntimeException | Error e) {
            return Verdict.thrown(Outcome.CRASH, "convert", e);
        }
        ScenarioLoader.Loaded loaded;
        try {
            loaded = loader.load("mutant.phy.yaml", yaml, "mutant");
        } catch (RuntimeException | Error e) {
            return Verdict.thrown(Outcome.CRASH, "load converted", e);
        }
        if (!loaded.ok()) {
            // The engine took the file; the scene convert made of it must be one the harness takes too.
            Verdict v = ScenarioChecker.refusal(loaded.problems());
            return v.outcome() == Outcome.CLEAN
                    ? new Verdict(Outcome.CLEAN, "", "load converted", v.message()) : v;
        }
        return ScenarioChecker.run(loaded.scenario(), ticks);
    }
}
