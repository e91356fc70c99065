package org.emini.harness.fuzz.world;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * The fuzz loop. World i of a run is generated from (seed, i) with the profile whose turn it is
 * (general, passive, extreme, separated, smooth, scene-only, in rotation) and checked against every
 * invariant; then relation i mod 8 is checked on a world (seed, i) of the relation's profile. Each
 * violation is shrunk and written out (FindingWriter); the first of each kind and profile is shrunk
 * with the full budget, later ones of the same kind only counted and written unshrunk, so that a
 * defect met in every tenth world does not cost the whole run.
 */
public final class WorldFuzzer {
    /** The rotation of profiles for the invariant checks. */
    static final Profile[] ROTATION = {Profile.GENERAL, Profile.PASSIVE, Profile.GENERAL, Profile.EXTREME,
        Profile.SEPARATED, Profile.SMOOTH, Profile.GENERAL, Profile.SCENE};

    /**
     * What to run.
     *
     * @param seed the run's seed
     * @param worlds how many worlds
     * @param relations whether to check the relations too
     * @param shrinkBudget runs the shrinker may make per finding (0: do not shrink)
     * @param out where findings go, or null to write nothing
     */
    public record Options(long seed, int worlds, boolean relations, int shrinkBudget, Path out) {
    }

    /**
     * What a run found.
     *
     * @param worlds worlds checked
     * @param relationChecks relation checks made
     * @param seconds wall time
     * @param counts violations by kind
     * @param findings the findings, shrunk or not
     * @param files the JSON files written
     */
    public record Summary(int worlds, int relationChecks, double seconds, Map<ViolationKind, Integer> counts,
                         List<Finding> findings, List<Path> files) {
        /** Violations of every kind together. */
        public int total() {
            return counts.values().stream().mapToInt(Integer::intValue).sum();
        }
    }

    private WorldFuzzer() {
    }

    /** Runs the loop, printing one line per violation to {@code log}. */
    public static Summary run(Options o, PrintStream log) {
        long t0 = System.nanoTime();
        Map<ViolationKind, Integer> counts = new EnumMap<>(ViolationKind.class);
        Map<String, Integer> shrunkKinds = new java.util.HashMap<>();
        List<Finding> findings = new ArrayList<>();
        List<Path> files = new ArrayList<>();
        int relationChecks = 0;
        for (int i = 0; i < o.worlds(); i++) {
            List<Object[]> found = new ArrayList<>();
            Recipe r = WorldGenerator.generate(o.seed(), i, ROTATION[i % ROTATION.length]);
            for (Violation v : WorldCheck.run(r).violations()) {
                found.add(new Object[] {v, r});
            }
            if (o.relations()) {
                Relation relation = Relations.all().get(i % Relations.all().size());
                Recipe rr = WorldGenerator.generate(o.seed(), i, relation.profile(i / Relations.all().size()));
                relationChecks++;
                Violation v;
                try {
                    v = relation.check(rr);
                } catch (RuntimeException e) {
                    v = new Violation(relation.kind(), -1, "the check threw " + TickFailure.describe(e));
                }
                if (v != null) {
                    found.add(new Object[] {v, rr});
                }
            }
            for (Object[] f : found) {
                Violation v = (Violation) f[0];
                Recipe world = (Recipe) f[1];
                counts.merge(v.kind(), 1, Integer::sum);
                String key = v.kind() + "/" + world.profile + (v.kind() == ViolationKind.EXCEPTION ? Reproduction.signature(v) : "");
                int budget = shrunkKinds.merge(key, 1, Integer::sum) == 1 ? o.shrinkBudget() : 0;
                Finding finding = Finding.of(v, world, budget);
                findings.add(finding);
                log.println("world " + world.profile.name().toLowerCase() + ":" + world.index + ": " + v
                        + (budget > 0 ? "\n    shrunk (" + finding.shrinkRuns() + " runs) to " + finding.shrunk().summary() + ": "
                                + finding.shrunkViolation().message() : ""));
                if (o.out() != null) {
                    try {
                        files.add(FindingWriter.write(o.out(), finding));
                    } catch (IOException e) {
                        log.println("    cannot write the finding: " + e.getMessage());
                    }
                }
            }
        }
        return new Summary(o.worlds(), relationChecks, (System.nanoTime() - t0) / 1e9, counts, findings, files);
    }
}
