package org.emini.harness.load;

/**
 * One thing wrong with a scenario file, located as precisely as the parser allows.
 *
 * @param file the file as the user named it
 * @param line 1-based line, or 0 when unknown
 * @param column 1-based column, or 0 when unknown
 * @param path the place inside the document, as a JSON path ({@code $.bodies[2].shape})
 * @param message what is wrong
 */
public record Problem(String file, int line, int column, String path, String message) {

    /** Formats as {@code file:line:column: path: message}, the shape compilers and editors understand. */
    @Override
    public String toString() {
        StringBuilder out = new StringBuilder(file);
        if (line > 0) {
            out.append(':').append(line);
            if (column > 0) {
                out.append(':').append(column);
            }
        }
        out.append(": ").append(path).append(": ").append(message);
        return out.toString();
    }
}
