package org.emini.harness.fuzz;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;

/**
 * A loader under fuzz: how its inputs are made from a seed (in the command's JVM) and how they are
 * judged (by a {@link Checker} in the worker's). Input i of seed S depends on S and i alone.
 *
 * @param name the subcommand and the worker's target
 * @param extension of the files a finding is written to
 * @param corpus the files mutated (empty for setters)
 */
record FuzzTarget(String name, String extension, List<byte[]> corpus) {

    /** Input {@code index} of {@code seed}. */
    byte[] input(long seed, long index) {
        SplittableRandom r = Inputs.random(seed, index);
        return switch (name) {
            case "scenarios" -> TextMutator.mutate(corpus.get(r.nextInt(corpus.size())), corpus, r);
            case "phy" -> {
                byte[] out = corpus.get(r.nextInt(corpus.size()));
                for (int i = 1 + r.nextInt(4); i > 0; i--) {
                    out = ByteMutator.mutate(out, corpus, r);
                }
                yield out;
            }
            default -> SetterProgram.generate(SetterCatalog.all(), seed, index).getBytes(StandardCharsets.UTF_8);
        };
    }

    /** The worker's checker for a target (or, by class name, a Checker with a no-argument constructor). */
    static Checker checker(String name, Path schema, int ticks) throws ReflectiveOperationException {
        if (name.equals("setters")) {
            return new SetterChecker(ticks);
        }
        if (name.contains(".")) {
            return (Checker) Class.forName(name).getDeclaredConstructor().newInstance();
        }
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(schema), schema.toAbsolutePath().getParent());
        return name.equals("phy") ? new PhyChecker(loader, ticks) : new ScenarioChecker(loader, ticks);
    }
}
