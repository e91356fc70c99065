package org.emini.flavour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Each rule of the double flavour on the smallest source that shows it, and what it must leave alone. */
class DoubleFlavourTest {
    private static String t(String source) {
        return DoubleFlavour.transform(source, "T.java");
    }

    @Test
    void theFloatTypeAndItsBoxBecomeDouble() {
        assertEquals("double x = (double) y; double[] a; Double b = Double.valueOf(x);",
            t("float x = (float) y; float[] a; Float b = Float.valueOf(x);"));
        assertEquals("Double.POSITIVE_INFINITY + Double.MAX_VALUE", t("Float.POSITIVE_INFINITY + Float.MAX_VALUE"));
    }

    @Test
    void floatLiteralsKeepTheirDigitsWithADoubleSuffix() {
        assertEquals("1d / 3", t("1f / 3"), "1f must not become the int 1");
        assertEquals("0.5d + 1e-6d + 2.5E+3d + .25d + 1_000d", t("0.5F + 1e-6f + 2.5E+3f + .25f + 1_000f"));
        assertEquals("0x1.8p3d", t("0x1.8p3f"), "a hex float literal");
    }

    @Test
    void otherNumbersStayAsWritten() {
        assertEquals("0xFF + 0x7F + 10L + 3 + 2.5 + 1e10 + 0b1010", t("0xFF + 0x7F + 10L + 3 + 2.5 + 1e10 + 0b1010"));
    }

    @Test
    void floatMembersAndLibraryNamesBecomeTheirDoubleCounterparts() {
        assertEquals("r.nextDouble() + Double.parseDouble(s) + o.doubleValue()",
            t("r.nextFloat() + Float.parseFloat(s) + o.floatValue()"));
        assertEquals("Arbitraries.doubles().between(0d, 1d); @DoubleRange(min = 0d) double x",
            t("Arbitraries.floats().between(0f, 1f); @FloatRange(min = 0f) float x"));
    }

    @Test
    void floatBitsBecomeTheIntHashOfTheDoubleBits() {
        assertEquals("h = 31 * h + Long.hashCode(Double.doubleToLongBits(b.getX(a(1), 2)));",
            t("h = 31 * h + Float.floatToIntBits(b.getX(a(1), 2));"));
        assertEquals("Long.hashCode(Double.doubleToRawLongBits(v))", t("Float.floatToRawIntBits(v)"));
    }

    @Test
    void floatBitsThatCannotBeCarriedOverStopTheGeneratorNamingThePlace() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> t("int a;\nfloat f = Float.intBitsToFloat(a);"));
        assertTrue(e.getMessage().startsWith("T.java:2:"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> t("ToIntFunction<Float> f = Float::floatToIntBits;"));
        assertTrue(e.getMessage().contains("floatToIntBits only as a call"), e.getMessage());
    }

    @Test
    void identifiersThatOnlyContainFloatStay() {
        String s = "boxFloatsAtRest(); int floating; FLOATS[0]; toFloat(x); Floats.of(1);";
        assertEquals(s, t(s));
    }

    @Test
    void commentsFollowButStringsAndCharactersStayAsWritten() {
        assertEquals("/** See {@link #setMass(double)}: a double, two doubles. */",
            t("/** See {@link #setMass(float)}: a float, two floats. */"));
        assertEquals("// Double.MAX_VALUE is the largest\n", t("// Float.MAX_VALUE is the largest\n"));
        String strings = "String a = \"--float-compare 1f\"; char c = 'f'; String b = \"\"\"\n  float 2f\n  \"\"\";";
        assertEquals(strings, t(strings));
        assertEquals("s = \"a \\\" float\" + 1d;", t("s = \"a \\\" float\" + 1f;"), "an escaped quote does not end the string");
    }

    @Test
    void aMarkedLineKeepsItsCodeAndOnlyThatLine() {
        String kept = "stroke(1.6f, new float[] {6f}); // flavour: float (AWT's)\n";
        assertEquals(kept + "double x = 2d;", t(kept + "float x = 2f;"));
    }

    @Test
    void unterminatedLiteralsAndCommentsAreErrorsWithTheLine() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> t("a;\n/* open"))
            .getMessage().startsWith("T.java:2: unterminated comment"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> t("s = \"open\nfloat x;"))
            .getMessage().startsWith("T.java:1: unterminated string"));
    }

    @Test
    void tokensJoinBackToTheSourceExactly() {
        String source = "package a;\n/* c */ class A { float f = 1.5e-3f; String s = \"x\\\"y\"; char c = '\\''; }\n";
        StringBuilder joined = new StringBuilder();
        JavaTokens.split(source, "A.java").forEach(tok -> joined.append(tok.text()));
        assertEquals(source, joined.toString());
    }

    @Test
    void generateWritesChangedFilesOnlyAndDeletesThoseWhoseSourceIsGone(@TempDir Path dir) throws IOException {
        Path src = dir.resolve("src/p");
        Files.createDirectories(src);
        Files.writeString(src.resolve("A.java"), "package p; class A { float a = 1f; }");
        Files.writeString(src.resolve("notes.md"), "float");
        Path out = dir.resolve("out");
        Files.createDirectories(out.resolve("p"));
        Files.writeString(out.resolve("p/Gone.java"), "class Gone {}");
        assertEquals(1, Generate.generate(dir.resolve("src"), out));
        String a = Files.readString(out.resolve("p/A.java"));
        assertTrue(a.startsWith("// Generated from p/A.java") && a.endsWith("package p; class A { double a = 1d; }"), a);
        assertFalse(Files.exists(out.resolve("p/Gone.java")), "a generated file without a source is deleted");
        assertFalse(Files.exists(out.resolve("p/notes.md")), "only Java sources are generated");
        assertEquals(0, Generate.generate(dir.resolve("src"), out), "an unchanged source is not written again");
    }
}
