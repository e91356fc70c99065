package org.emini.harness.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.emini.harness.convert.ScenarioToWorld;
import org.emini.harness.convert.WorldToScenario;
import org.emini.harness.load.IoText;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioLoader;
import org.emini.io.PhyFormatException;
import org.emini.io.PhyReader;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code convert FILE}: an original world file (.phy, .world) to a scene file, or a scene file
 * (.yaml, .yml, .json) back to a world file where the format allows. What does not carry over is
 * printed (and written as comments at the top of a scene).
 */
@Command(name = "convert", mixinStandardHelpOptions = true,
        description = {"Converts an original world file (.phy, .world) to a scene file, or a scene file "
                + "(.yaml, .yml, .json) to a world file (version 10).",
            "Prints what the target format cannot hold; exit status 0 when converted, 1 when the input is invalid."})
final class ConvertCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Parameters(paramLabel = "FILE", description = "The file to convert.")
    Path input;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE",
            description = "Where to write (default: FILE with the extension .yaml or .phy, in the same folder).")
    Path output;

    @Option(names = "--duration", paramLabel = "SECONDS", defaultValue = "30",
            description = "Run duration of a converted scene (default: ${DEFAULT-VALUE} s, 600 ticks at 20 ticks/s).")
    double duration;

    @Override
    public Integer call() {
        String file = input.getFileName().toString();
        String lower = file.toLowerCase(Locale.ROOT);
        boolean scene = lower.endsWith(".yaml") || lower.endsWith(".yml") || lower.endsWith(".json");
        try {
            return scene ? toWorld(file) : toScene(file);
        } catch (PhyFormatException e) {
            System.err.println(input + ": not a valid world file: " + e.getMessage());
            return 1;
        } catch (IOException e) {
            // A missing or unreadable input (or output) is the command's failure, not the file's content.
            System.err.println("harness convert: " + IoText.describe(e));
            return ExitStatus.IO;
        }
    }

    private int toScene(String file) throws IOException {
        if (!(duration > 0)) {
            System.err.println("--duration must be > 0, was " + duration);
            return 1;
        }
        PhyWorld doc;
        try (var in = Files.newInputStream(input)) {
            doc = new PhyReader().read(in);
        }
        WorldToScenario.Result r = WorldToScenario.convert(doc, file, duration);
        Path out = output != null ? output : sibling(file, ".yaml");
        Files.writeString(out, r.yaml());
        report(out, r.notConverted(), r.approximated());
        return 0;
    }

    private int toWorld(String file) throws IOException {
        ScenarioLoader.Loaded loaded = library.loader().load(input);
        if (!loaded.ok()) {
            for (Problem p : loaded.problems()) {
                System.err.println(p);
            }
            return 1;
        }
        ScenarioToWorld.Result r = ScenarioToWorld.convert(loaded.scenario());
        Path out = output != null ? output : sibling(file, ".phy");
        Files.write(out, new PhyWriter().write(r.world()));
        report(out, r.notConverted(), r.approximated());
        return 0;
    }

    private Path sibling(String file, String extension) {
        int dot = file.lastIndexOf('.');
        String stem = dot > 0 ? file.substring(0, dot) : file;
        Path dir = input.toAbsolutePath().getParent();
        return dir.resolve(stem + extension);
    }

    private void report(Path out, List<String> notConverted, List<String> approximated) {
        System.out.println(input + " -> " + out + ": " + notConverted.size() + " not converted, " + approximated.size()
                + " approximated");
        for (String s : notConverted) {
            System.out.println("  not converted: " + s);
        }
        for (String s : approximated) {
            System.out.println("  approximated: " + s);
        }
    }
}
