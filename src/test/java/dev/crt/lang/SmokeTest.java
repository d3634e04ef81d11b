package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class SmokeTest {
    @Test
    void smoke() {
        String text = Scripts.CAMERA + """
                s = Sphere { radius -> 2 center -> vec3(1, 2, 3) }
                b = Box { cornerA -> vec3(1,1,1) cornerB -> vec3(0,0,0) }
                row = Macro (n) { i = 0 while (i < n) { s <translate vec3(i*1.0, 0, 0)> i = i + 1 } }
                Scene { s b row(3) s - b ^ s }
                """;
        CompileResult r = Scripts.compile(text);
        System.out.println(Scripts.render(r, text));
        assertThat(r.scene().entities()).hasSize(6);
        String bad = "x = Sphere { radus -> 2 }\nScene { x 3 }\n y = 1 +\n z = [1,2\n";
        System.out.println(Scripts.render(Scripts.compile(bad), bad));
        bad = "x = Sphere { radus -> 2 }\nScene { x 3 }\n";
        System.out.println(Scripts.render(Scripts.compile(bad), bad));
    }
}
