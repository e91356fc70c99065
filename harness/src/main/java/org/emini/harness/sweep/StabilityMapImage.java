package org.emini.harness.sweep;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * Draws a family's stability maps as one SVG, the engines side by side (Emini left, pymunk right): the
 * parameter's values down, ticks per second across, each cell coloured by its verdict and labelled
 * with it (stable, NaN, energy growth, tunnelling, penetration, collapse; grey when not run or
 * unsupported). Plain SVG written here: a table of coloured cells needs no charting library.
 */
public final class StabilityMapImage {
    private static final int CELL_W = 54;
    private static final int CELL_H = 24;
    private static final int LABEL_W = 86;
    private static final int GAP = 40;

    private StabilityMapImage() {
    }

    /** The colour and short label of a verdict. */
    public static String[] style(String verdict) {
        return switch (verdict) {
            case "stable" -> new String[] {"#b7e4c7", "ok"};
            case "NaN" -> new String[] {"#d7263d", "NaN"};
            case "energy growth" -> new String[] {"#f46036", "E grows"};
            case "energy error" -> new String[] {"#ffe08a", "E error"};
            case "tunnelling" -> new String[] {"#f4a6a6", "tunnel"};
            case "penetration" -> new String[] {"#f7b267", "overlap"};
            case "collapse" -> new String[] {"#e8a0bf", "collapse"};
            case "error" -> new String[] {"#9e9e9e", "error"};
            default -> new String[] {"#e8e8e8", "n/a"};
        };
    }

    /**
     * Writes the image.
     *
     * @param file the SVG file
     * @param family the family
     * @param rates ticks per second (columns)
     * @param iterations solver iterations used
     * @param maps one per engine, drawn left to right
     */
    public static void write(Path file, StabilityFamily family, List<Integer> rates, int iterations,
                             List<StabilityMap.Map> maps) throws IOException {
        List<Double> values = family.values();
        int panelW = LABEL_W + rates.size() * CELL_W;
        int width = Math.max(420, maps.size() * panelW + (maps.size() - 1) * GAP + 20);
        int top = 58;
        int height = top + 40 + values.size() * CELL_H + 70;
        StringBuilder svg = new StringBuilder();
        svg.append(String.format(Locale.ROOT,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\""
                        + " font-family=\"sans-serif\" font-size=\"11\">%n", width, height, width, height));
        svg.append(String.format(Locale.ROOT, "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>%n", width, height));
        svg.append(String.format(Locale.ROOT, "<text x=\"10\" y=\"18\" font-size=\"14\" font-weight=\"bold\">%s</text>%n",
                esc(family.name() + ": " + family.parameter())));
        svg.append(String.format(Locale.ROOT, "<text x=\"10\" y=\"36\" fill=\"#555\">%s</text>%n",
                esc("rows: parameter value; columns: ticks per second; " + iterations + " iterations")));
        for (int m = 0; m < maps.size(); m++) {
            StabilityMap.Map map = maps.get(m);
            int x0 = 10 + m * (panelW + GAP);
            svg.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\" font-size=\"13\" font-weight=\"bold\">%s</text>%n",
                    x0, top, esc(map.engine())));
            int y0 = top + 16;
            for (int c = 0; c < rates.size(); c++) {
                svg.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" fill=\"#333\">%d</text>%n",
                        x0 + LABEL_W + c * CELL_W + CELL_W / 2, y0 + 12, rates.get(c)));
            }
            y0 += 18;
            if (map.cells().isEmpty()) {
                svg.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\" fill=\"#777\">%s</text>%n", x0, y0 + 16,
                        esc(map.note().isEmpty() ? "not run" : abbreviate(map.note(), 90))));
                continue;
            }
            for (int r = 0; r < values.size(); r++) {
                double v = values.get(r);
                int y = y0 + r * CELL_H;
                svg.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\" text-anchor=\"end\" fill=\"#333\">%s</text>%n",
                        x0 + LABEL_W - 6, y + CELL_H / 2 + 4, esc(label(v))));
                for (int c = 0; c < rates.size(); c++) {
                    int rate = rates.get(c);
                    StabilityMap.Cell cell = map.cells().stream().filter(x -> x.value() == v && x.rate() == rate)
                            .findFirst().orElse(null);
                    String verdict = cell == null ? "not run" : cell.verdict();
                    String[] st = style(verdict);
                    int x = x0 + LABEL_W + c * CELL_W;
                    svg.append(String.format(Locale.ROOT,
                            "<g><title>%s</title><rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"%s\" stroke=\"white\"/>"
                                    + "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" font-size=\"10\">%s</text></g>%n",
                            esc(verdict + (cell != null && !cell.detail().isEmpty() ? ": " + cell.detail() : "")),
                            x, y, CELL_W, CELL_H, st[0], x + CELL_W / 2, y + CELL_H / 2 + 4, esc(st[1])));
                }
            }
        }
        int ly = top + 40 + values.size() * CELL_H + 26;
        int lx = 10;
        for (String v : List.of("stable", "NaN", "energy growth", "energy error", "tunnelling", "penetration", "collapse", "error", "unsupported")) {
            String[] st = style(v);
            svg.append(String.format(Locale.ROOT, "<rect x=\"%d\" y=\"%d\" width=\"12\" height=\"12\" fill=\"%s\"/>"
                    + "<text x=\"%d\" y=\"%d\">%s</text>%n", lx, ly, st[0], lx + 16, ly + 10, esc(v)));
            lx += 16 + 7 * v.length() + 14;
            if (lx > width - 90) {
                lx = 10;
                ly += 18;
            }
        }
        svg.append("</svg>\n");
        Files.createDirectories(file.toAbsolutePath().getParent());
        Files.writeString(file, svg.toString(), StandardCharsets.UTF_8);
    }

    static String label(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e9 ? Long.toString((long) v) : String.format(Locale.ROOT, "%.3g", v);
    }

    private static String abbreviate(String s, int n) {
        return s.length() <= n ? s : s.substring(0, n) + "...";
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
