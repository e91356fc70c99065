package org.emini.flavour;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

/**
 * The build step that writes a flavour's sources: {@code Generate SOURCE_ROOT OUTPUT_ROOT} rewrites every
 * {@code .java} file under the source root with {@link DoubleFlavour} into the same path under the
 * output root. A file is written only when its text changed (so the compiler's staleness check still
 * works), and generated files whose source is gone are deleted.
 */
public final class Generate {
    private Generate() {
    }

    /**
     * Runs the generator.
     *
     * @param args the source root and the output root
     * @throws IOException when a file cannot be read or written
     * @throws IllegalArgumentException for wrong arguments or source the rules cannot carry over (the
     *     build runs this in Maven's JVM, so it throws rather than exits)
     */
    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            throw new IllegalArgumentException("usage: Generate SOURCE_ROOT OUTPUT_ROOT");
        }
        int written = generate(Path.of(args[0]), Path.of(args[1]));
        System.out.println("double flavour: " + args[0] + " -> " + args[1] + " (" + written + " files written)");
    }

    /**
     * Rewrites a source tree.
     *
     * @param sourceRoot the float flavour's source root
     * @param outputRoot where the double flavour's source goes
     * @return how many files were written (changed or new)
     * @throws IOException when a file cannot be read or written
     */
    public static int generate(Path sourceRoot, Path outputRoot) throws IOException {
        if (!Files.isDirectory(sourceRoot)) {
            throw new IllegalArgumentException("no source directory " + sourceRoot.toAbsolutePath());
        }
        List<Path> sources;
        try (Stream<Path> walk = Files.walk(sourceRoot)) {
            sources = walk.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
        Set<Path> wanted = new HashSet<>();
        int written = 0;
        for (Path source : sources) {
            Path relative = sourceRoot.relativize(source);
            Path target = outputRoot.resolve(relative.toString());
            wanted.add(target.toAbsolutePath().normalize());
            String text = DoubleFlavour.transform(Files.readString(source, StandardCharsets.UTF_8), source.toString());
            String generated = "// Generated from " + relative.toString().replace('\\', '/')
                + " by org.emini.flavour.DoubleFlavour: edit the float source, not this file.\n" + text;
            if (!Files.exists(target) || !Files.readString(target, StandardCharsets.UTF_8).equals(generated)) {
                Files.createDirectories(target.getParent());
                Files.writeString(target, generated, StandardCharsets.UTF_8);
                written++;
            }
        }
        if (Files.isDirectory(outputRoot)) {
            try (Stream<Path> walk = Files.walk(outputRoot)) {
                walk.filter(p -> p.toString().endsWith(".java") && !wanted.contains(p.toAbsolutePath().normalize()))
                    .forEach(Generate::delete);
            }
        }
        return written;
    }

    private static void delete(Path p) {
        try {
            Files.delete(p);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
