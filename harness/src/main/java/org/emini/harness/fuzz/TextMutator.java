package org.emini.harness.fuzz;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Mutations of scene text that know YAML's shape: numbers and words replaced by extremes and
 * neighbours, lines (keys) deleted or repeated, lines from other scenes spliced in, alias bombs, deep
 * nesting, invalid UTF-8 and control characters, and the byte-level ones of {@link ByteMutator}.
 */
final class TextMutator {
    /** Numbers that a reader can wrap, round to 0 or infinity, or misread. */
    static final String[] NUMBERS = {"1e300", "-1e300", "1e400", "1e-400", "1e39", "-1e39", "3.4028236e38",
        "3.4028235e38", "1.4e-45", "1e-46", "4294967297", "2147483648", "-2147483649", "9223372036854775808",
        "18446744073709551617", "100000000", "1e30", "-1e30", "0", "-0", "-1", "0.0", ".nan", ".NaN", ".inf",
        "-.inf", "017", "0x1F", "0b11", "1_000", "1:20", "1e2147483648", "0.000000000000000000000000000000000000000001",
        "1" + "0".repeat(120), "100000", "99999", "1000", "1001", "31", "32", "-32", "12", "13", "2"};

    /** Words: YAML's other scalars and the scene format's own names. */
    static final String[] WORDS = {"true", "false", "null", "~", "yes", "no", "''", "[]", "{}", "\"\"", "circle",
        "polygon", "multiShape", "rectangle", "tower", "rain", "all", "none", "dynamic", "energy", "stable",
        "body0", "a", "ball", "*missing", "&anchor", "!!int", "!!float x", "!!binary", "<<", "-", "?", ":"};

    private static final Pattern NUMBER = Pattern.compile("-?\\d+(\\.\\d+)?([eE][-+]?\\d+)?");
    private static final Pattern WORD = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

    private TextMutator() {
    }

    /** One to three mutations of a scene file. */
    static byte[] mutate(byte[] file, List<byte[]> corpus, SplittableRandom r) {
        byte[] out = file;
        int n = 1 + r.nextInt(3);
        for (int i = 0; i < n; i++) {
            out = once(out, corpus, r);
        }
        return out;
    }

    private static byte[] once(byte[] in, List<byte[]> corpus, SplittableRandom r) {
        String text = new String(in, StandardCharsets.UTF_8);
        return switch (r.nextInt(12)) {
            case 0, 1, 2 -> bytes(replace(text, NUMBER, NUMBERS, r));
            case 3 -> bytes(replace(text, WORD, WORDS, r));
            case 4 -> bytes(lines(text, r, false));
            case 5 -> bytes(lines(text, r, true));
            case 6 -> bytes(spliceLine(text, corpus, r));
            case 7 -> bytes(aliasBomb(text, r));
            case 8 -> bytes(deepNesting(text, r));
            case 9 -> ByteMutator.splice(in, r.nextInt(in.length + 1), r.nextInt(2), Inputs.pick(r, new byte[] {(byte) 0xFF},
                    new byte[] {(byte) 0xC3}, new byte[] {(byte) 0xC0, (byte) 0xAF}, new byte[] {(byte) 0xED, (byte) 0xA0,
                        (byte) 0x80}, new byte[] {(byte) 0xF4, (byte) 0x90, (byte) 0x80, (byte) 0x80}, new byte[] {0},
                    new byte[] {1}, new byte[] {0x1B}, new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF}));
            default -> ByteMutator.mutate(in, corpus, r);
        };
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    /** One match of the pattern replaced by a value from the list or by another match of the text. */
    private static String replace(String text, Pattern p, String[] values, SplittableRandom r) {
        List<int[]> spans = new ArrayList<>();
        Matcher m = p.matcher(text);
        while (m.find()) {
            spans.add(new int[] {m.start(), m.end()});
        }
        if (spans.isEmpty()) {
            return text;
        }
        int[] s = spans.get(r.nextInt(spans.size()));
        String value;
        if (r.nextInt(4) == 0) {
            int[] o = spans.get(r.nextInt(spans.size()));
            value = text.substring(o[0], o[1]);
        } else {
            value = values[r.nextInt(values.length)];
        }
        return text.substring(0, s[0]) + value + text.substring(s[1]);
    }

    /** A line removed (a key lost) or repeated (a duplicate key or list item). */
    private static String lines(String text, SplittableRandom r, boolean repeat) {
        List<String> lines = new ArrayList<>(List.of(text.split("\n", -1)));
        int i = r.nextInt(lines.size());
        if (repeat) {
            lines.add(i, lines.get(i));
        } else {
            lines.remove(i);
        }
        return String.join("\n", lines);
    }

    private static String spliceLine(String text, List<byte[]> corpus, SplittableRandom r) {
        String[] other = new String(corpus.get(r.nextInt(corpus.size())), StandardCharsets.UTF_8).split("\n");
        List<String> lines = new ArrayList<>(List.of(text.split("\n", -1)));
        lines.add(r.nextInt(lines.size() + 1), other[r.nextInt(other.length)]);
        return String.join("\n", lines);
    }

    /**
     * Issue 14's bomb (a list of items, then levels of lists of three aliases of the level below) as a
     * top-level key or in place of a value, with a random width and depth.
     */
    static String aliasBomb(String text, SplittableRandom r) {
        int width = 1 + r.nextInt(100);
        int levels = 1 + r.nextInt(20);
        StringBuilder b = new StringBuilder("&b0 [").append("1, ".repeat(width - 1)).append("1]");
        String value = b.toString();
        StringBuilder doc = new StringBuilder("bomb0: ").append(value).append('\n');
        for (int i = 1; i <= levels; i++) {
            String prev = "*b" + (i - 1);
            doc.append("bomb").append(i).append(": &b").append(i).append(" [").append(prev).append(", ").append(prev)
                    .append(", ").append(prev).append("]\n");
        }
        if (r.nextBoolean()) {
            return doc + text;
        }
        // The top level defines the anchors; a value somewhere below uses the last one.
        Matcher m = NUMBER.matcher(text);
        List<Integer> at = new ArrayList<>();
        while (m.find()) {
            at.add(m.start());
        }
        if (at.isEmpty()) {
            return doc + text;
        }
        int s = at.get(r.nextInt(at.size()));
        Matcher n = NUMBER.matcher(text);
        n.find(s);
        return doc + text.substring(0, s) + "*b" + levels + text.substring(n.end());
    }

    /** A value replaced by lists or maps nested 20 to 200 deep. */
    static String deepNesting(String text, SplittableRandom r) {
        int depth = 20 + r.nextInt(180);
        String nest = r.nextBoolean() ? "[".repeat(depth) + "1" + "]".repeat(depth)
                : "{a: ".repeat(depth) + "1" + "}".repeat(depth);
        return replace(text, NUMBER, new String[] {nest}, r);
    }
}
