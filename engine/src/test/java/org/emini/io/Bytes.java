package org.emini.io;

import java.io.ByteArrayOutputStream;

/** Builds test files byte by byte in the format's primitives. */
final class Bytes {
    private final ByteArrayOutputStream out = new ByteArrayOutputStream();

    static Bytes version(int word) {
        return new Bytes().i32(word);
    }

    Bytes u8(int... values) {
        for (int v : values) {
            out.write(v);
        }
        return this;
    }

    Bytes i32(int... values) {
        for (int v : values) {
            out.write(v >>> 24);
            out.write(v >>> 16);
            out.write(v >>> 8);
            out.write(v);
        }
        return this;
    }

    Bytes px(float... values) {
        for (float v : values) {
            i32((int) Math.round(v * 4096));
        }
        return this;
    }

    Bytes str(String s) {
        byte[] b = RandomDocuments.utf8(s);
        i32(b.length);
        out.write(b, 0, b.length);
        return this;
    }

    int size() {
        return out.size();
    }

    byte[] bytes() {
        return out.toByteArray();
    }

    /** A version-10 square shape record of half-size h with the given user data. */
    Bytes square10(float h, String userData) {
        u8(4).px(h, h, h, -h, -h, -h, -h, h).i32(0, 1024, 4096);
        return str(userData);
    }

    /** A version-10 body record at (x, y) using a shape, dynamic and rotating. */
    Bytes body10(float x, float y, int shape, String userData) {
        px(x, y, 0, 0).i32(0, 0).u8(shape, 3).i32(0);
        return str(userData);
    }
}
