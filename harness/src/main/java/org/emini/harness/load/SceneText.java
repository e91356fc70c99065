package org.emini.harness.load;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * A scene file's bytes as text, or a located problem: the file must be UTF-8 and hold only the
 * characters YAML allows (YAML 1.1, 5.1: tab, line breaks and printable Unicode). Both are checked here,
 * before the parser, because the decoder and SnakeYAML's reader report them without a usable line.
 */
public final class SceneText {
    private SceneText() {
    }

    /** The text, or the problem that stops it being read. */
    public record Decoded(String text, Problem problem) {
    }

    /**
     * @param file the file as shown in problems
     * @param bytes its content
     */
    public static Decoded decode(String file, byte[] bytes) {
        if (bytes.length > Limits.FILE_BYTES) {
            return new Decoded(null, new Problem(file, 0, 0, "$", "the file is " + bytes.length
                    + " bytes, more than the " + Limits.FILE_BYTES + " a scene may have"));
        }
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length + 1);
        CoderResult result = decoder.decode(in, out, true);
        if (result.isError()) {
            out.flip();
            int[] at = lineColumn(out, out.length());
            return new Decoded(null, new Problem(file, at[0], at[1], "$", String.format(
                    "not UTF-8: byte 0x%02X at offset %d cannot start or continue a character",
                    bytes[in.position()] & 0xff, in.position())));
        }
        decoder.flush(out);
        out.flip();
        return new Decoded(out.toString(), null);
    }

    /** The first character YAML does not allow, as a located problem, or null. */
    public static Problem unprintable(String file, String text) {
        int bad = firstUnprintable(text);
        if (bad < 0) {
            return null;
        }
        int[] at = lineColumn(text, bad);
        return new Problem(file, at[0], at[1], "$", String.format("character U+%04X is not allowed in YAML or JSON "
                + "(a control character; write it escaped in a quoted string)", text.codePointAt(bad)));
    }

    /** The index of the first character YAML does not allow, or -1. */
    static int firstUnprintable(String text) {
        for (int i = 0; i < text.length();) {
            int c = text.codePointAt(i);
            boolean ok = c == 0x9 || c == 0xA || c == 0xD || c >= 0x20 && c <= 0x7E || c == 0x85
                    || c >= 0xA0 && c <= 0xD7FF || c >= 0xE000 && c <= 0xFFFD || c >= 0x10000 && c <= 0x10FFFF;
            if (!ok) {
                return i;
            }
            i += Character.charCount(c);
        }
        return -1;
    }

    /** The 1-based line and column (in code points) of a character index. */
    static int[] lineColumn(CharSequence text, int index) {
        int line = 1;
        int column = 1;
        for (int i = 0; i < index; i++) {
            char c = text.charAt(i);
            if (c == '\n') {
                line++;
                column = 1;
            } else if (!Character.isLowSurrogate(c)) {
                column++;
            }
        }
        return new int[] {line, column};
    }
}
