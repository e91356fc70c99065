package org.emini.examples.manual;

import java.util.ArrayList;
import java.util.List;

/**
 * A stand-in for J2ME's {@code javax.microedition.lcdui.Graphics} with the calls the manual's
 * listings make, recording what was drawn. Porting to a real device replaces it with the
 * platform's canvas; the engine calls around it are what the listings test.
 */
final class Graphics {
    final List<String> calls = new ArrayList<>();
    private final int width;
    private final int height;

    Graphics(int width, int height) {
        this.width = width;
        this.height = height;
    }

    void setColor(int r, int g, int b) {
        calls.add("color " + r + " " + g + " " + b);
    }

    void setColor(int rgb) {
        calls.add("color " + Integer.toHexString(rgb));
    }

    void fillRect(int x, int y, int w, int h) {
        calls.add("fillRect");
    }

    void drawLine(int x1, int y1, int x2, int y2) {
        calls.add("line " + x1 + " " + y1 + " " + x2 + " " + y2);
    }

    void drawArc(int x, int y, int w, int h, int start, int arc) {
        calls.add("arc " + x + " " + y + " " + w + " " + h);
    }

    void translate(int x, int y) {
        calls.add("translate");
    }

    int getClipWidth() {
        return width;
    }

    int getClipHeight() {
        return height;
    }

    long count(String prefix) {
        return calls.stream().filter(c -> c.startsWith(prefix)).count();
    }
}
