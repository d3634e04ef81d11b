package dev.crt.studio;

import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Keeps the libraries' routine log lines out of the artist's terminal. The NetBeans property sheet
 * logs, on first use, that it runs outside the NetBeans platform ("NetBeans implementation of
 * Preferences not found", "No SVG loader available …"), and java.util.prefs that it made its
 * folder: true, harmless, and nothing the user can act on. Severe records still get through.
 */
final class LibraryLogs {
    /** Held here: java.util.logging keeps loggers weakly, and a collected one forgets its level. */
    private static final List<Logger> QUIETED = List.of(Logger.getLogger("org.openide"), Logger.getLogger("java.util.prefs"));

    private LibraryLogs() {}

    /** Sets the libraries' loggers to pass severe records only. */
    static void quiet() {
        for (Logger logger : QUIETED) logger.setLevel(Level.SEVERE);
    }
}
