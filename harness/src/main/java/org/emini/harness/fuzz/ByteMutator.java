package org.emini.harness.fuzz;

import java.io.ByteArrayOutputStream;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Mutations that do not know the format: bit flips, cuts, lost, repeated or foreign chunks, and
 * numbers overwritten with extremes (32-bit integers, float bits) at any offset, as a damaged or
 * hostile world file would have them. The phy fuzzer uses these alone, the scenario fuzzer among others.
 */
final class ByteMutator {
    /** 32-bit words that break counts, sizes and floats: limits, sign bits, NaN, infinities, float extremes. */
    private static final int[] WORDS = {0, 1, -1, 0x7FFFFFFF, 0x80000000, 0xFFFF, 0x10000, 0x7FFF, 0x8000, 1 << 24,
        Float.floatToRawIntBits(Float.NaN), Float.floatToRawIntBits(Float.POSITIVE_INFINITY),
        Float.floatToRawIntBits(Float.NEGATIVE_INFINITY), Float.floatToRawIntBits(Float.MAX_VALUE),
        Float.floatToRawIntBits(-Float.MAX_VALUE), Float.floatToRawIntBits(Float.MIN_VALUE),
        Float.floatToRawIntBits(1e30f), Float.floatToRawIntBits(-1e30f), 0x7FC00001, 100_000_000};

    private ByteMutator() {
    }

    /** One mutation of {@code in}; {@code corpus} supplies foreign chunks. */
    static byte[] mutate(byte[] in, List<byte[]> corpus, SplittableRandom r) {
        if (in.length == 0) {
            return new byte[] {(byte) r.nextInt(256)};
        }
        byte[] out = in.clone();
        int at = r.nextInt(in.length);
        switch (r.nextInt(8)) {
            case 0 -> out[at] ^= (byte) (1 << r.nextInt(8));
            case 1 -> out[at] = (byte) Inputs.pick(r, 0, 0xFF, 0x7F, 0x80, 0x01, 0xFE).intValue();
            case 2 -> {
                return java.util.Arrays.copyOf(in, at);
            }
            case 3 -> writeWord(out, at, WORDS[r.nextInt(WORDS.length)], r.nextBoolean());
            case 4 -> {
                int len = Math.min(in.length - at, 1 + r.nextInt(64));
                return splice(in, at, len, new byte[0]);
            }
            case 5 -> {
                int len = Math.min(in.length - at, 1 + r.nextInt(64));
                byte[] chunk = java.util.Arrays.copyOfRange(in, at, at + len);
                return splice(in, at, 0, chunk);
            }
            case 6 -> {
                byte[] other = corpus.get(r.nextInt(corpus.size()));
                if (other.length > 0) {
                    int from = r.nextInt(other.length);
                    int len = Math.min(other.length - from, 1 + r.nextInt(128));
                    return splice(in, at, r.nextInt(16), java.util.Arrays.copyOfRange(other, from, from + len));
                }
            }
            default -> {
                byte[] noise = new byte[1 + r.nextInt(8)];
                for (int i = 0; i < noise.length; i++) {
                    noise[i] = (byte) r.nextInt(256);
                }
                return splice(in, at, 0, noise);
            }
        }
        return out;
    }

    /** A 32-bit word at {@code at} (as far as it fits), big- or little-endian. */
    static void writeWord(byte[] out, int at, int word, boolean bigEndian) {
        for (int i = 0; i < 4 && at + i < out.length; i++) {
            int shift = bigEndian ? 24 - 8 * i : 8 * i;
            out[at + i] = (byte) (word >>> shift);
        }
    }

    /** {@code in} with {@code remove} bytes at {@code at} replaced by {@code insert}. */
    static byte[] splice(byte[] in, int at, int remove, byte[] insert) {
        int cut = Math.min(in.length, at + remove);
        ByteArrayOutputStream out = new ByteArrayOutputStream(in.length + insert.length);
        out.write(in, 0, at);
        out.write(insert, 0, insert.length);
        out.write(in, cut, in.length - cut);
        return out.toByteArray();
    }
}
