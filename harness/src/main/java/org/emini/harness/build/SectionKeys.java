package org.emini.harness.build;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Iterator;
import java.util.Set;
import org.emini.harness.load.JsonPath;

/**
 * What a builder reads of a section. The schema already refuses unknown keys; this guards against a
 * key the schema gains before its builder does: such a key makes the scene unsupported, naming the
 * path, rather than being dropped in silence.
 */
final class SectionKeys {
    private SectionKeys() {
    }

    /**
     * @param element the element as the scene names it ({@code particles})
     * @param node an object of the section
     * @param path where it is written
     * @param known the keys the builder reads
     * @throws UnsupportedElementException naming the first key the builder does not read
     */
    static void only(String element, JsonNode node, JsonPath path, Set<String> known)
            throws UnsupportedElementException {
        for (Iterator<String> it = node.fieldNames(); it.hasNext();) {
            String key = it.next();
            if (!known.contains(key)) {
                throw new UnsupportedElementException(element + " key '" + key + "'", path.key(key));
            }
        }
    }
}
