package dev.crt.live;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class GlContextTest {
    @Test
    void makesAHeadlessCoreContext() throws Exception {
        try (GlContext gl = GlContext.create()) {
            assertThat(gl.description()).contains("Core Profile");
            System.out.println(gl.description());
        }
    }
}
