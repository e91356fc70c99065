package org.emini.flavour;

import java.util.ArrayList;
import java.util.List;

/**
 * Splits Java source into tokens that keep every character, so joining the tokens gives the source
 * back. The rules only need to tell code from comments and literals, so this is a lexer, not a
 * parser: identifiers, numbers, strings (text blocks included), character literals, comments,
 * white space and single other characters.
 */
final class JavaTokens {
    /** What a token is. */
    enum Kind { IDENTIFIER, NUMBER, STRING, CHAR, COMMENT, SPACE, OTHER }

    /**
     * One token.
     *
     * @param kind what it is
     * @param text its characters, exactly as in the source
     * @param line the line it starts on, from 1
     */
    record Token(Kind kind, String text, int line) {
    }

    private JavaTokens() {
    }

    /**
     * Tokenizes a compilation unit.
     *
     * @param source the source text
     * @param name the file's name, for errors
     * @return the tokens in order
     * @throws IllegalArgumentException for an unterminated comment, string or character literal
     */
    static List<Token> split(String source, String name) {
        List<Token> out = new ArrayList<>();
        int i = 0;
        int line = 1;
        int n = source.length();
        while (i < n) {
            char c = source.charAt(i);
            int end;
            Kind kind;
            if (c == '/' && i + 1 < n && source.charAt(i + 1) == '/') {
                end = source.indexOf('\n', i);
                end = end < 0 ? n : end;
                kind = Kind.COMMENT;
            } else if (c == '/' && i + 1 < n && source.charAt(i + 1) == '*') {
                end = source.indexOf("*/", i + 2);
                if (end < 0) {
                    throw new IllegalArgumentException(name + ":" + line + ": unterminated comment");
                }
                end += 2;
                kind = Kind.COMMENT;
            } else if (source.startsWith("\"\"\"", i)) {
                end = closing(source, i + 3, "\"\"\"", name, line);
                kind = Kind.STRING;
            } else if (c == '"' || c == '\'') {
                end = closing(source, i + 1, String.valueOf(c), name, line);
                kind = c == '"' ? Kind.STRING : Kind.CHAR;
            } else if (Character.isJavaIdentifierStart(c)) {
                end = i + 1;
                while (end < n && Character.isJavaIdentifierPart(source.charAt(end))) {
                    end++;
                }
                kind = Kind.IDENTIFIER;
            } else if (Character.isDigit(c) || c == '.' && i + 1 < n && Character.isDigit(source.charAt(i + 1))) {
                end = numberEnd(source, i);
                kind = Kind.NUMBER;
            } else if (Character.isWhitespace(c)) {
                end = i + 1;
                while (end < n && Character.isWhitespace(source.charAt(end))) {
                    end++;
                }
                kind = Kind.SPACE;
            } else {
                end = i + 1;
                kind = Kind.OTHER;
            }
            String text = source.substring(i, end);
            out.add(new Token(kind, text, line));
            line += (int) text.chars().filter(ch -> ch == '\n').count();
            i = end;
        }
        return out;
    }

    /** The end of a literal whose body starts at from, skipping escapes; it must close on its line unless a text block. */
    private static int closing(String s, int from, String quote, String name, int line) {
        boolean block = quote.length() == 3;
        for (int i = from; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\\') {
                i++;
            } else if (s.startsWith(quote, i)) {
                return i + quote.length();
            } else if (c == '\n' && !block) {
                break;
            }
        }
        throw new IllegalArgumentException(name + ":" + line + ": unterminated " + (quote.equals("'") ? "character" : "string")
            + " literal");
    }

    /** The end of a numeric literal: digits, letters (suffixes, hex digits, exponents), '.', '_' and an exponent's sign. */
    private static int numberEnd(String s, int i) {
        boolean hex = s.startsWith("0x", i) || s.startsWith("0X", i);
        int end = i;
        while (end < s.length()) {
            char c = s.charAt(end);
            char before = s.charAt(end - 1 < i ? i : end - 1);
            boolean exponentSign = (c == '+' || c == '-') && end > i
                && (hex ? before == 'p' || before == 'P' : before == 'e' || before == 'E');
            if (Character.isLetterOrDigit(c) || c == '.' || c == '_' || exponentSign) {
                end++;
            } else {
                break;
            }
        }
        return end;
    }
}
