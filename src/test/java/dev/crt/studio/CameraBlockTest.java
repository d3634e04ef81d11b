package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import org.junit.jupiter.api.Test;

/** Where "Copy camera to script" finds the Camera block it replaces. */
class CameraBlockTest {
    private static int[] rangeOfCompiledCamera(String text) {
        var scene = CrtCompiler.compile(new Source("t.crt", text, null), CompileOptions.DEFAULT).scene();
        return LiveDock.blockRange(text, scene.settings().camera().span().start());
    }

    @Test
    void theBlockEndsAtItsOwnBraceNotAtBracesInStringsCommentsOrNestedValues() {
        String camera = "Camera { position -> vec3(0, 1, -5) -- a } in a comment\n  pointing -> vec3(0, 0, 0) fov -> 40 }";
        String text = "Settings { title -> \"{ braces }\" camera -> " + camera + " }\nScene { Sphere { } }\n";
        int[] range = rangeOfCompiledCamera(text);
        assertThat(text.substring(range[0], range[1])).isEqualTo(camera);
    }

    @Test
    void aCameraInAVariableIsFoundWhereItIsWritten() {
        String text = "cam = Camera { position -> vec3(0, 0, -4) pointing -> vec3(0, 0, 0) }\nSettings { camera -> cam }\nScene { Sphere { } }\n";
        int[] range = rangeOfCompiledCamera(text);
        assertThat(text.substring(range[0], range[1])).isEqualTo("Camera { position -> vec3(0, 0, -4) pointing -> vec3(0, 0, 0) }");
    }

    @Test
    void noBlockWhereTheNameIsNotFollowedByABrace() {
        assertThat(LiveDock.blockRange("Camera = 3", 0)).isNull();
        assertThat(LiveDock.blockRange("Camera { position -> vec3(0, 0, -4)", 0)).isNull();
        assertThat(LiveDock.blockRange("x", 5)).isNull();
    }
}
