package org.emini.flavour;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.emini.flavour.JavaTokens.Kind;
import org.emini.flavour.JavaTokens.Token;

/**
 * The double-precision flavour's rules: turns the float engine's source (and the code that drives it:
 * its tests, the harness) into the same program in {@code double}. The engine keeps every square root
 * and trigonometric call in {@code EMath}, whose float code is cast-and-call, so these rules are token
 * substitutions:
 * <ol>
 *   <li>In code, the names in {@link #NAMES}: {@code float} becomes {@code double}, {@code Float} becomes
 *   {@code Double}, and the {@code Float}-specific members and jqwik types their double counterparts.</li>
 *   <li>A float literal ({@code 1f}, {@code 0.5F}, {@code 1e-6f}, {@code 0x1p3f}) becomes the same
 *   digits with a {@code d} suffix, so {@code 1f / 3} stays a floating division.</li>
 *   <li>{@code Float.floatToIntBits(x)} and {@code Float.floatToRawIntBits(x)} become
 *   {@code Long.hashCode(Double.doubleToLongBits(x))} (and raw): still an int, so a hash that mixes them
 *   compiles, and it hashes all 64 bits. {@code Float.intBitsToFloat} has no double counterpart
 *   taking an int: the generator stops with an error naming the place.</li>
 *   <li>In comments, the words float, floats and Float likewise, so Javadoc links such as
 *   {@code {@link #setMass(float)}} resolve. String and character literals stay as written: they hold
 *   option names, keys and tags ({@code "--float-compare"}, {@code "!!float"}) as well as prose, so a
 *   message of the double flavour may still say "overflows a float".</li>
 * </ol>
 * A line whose comment says {@value #KEEP} keeps its code as written: float there is not the
 * engine's number type but a library's (AWT's strokes in the harness). Nothing else changes: hex
 * integer literals ({@code 0xFF}), identifiers that merely contain "float" and {@code Math.round} (which
 * answers long for a double: code that needs an int casts, in the float source too) are left alone,
 * and a mistake shows as a compile error in the generated source.
 */
public final class DoubleFlavour {
    /** Code names and their double counterparts. */
    static final Map<String, String> NAMES = Map.of(
        "float", "double",
        "Float", "Double",
        "floatValue", "doubleValue",
        "parseFloat", "parseDouble",
        "nextFloat", "nextDouble",
        "floats", "doubles",
        "FloatRange", "DoubleRange",
        "FloatArbitrary", "DoubleArbitrary");

    private static final Map<String, String> BITS = Map.of(
        "floatToIntBits", "doubleToLongBits",
        "floatToRawIntBits", "doubleToRawLongBits");

    /** The marker comment that keeps a line's code as written. */
    public static final String KEEP = "flavour: float";

    private static final Pattern WORD = Pattern.compile("\\b(float|floats|Float)\\b");

    private DoubleFlavour() {
    }

    /**
     * Rewrites one compilation unit.
     *
     * @param source the float flavour's source
     * @param name the file's name, for errors
     * @return the double flavour's source
     * @throws IllegalArgumentException for source the rules cannot carry over, naming the file and line
     */
    public static String transform(String source, String name) {
        List<Token> tokens = JavaTokens.split(source, name);
        Set<Integer> kept = new HashSet<>();
        for (Token t : tokens) {
            if (t.kind() == Kind.COMMENT && t.text().contains(KEEP)) {
                kept.add(t.line());
            }
        }
        List<String> out = new ArrayList<>(tokens.size());
        for (Token t : tokens) {
            out.add(kept.contains(t.line()) ? t.text() : switch (t.kind()) {
                case IDENTIFIER -> NAMES.getOrDefault(t.text(), t.text());
                case NUMBER -> number(t.text());
                case COMMENT -> words(t.text());
                default -> t.text();
            });
        }
        bits(tokens, out, kept, name);
        return String.join("", out);
    }

    /** A float literal becomes a double literal with the same digits; every other number stays. */
    static String number(String literal) {
        char last = literal.charAt(literal.length() - 1);
        if (last != 'f' && last != 'F') {
            return literal;
        }
        boolean hex = literal.startsWith("0x") || literal.startsWith("0X");
        if (hex && literal.indexOf('p') < 0 && literal.indexOf('P') < 0) {
            return literal; // a hex integer ending in the digit F
        }
        return literal.substring(0, literal.length() - 1) + "d";
    }

    private static String words(String text) {
        Matcher m = WORD.matcher(text);
        StringBuilder sb = new StringBuilder();
        while (m.find()) {
            m.appendReplacement(sb, NAMES.get(m.group(1)));
        }
        m.appendTail(sb);
        return sb.toString();
    }

    /** Float.floatToIntBits(x) → Long.hashCode(Double.doubleToLongBits(x)); out already says Double for Float. */
    private static void bits(List<Token> tokens, List<String> out, Set<Integer> kept, String name) {
        for (int i = 0; i < tokens.size(); i++) {
            Token t = tokens.get(i);
            if (t.kind() != Kind.IDENTIFIER || kept.contains(t.line())) {
                continue;
            }
            if (t.text().equals("intBitsToFloat")) {
                throw new IllegalArgumentException(name + ":" + t.line()
                    + ": Float.intBitsToFloat has no double counterpart that takes an int; write the float code without it");
            }
            String to = BITS.get(t.text());
            if (to == null) {
                continue;
            }
            int dot = previousCode(tokens, i);
            int owner = dot < 0 ? -1 : previousCode(tokens, dot);
            int open = nextCode(tokens, i);
            if (owner < 0 || !tokens.get(dot).text().equals(".") || !tokens.get(owner).text().equals("Float")
                || open < 0 || !tokens.get(open).text().equals("(")) {
                throw new IllegalArgumentException(name + ":" + t.line() + ": " + t.text()
                    + " only as a call Float." + t.text() + "(...)");
            }
            int close = matching(tokens, open, name);
            out.set(owner, "Long.hashCode(Double");
            out.set(i, to);
            out.set(close, ")" + out.get(close));
        }
    }

    private static int previousCode(List<Token> tokens, int i) {
        for (int k = i - 1; k >= 0; k--) {
            if (isCode(tokens.get(k))) {
                return k;
            }
        }
        return -1;
    }

    private static int nextCode(List<Token> tokens, int i) {
        for (int k = i + 1; k < tokens.size(); k++) {
            if (isCode(tokens.get(k))) {
                return k;
            }
        }
        return -1;
    }

    private static boolean isCode(Token t) {
        return t.kind() != Kind.SPACE && t.kind() != Kind.COMMENT;
    }

    private static int matching(List<Token> tokens, int open, String name) {
        int depth = 0;
        for (int k = open; k < tokens.size(); k++) {
            Token t = tokens.get(k);
            if (t.kind() == Kind.OTHER && t.text().equals("(")) {
                depth++;
            } else if (t.kind() == Kind.OTHER && t.text().equals(")") && --depth == 0) {
                return k;
            }
        }
        throw new IllegalArgumentException(name + ":" + tokens.get(open).line() + ": unbalanced parentheses");
    }
}
