package org.emini.harness.fuzz.world;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code worlds}: the world fuzzer. Generates seeded random worlds from every engine feature, checks
 * the invariants after every tick and the metamorphic relations, shrinks each violation and writes it
 * out. The {@code worlds} subcommand of {@code harness fuzz}.
 */
@Command(name = "worlds", mixinStandardHelpOptions = true,
        description = {"Fuzzes the engine with seeded random worlds: invariants every tick, metamorphic relations,",
            "violations shrunk and written as scene files or world descriptions (harness/README.md, World fuzzer).",
            "Exit status 1 when a world violated something (or a replayed finding still does)."})
public final class WorldFuzzCommand implements Callable<Integer> {
    @Option(names = "--worlds", paramLabel = "N", description = "Worlds to generate (default ${DEFAULT-VALUE}).")
    int worlds = 200;

    @Option(names = "--seed", paramLabel = "S", description = "The run's seed (default ${DEFAULT-VALUE}).")
    long seed = 1;

    @Option(names = "--no-relations", negatable = true, description = "Skip the metamorphic relations.")
    boolean relations = true;

    @Option(names = "--shrink", paramLabel = "RUNS", description = "Runs the shrinker may make per finding (default ${DEFAULT-VALUE}; 0: none).")
    int shrink = 150;

    @Option(names = "--reports", paramLabel = "DIR", description = "Where findings go (default ${DEFAULT-VALUE}).")
    Path reports = Path.of("reports", "fuzz", "worlds");

    @Option(names = "--only", paramLabel = "PROFILE:INDEX", description = "Check one generated world (invariants and its profile's relations).")
    String only;

    @Option(names = "--replay", paramLabel = "FILE", description = "Check a written finding (its .json) again.")
    List<Path> replay;

    @Override
    public Integer call() throws IOException {
        PrintStream out = System.out;
        if (replay != null) {
            return replay(out);
        }
        if (only != null) {
            return only(out);
        }
        WorldFuzzer.Summary s = WorldFuzzer.run(new WorldFuzzer.Options(seed, worlds, relations, shrink, reports), out);
        out.printf(Locale.ROOT, "world fuzzer, seed %d: %d worlds and %d relation checks in %.1f s (%.1f worlds/s)%n",
                seed, s.worlds(), s.relationChecks(), s.seconds(), s.worlds() / s.seconds());
        for (Map.Entry<ViolationKind, Integer> e : s.counts().entrySet()) {
            out.printf("  %-28s %d%n", e.getKey().label(), e.getValue());
        }
        out.println(s.total() == 0 ? "no violations" : s.total() + " violations; findings in " + reports);
        return s.total() == 0 ? 0 : 1;
    }

    private int replay(PrintStream out) throws IOException {
        int still = 0;
        for (Path file : replay) {
            JsonObject o = JsonParser.parseString(Files.readString(file, StandardCharsets.UTF_8)).getAsJsonObject();
            Recipe r = Recipe.fromJson(o.get("recipe").toString());
            ViolationKind kind = ViolationKind.valueOf(o.get("kind").getAsString());
            Violation v = Reproduction.find(r, new Violation(kind, o.get("tick").getAsInt(), o.get("shrunkViolation").getAsString()));
            out.println(file + ": " + (v == null ? "no longer violates " + kind.label() : "still: " + v));
            still += v == null ? 0 : 1;
        }
        return still == 0 ? 0 : 1;
    }

    private int only(PrintStream out) {
        String[] p = only.split(":");
        Profile profile = Profile.valueOf(p[0].toUpperCase(Locale.ROOT));
        Recipe r = WorldGenerator.generate(seed, Integer.parseInt(p[1]), profile);
        out.println(r.summary());
        int found = 0;
        for (Violation v : WorldCheck.run(r).violations()) {
            out.println("  " + v);
            found++;
        }
        for (Relation relation : Relations.all()) {
            if (relation.profile(0) == profile || relation.profile(1) == profile) {
                Violation v = relation.check(r);
                out.println("  " + relation.kind().label() + ": " + (v == null ? "holds" : v.message()));
                found += v == null ? 0 : 1;
            }
        }
        return found == 0 ? 0 : 1;
    }
}
