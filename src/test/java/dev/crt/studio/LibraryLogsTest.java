package dev.crt.studio;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.logging.Level;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;

class LibraryLogsTest {
    @Test
    void thePropertySheetsRoutineWarningsAreQuietAndSevereOnesPass() {
        LibraryLogs.quiet();
        System.gc(); // the levels must survive a collection of the loggers nobody else holds
        // The loggers the NetBeans property sheet writes to on first use (names of its classes).
        for (String name : new String[] {"org.openide.util.NbPreferences", "org.openide.util.ImageUtilities", "java.util.prefs"}) {
            Logger logger = Logger.getLogger(name);
            assertFalse(logger.isLoggable(Level.WARNING), name + " still logs warnings");
            assertFalse(logger.isLoggable(Level.INFO), name + " still logs information");
            assertTrue(logger.isLoggable(Level.SEVERE), name + " no longer logs severe errors");
        }
        assertTrue(Logger.getLogger("dev.crt").isLoggable(Level.WARNING), "CRT's own warnings must not be quieted");
    }
}
