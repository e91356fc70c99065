package org.emini.harness.cli;

import java.nio.file.FileSystems;
import java.nio.file.Path;
import java.nio.file.PathMatcher;
import java.util.ArrayList;
import java.util.List;
import org.emini.harness.load.ScenarioLoader;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/**
 * {@code -k PATTERN}: keeps the scenes whose id (e.g. {@code stacking/tower-10-20hz}) matches one of the
 * patterns: a glob when it holds {@code *}, {@code ?} or {@code [} ({@code stacking/*}, {@code *-60hz}),
 * else a substring ({@code pendulum}). A scene that could not be read is matched by its file path.
 */
final class SceneFilter {
    private SceneFilter() {
    }

    /** The scenes the patterns keep (all when there are none); a pattern set that keeps none is a usage error. */
    static List<ScenarioLoader.Loaded> keep(CommandSpec spec, List<ScenarioLoader.Loaded> scenes, List<String> patterns) {
        if (patterns == null || patterns.isEmpty()) {
            return scenes;
        }
        List<ScenarioLoader.Loaded> out = new ArrayList<>();
        for (ScenarioLoader.Loaded l : scenes) {
            String id = l.ok() ? l.scenario().name() : l.file().toString().replace('\\', '/');
            if (patterns.stream().anyMatch(p -> matches(p, id))) {
                out.add(l);
            }
        }
        if (out.isEmpty()) {
            throw new ParameterException(spec.commandLine(), "-k " + String.join(" -k ", patterns) + " matches none of the "
                    + scenes.size() + " scenes");
        }
        return out;
    }

    /** Whether a scene id matches a pattern (a glob with *, ? or [; else a substring). */
    static boolean matches(String pattern, String id) {
        if (pattern.chars().noneMatch(c -> c == '*' || c == '?' || c == '[')) {
            return id.contains(pattern);
        }
        // ** crosses folders as * does not; a glob that names no folder matches the scene's own name too.
        PathMatcher m = FileSystems.getDefault().getPathMatcher("glob:" + pattern);
        Path p = Path.of(id);
        return m.matches(p) || (!pattern.contains("/") && p.getFileName() != null && m.matches(p.getFileName()));
    }
}
