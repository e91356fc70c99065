package org.emini.harness.load;

import org.yaml.snakeyaml.error.Mark;
import org.yaml.snakeyaml.events.Event;
import org.yaml.snakeyaml.parser.Parser;

/**
 * SnakeYAML's parser with the harness's size limits and a memory of where it is. The composer stops
 * on its own limits (aliases, nesting) with an exception that has no mark; {@link #lastMark()} says
 * where the event it was reading starts, so that those problems get a line too. Events and nesting
 * are counted here, as they are read, so an oversized document stops before it is composed.
 */
final class GuardedParser implements Parser {
    /** A limit met at a place in the text. */
    static final class LimitException extends RuntimeException {
        private static final long serialVersionUID = 1L;
        private final transient Mark mark;
        private final String path;

        LimitException(String message, Mark mark) {
            this(message, mark, JsonPath.ROOT);
        }

        LimitException(String message, Mark mark, JsonPath path) {
            super(message, null, false, false);
            this.mark = mark;
            this.path = path.toString();
        }

        Mark mark() {
            return mark;
        }

        String path() {
            return path;
        }
    }

    private final Parser parser;
    private Mark lastMark;
    private int events;
    private int depth;

    GuardedParser(Parser parser) {
        this.parser = parser;
    }

    /** The start of the last event peeked or read, or null before the first. */
    Mark lastMark() {
        return lastMark;
    }

    @Override
    public boolean checkEvent(Event.ID choice) {
        return remember(parser.peekEvent()) != null && parser.checkEvent(choice);
    }

    @Override
    public Event peekEvent() {
        return remember(parser.peekEvent());
    }

    @Override
    public Event getEvent() {
        Event e = remember(parser.getEvent());
        if (e == null) {
            return null;
        }
        if (++events > Limits.EVENTS) {
            throw new LimitException("more than " + Limits.EVENTS + " values: the document is too large", e.getStartMark());
        }
        if (e.is(Event.ID.SequenceStart) || e.is(Event.ID.MappingStart)) {
            if (++depth > Limits.DEPTH) {
                throw new LimitException("lists and maps nested more than " + Limits.DEPTH + " deep",
                        e.getStartMark());
            }
        } else if (e.is(Event.ID.SequenceEnd) || e.is(Event.ID.MappingEnd)) {
            depth--;
        }
        return e;
    }

    private Event remember(Event e) {
        if (e != null && e.getStartMark() != null) {
            lastMark = e.getStartMark();
        }
        return e;
    }
}
