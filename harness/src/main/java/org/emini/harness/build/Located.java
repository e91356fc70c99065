package org.emini.harness.build;

import java.util.function.Supplier;
import org.emini.harness.load.JsonPath;

/**
 * Runs an engine call for a value written at a path: an {@code IllegalArgumentException} the engine
 * throws becomes a {@link BuildRefusedException} naming that path. The engine's checks stay the only
 * rules; this only says where their input came from.
 */
final class Located {
    private Located() {
    }

    static void at(JsonPath path, Runnable call) {
        at(path, () -> {
            call.run();
            return null;
        });
    }

    static <T> T at(JsonPath path, Supplier<T> call) {
        try {
            return call.get();
        } catch (BuildRefusedException e) {
            throw e;
        } catch (IllegalArgumentException e) {
            throw new BuildRefusedException(path, e.getMessage(), e);
        }
    }
}
