package org.emini.harness.report;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.emini.harness.expect.Verdict;
import org.emini.harness.run.SceneResult;

/**
 * Writes the results as JUnit XML (one test case per scene), so CI tools list the scenes. Regressions
 * are failures, errors are errors; known failures and unsupported scenes are "skipped" with the reason,
 * because neither should turn CI red.
 */
public final class JUnitXmlWriter {
    private JUnitXmlWriter() {
    }

    /** Writes the file. */
    public static void write(Path file, List<SceneResult> results, Summary summary) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            out.write("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
            out.write(String.format(Locale.ROOT,
                    "<testsuite name=\"emini-scenarios\" tests=\"%d\" failures=\"%d\" errors=\"%d\" skipped=\"%d\" time=\"%.3f\">\n",
                    summary.total(), summary.fail(), summary.error(), summary.known() + summary.unsupported(),
                    summary.seconds()));
            for (SceneResult r : results) {
                String category = r.category() != null ? r.category() : "scenarios";
                out.write(String.format(Locale.ROOT, "  <testcase classname=\"%s\" name=\"%s\" time=\"%.3f\">\n",
                        esc("scenarios." + category), esc(r.scene()), (r.buildMillis() + r.runMillis()) / 1000));
                switch (r.status()) {
                    case FAIL -> out.write("    <failure message=\"" + esc(r.message()) + "\"/>\n");
                    case ERROR -> out.write("    <error message=\"" + esc(r.message()) + "\"/>\n");
                    case KNOWN_FAILURE -> out.write("    <skipped message=\"known failure: " + esc(r.message()) + "\"/>\n");
                    case UNSUPPORTED -> out.write("    <skipped message=\"" + esc(r.message()) + "\"/>\n");
                    default -> { }
                }
                if (!r.verdicts().isEmpty()) {
                    StringBuilder text = new StringBuilder();
                    for (Verdict v : r.verdicts()) {
                        text.append(v.passed() ? "ok   " : "FAIL ").append(v.expectation()).append(": ")
                                .append(v.detail()).append('\n');
                    }
                    out.write("    <system-out>" + esc(text.toString()) + "</system-out>\n");
                }
                out.write("  </testcase>\n");
            }
            out.write("</testsuite>\n");
        }
    }

    private static String esc(String s) {
        StringBuilder out = new StringBuilder(s.length());
        for (char c : s.toCharArray()) {
            switch (c) {
                case '&' -> out.append("&amp;");
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '"' -> out.append("&quot;");
                default -> {
                    if (c >= 0x20 || c == '\n' || c == '\t') {
                        out.append(c);
                    }
                }
            }
        }
        return out.toString();
    }
}
