package org.emini.harness.oracle;

import java.io.IOException;
import java.io.PrintStream;
import java.io.RandomAccessFile;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;

/**
 * The oracle's Python virtual environment, {@code oracle-py/.venv}: created on first use from the pinned
 * {@code oracle-py/requirements.txt} (then the package itself, editable, without dependencies) and
 * reused while the requirements and {@code pyproject.toml} are unchanged (a stamp file holds their
 * hash). A lock file keeps two harness processes from building it at once. The benchmark makes its
 * Python peers' environments the same way ({@code bench/box2d/.venv}: a folder with a
 * {@code requirements.txt} and no package of its own).
 */
public final class OracleEnvironment {
    private static final String STAMP = "emini-oracle.stamp";

    private final Path project;
    private final String python;

    /**
     * @param project the oracle's folder ({@code oracle-py/})
     * @param python the interpreter that creates the environment ({@code python3}, or $EMINI_PYTHON)
     */
    public OracleEnvironment(Path project, String python) {
        this.project = project.toAbsolutePath().normalize();
        this.python = python;
    }

    /** The interpreter to create environments with: $EMINI_PYTHON, or python3. */
    public static String defaultPython() {
        String p = System.getenv("EMINI_PYTHON");
        return p != null && !p.isBlank() ? p : "python3";
    }

    /** The oracle's folder. */
    public Path project() {
        return project;
    }

    /** The environment's folder. */
    public Path venv() {
        return project.resolve(".venv");
    }

    /** The environment's interpreter. */
    public Path interpreter() {
        return venv().resolve("bin").resolve("python");
    }

    /**
     * Makes sure the environment exists and matches the pinned requirements, building it if not.
     *
     * @param log where progress goes (stderr)
     * @return the environment's interpreter
     * @throws IOException if Python or pip fails (their output is in the message)
     */
    public Path ensure(PrintStream log) throws IOException {
        if (!Files.isRegularFile(project.resolve("requirements.txt"))) {
            throw new IOException("no Python project at " + project + " (requirements.txt missing)");
        }
        String want = fingerprint();
        try (FileChannel channel = new RandomAccessFile(project.resolve(".venv.lock").toFile(), "rw").getChannel();
             FileLock lock = channel.lock()) {
            Path stamp = venv().resolve(STAMP);
            if (Files.isExecutable(interpreter()) && Files.isRegularFile(stamp)
                    && Files.readString(stamp, StandardCharsets.UTF_8).trim().equals(want)) {
                return interpreter();
            }
            String name = project.getFileName().toString();
            log.println(name + ": creating " + name + "/.venv from the pinned requirements"
                    + " (first use; later runs reuse it)");
            exec(List.of(python, "-m", "venv", "--clear", venv().toString()), "creating the virtual environment");
            String py = interpreter().toString();
            exec(List.of(py, "-m", "pip", "install", "--disable-pip-version-check", "--no-input", "-q",
                    "-r", project.resolve("requirements.txt").toString()), "installing " + name + "/requirements.txt");
            if (Files.isRegularFile(project.resolve("pyproject.toml"))) {
                exec(List.of(py, "-m", "pip", "install", "--disable-pip-version-check", "--no-input", "-q",
                        "--no-deps", "-e", project.toString()), "installing the " + name + " package");
            }
            Files.writeString(stamp, want + "\n", StandardCharsets.UTF_8);
            log.println(name + ": environment ready");
            return interpreter();
        }
    }

    /** Hash of what the environment is built from. */
    String fingerprint() throws IOException {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            for (String f : List.of("requirements.txt", "pyproject.toml")) {
                Path p = project.resolve(f);
                if (Files.isRegularFile(p)) {
                    sha.update(Files.readAllBytes(p));
                }
                sha.update((byte) 0);
            }
            sha.update(python.getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(sha.digest());
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    private void exec(List<String> command, String what) throws IOException {
        ProcessBuilder pb = new ProcessBuilder(new ArrayList<>(command)).directory(project.toFile())
                .redirectErrorStream(true);
        Process p;
        try {
            p = pb.start();
        } catch (IOException e) {
            throw new IOException(what + ": cannot start " + command.get(0)
                    + " (Python 3.9+ with venv is needed; set EMINI_PYTHON to choose the interpreter): "
                    + e.getMessage(), e);
        }
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        try {
            int status = p.waitFor();
            if (status != 0) {
                throw new IOException(what + " failed (exit " + status + "): " + String.join(" ", command)
                        + "\n" + output);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            p.destroy();
            throw new IOException(what + ": interrupted", e);
        }
    }
}
