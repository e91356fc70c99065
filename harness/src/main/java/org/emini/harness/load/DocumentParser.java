package org.emini.harness.load;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.StringReader;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.composer.Composer;
import org.yaml.snakeyaml.error.Mark;
import org.yaml.snakeyaml.error.MarkedYAMLException;
import org.yaml.snakeyaml.error.YAMLException;
import org.yaml.snakeyaml.nodes.MappingNode;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.NodeTuple;
import org.yaml.snakeyaml.nodes.ScalarNode;
import org.yaml.snakeyaml.nodes.SequenceNode;
import org.yaml.snakeyaml.nodes.Tag;
import org.yaml.snakeyaml.parser.ParserImpl;
import org.yaml.snakeyaml.reader.StreamReader;
import org.yaml.snakeyaml.resolver.Resolver;

/**
 * Parses a YAML or JSON scenario into a JSON tree and a {@link SourceMap}.
 *
 * <p>Both formats go through SnakeYAML's composer (JSON is, for the documents we write, a subset of
 * YAML), which keeps a start mark on every node: that is how a schema error about
 * {@code $.bodies[2].shape} gets a line number. The same code path for both formats is also why a YAML
 * scene and its JSON translation build identical worlds.
 */
public final class DocumentParser {
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    /** A parsed document, or the problems that stopped the parse. */
    public record Parsed(JsonNode root, SourceMap sourceMap, List<Problem> problems) {
        /** Whether the document could be read at all. */
        public boolean ok() {
            return problems.isEmpty();
        }
    }

    private final String file;
    private final SourceMap sourceMap = new SourceMap();
    private final List<Problem> problems = new java.util.ArrayList<>();
    private int nodes;

    private DocumentParser(String file) {
        this.file = file;
    }

    /**
     * Parses a document.
     *
     * @param file the file name used in problems
     * @param text the file's text
     * @return the tree (null when unreadable), its source map and any problems
     */
    public static Parsed parse(String file, String text) {
        DocumentParser parser = new DocumentParser(file);
        return parser.run(text);
    }

    private Parsed run(String text) {
        Problem unprintable = SceneText.unprintable(file, text);
        if (unprintable != null) {
            problems.add(unprintable);
            return new Parsed(null, sourceMap, problems);
        }
        LoaderOptions options = new LoaderOptions();
        options.setAllowDuplicateKeys(false);
        options.setProcessComments(false);
        options.setCodePointLimit(Limits.CODE_POINTS);
        options.setMaxAliasesForCollections(Limits.COLLECTION_ALIASES);
        // The guarded parser stops deeper documents first, with a mark; this is only a backstop.
        options.setNestingDepthLimit(Limits.DEPTH + 10);
        GuardedParser parser = new GuardedParser(new ParserImpl(new StreamReader(new StringReader(text)), options));
        Node node;
        try {
            node = new Composer(parser, new Resolver(), options).getSingleNode();
        } catch (MarkedYAMLException e) {
            Mark mark = e.getProblemMark() != null ? e.getProblemMark() : e.getContextMark();
            String what = e.getProblem() != null ? e.getProblem() : e.getMessage();
            if (e.getContext() != null) {
                what = e.getContext() + ": " + what;
            }
            return failed(mark != null ? mark : parser.lastMark(), "$", "cannot parse: " + what.trim());
        } catch (GuardedParser.LimitException e) {
            return failed(e.mark(), e.path(), e.getMessage());
        } catch (YAMLException e) {
            // SnakeYAML's own limits (aliases, nesting, size) carry no mark: the parser knows where it was.
            return failed(parser.lastMark(), "$", "cannot parse: " + e.getMessage());
        } catch (RuntimeException e) {
            return failed(parser.lastMark(), "$", "cannot parse: " + e);
        }
        if (node == null) {
            problems.add(new Problem(file, 1, 1, "$", "the file is empty"));
            return new Parsed(null, sourceMap, problems);
        }
        mark(JsonPath.ROOT, node);
        JsonNode root;
        try {
            root = convert(node, JsonPath.ROOT);
        } catch (GuardedParser.LimitException e) {
            return failed(e.mark(), e.path(), e.getMessage());
        }
        return new Parsed(problems.isEmpty() ? root : null, sourceMap, problems);
    }

    private Parsed failed(Mark mark, String path, String message) {
        problems.add(new Problem(file, mark == null ? 0 : mark.getLine() + 1, mark == null ? 0 : mark.getColumn() + 1,
                path, message));
        return new Parsed(null, sourceMap, problems);
    }

    private void mark(JsonPath path, Node node) {
        Mark m = node.getStartMark();
        if (m != null) {
            sourceMap.put(path, m.getLine() + 1, m.getColumn() + 1);
        }
    }

    // Aliases share nodes: a small file can stand for billions of values. Count them as expanded.
    private JsonNode convert(Node node, JsonPath path) {
        if (path.elements().size() > Limits.DEPTH) {
            throw new GuardedParser.LimitException("lists and maps nested more than " + Limits.DEPTH
                    + " deep once aliases are expanded (an alias inside its own anchor?)", node.getStartMark(), path);
        }
        if (++nodes > Limits.NODES) {
            throw new GuardedParser.LimitException("more than " + Limits.NODES
                    + " values once aliases are expanded: the document is too large", node.getStartMark(), path);
        }
        if (node instanceof MappingNode mapping) {
            ObjectNode out = NODES.objectNode();
            Set<String> seen = new HashSet<>();
            for (NodeTuple tuple : mapping.getValue()) {
                Node keyNode = tuple.getKeyNode();
                if (!(keyNode instanceof ScalarNode key)) {
                    problem(keyNode, path, "keys must be plain text");
                    continue;
                }
                String name = key.getValue();
                JsonPath child = path.key(name);
                if (!seen.add(name)) {
                    problem(keyNode, child, "duplicate key '" + name + "'");
                    continue;
                }
                mark(child, keyNode);
                out.set(name, convert(tuple.getValueNode(), child));
            }
            return out;
        }
        if (node instanceof SequenceNode sequence) {
            ArrayNode out = NODES.arrayNode();
            int i = 0;
            for (Node item : sequence.getValue()) {
                JsonPath child = path.index(i++);
                mark(child, item);
                out.add(convert(item, child));
            }
            return out;
        }
        return scalar((ScalarNode) node, path);
    }

    private JsonNode scalar(ScalarNode node, JsonPath path) {
        Tag tag = node.getTag();
        String v = node.getValue();
        if (Tag.NULL.equals(tag)) {
            return NODES.nullNode();
        }
        if (Tag.BOOL.equals(tag)) {
            String s = v.toLowerCase(java.util.Locale.ROOT);
            return NODES.booleanNode(s.equals("true") || s.equals("yes") || s.equals("on") || s.equals("y"));
        }
        Numbers.Read number = Tag.INT.equals(tag) ? Numbers.integer(v) : Tag.FLOAT.equals(tag) ? Numbers.decimal(v) : null;
        if (number == null) {
            return NODES.textNode(v);
        }
        if (number.problem() != null) {
            problem(node, path, number.problem());
            return NODES.nullNode();
        }
        return number.value() instanceof BigInteger i ? NODES.numberNode(i) : NODES.numberNode((BigDecimal) number.value());
    }

    private void problem(Node at, JsonPath path, String message) {
        Mark m = at.getStartMark();
        problems.add(new Problem(file, m == null ? 0 : m.getLine() + 1, m == null ? 0 : m.getColumn() + 1,
                path.toString(), message));
    }
}
