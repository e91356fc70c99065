package org.emini.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every Java snippet of README.md compiles against the engine with the imports it shows (issue 21):
 * a snippet that declares a class compiles as it is; any other is the body of a method that is given
 * the {@code world} of the getting-started example (unless it makes its own). The getting-started
 * example is examples/consumer's Main, which ./emini test runs from a project outside the repository.
 */
class ReadmeSnippetsTest {
    private static final Path README = Path.of("..", "README.md");

    private static List<String> javaBlocks() throws IOException {
        String text = Files.readString(README, StandardCharsets.UTF_8);
        List<String> blocks = new ArrayList<>();
        Matcher m = Pattern.compile("```java\\n(.*?)```", Pattern.DOTALL).matcher(text);
        while (m.find()) {
            blocks.add(m.group(1));
        }
        return blocks;
    }

    @Test
    void theGettingStartedExampleIsTheConsumersProgram() throws IOException {
        String main = Files.readString(Path.of("consumer", "src", "main", "java", "org", "example", "Main.java"));
        String withoutPackage = main.substring(main.indexOf("import"));
        assertEquals(withoutPackage.strip(), javaBlocks().get(0).strip());
    }

    @Test
    void everyJavaSnippetCompiles(@TempDir Path dir) throws IOException {
        List<String> blocks = javaBlocks();
        assertTrue(blocks.size() >= 11, "found " + blocks.size() + " snippets");
        List<String> files = new ArrayList<>();
        for (int n = 0; n < blocks.size(); n++) {
            files.add(source(dir, n, blocks.get(n)).toString());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        List<String> args = new ArrayList<>(List.of("-d", dir.resolve("classes").toString(), "-cp",
            System.getProperty("java.class.path"), "-Xlint:none", "-proc:none"));
        args.addAll(files);
        ByteArrayOutputStream errors = new ByteArrayOutputStream();
        int rc = javac.run(null, errors, errors, args.toArray(new String[0]));
        assertEquals(0, rc, errors.toString(StandardCharsets.UTF_8));
    }

    /** A snippet as a compilation unit in package readme. */
    private static Path source(Path dir, int n, String block) throws IOException {
        StringBuilder imports = new StringBuilder();
        StringBuilder body = new StringBuilder();
        for (String line : block.split("\n", -1)) {
            if (line.startsWith("import ")) {
                imports.append(line).append('\n');
            } else {
                body.append(line).append('\n');
            }
        }
        String code = body.toString();
        Matcher cls = Pattern.compile("(?m)^(public )?class (\\w+)").matcher(code);
        String name;
        String unit;
        if (cls.find()) {
            name = cls.group(2);
            unit = "package readme;\n" + imports + code.replaceFirst("(?m)^public class", "class");
            name = name + n;
            unit = unit.replaceFirst("class " + cls.group(2), "class " + name);
        } else {
            name = "Snippet" + n;
            String world = code.contains("World world =") ? "" : "org.emini.world.World world";
            unit = "package readme;\n" + imports + "class " + name + " {\n    void run(" + world + ") throws Exception {\n" + code
                + "\n    }\n}\n";
        }
        Path file = dir.resolve("readme").resolve(name + ".java");
        Files.createDirectories(file.getParent());
        Files.writeString(file, unit);
        return file;
    }
}
