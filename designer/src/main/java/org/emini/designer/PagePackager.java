package org.emini.designer;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Base64;

/**
 * Puts the page together after TeaVM has compiled the engine (the build runs it; JVM only): copies
 * the page's files into the output folder and embeds the WebAssembly module as base64 in
 * engine-wasm.js, so the page opens from the file system (a browser refuses to fetch a file:// URL,
 * but loads a script from one).
 *
 * <pre>java ... org.emini.designer.PagePackager SOURCE_DIR ENGINE_WASM PAGE_DIR</pre>
 */
public final class PagePackager {
    private PagePackager() {
    }

    /**
     * Packages the page.
     *
     * @param args the page's sources (src/main/page), TeaVM's module and the page's folder
     * @throws IOException if a file cannot be read or written
     */
    public static void main(String[] args) throws IOException {
        Path source = Path.of(args[0]);
        Path page = Path.of(args[2]);
        Files.createDirectories(page);
        try (DirectoryStream<Path> files = Files.newDirectoryStream(source)) {
            for (Path f : files) {
                Files.copy(f, page.resolve(f.getFileName().toString()), StandardCopyOption.REPLACE_EXISTING);
            }
        }
        byte[] wasm = Files.readAllBytes(Path.of(args[1]));
        String js = "// The engine compiled to WebAssembly by TeaVM (engine.wasm), as base64.\n"
                + "var EMINI_ENGINE_WASM = \"" + Base64.getEncoder().encodeToString(wasm) + "\";\n";
        Files.write(page.resolve("engine-wasm.js"), js.getBytes(StandardCharsets.US_ASCII));
    }
}
