package dev.crt.live;

import static org.assertj.core.api.Assertions.fail;

import org.junit.jupiter.api.Assumptions;

/** Opens the headless renderer for a test: in CI (CI=true) a missing OpenGL fails the test, elsewhere it skips it. */
final class GlAvailability {
    private GlAvailability() {}

    static Preview open() {
        try {
            return Preview.open();
        } catch (GlUnavailableException e) {
            if ("true".equalsIgnoreCase(System.getenv("CI"))) fail("CI must be able to draw with OpenGL: " + e.getMessage());
            Assumptions.abort(e.getMessage());
            throw new AssertionError(e);
        }
    }
}
