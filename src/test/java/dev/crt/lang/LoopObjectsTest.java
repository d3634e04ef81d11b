package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * An object literal inside a loop or a macro body is checked once and then built from that plan on
 * every turn; at the top level it is evaluated directly. Both must give the same entities and the
 * same diagnostics, mistakes included. The literal stands at the same place of the text in each
 * script (the top-level one is padded), so spans compare equal too.
 */
class LoopObjectsTest {
    private static final String LOOP = "Scene { i = 0 while (i < 1) { ";
    private static final String LOOP_END = " i = i + 1 } }";

    @ParameterizedTest
    @ValueSource(strings = {
        "Sphere { center -> vec3(1, 2, 3) radius -> 0.5 material -> Material { color -> rgb(0.2, 0.4, 0.6) specular -> 0.3 } }",
        "Box { cornerA -> vec3(0, 0, 0) cornerB -> vec3(1, 2, 3) }",
        "Torus { center -> vec3(0, 1, 0) major -> 2 minor -> 0.5 }",
        "Cylinder { from -> vec3(0, 0, 0) to -> vec3(0, 2, 0) radius -> 0.3 capped -> false }",
        "Sphere { radius -> 1 center -> vec3(0, 0, 0) } + Box { cornerA -> vec3(0, 0, 0) cornerB -> vec3(1, 1, 1) }",
        "Sphere { center -> vec3(0, 0, 0) radius -> -1 }",
        "Sphere { center -> 3 radius -> 1 }",
        "Sphere { radius -> 1 }",
        "Sphere { center -> vec3(0, 0, 0) radius -> 1 radius -> 2 }",
        "Sphere { center -> vec3(0, 0, 0) radius -> 1 colour -> rgb(1, 0, 0) }",
        "Sphre { center -> vec3(0, 0, 0) radius -> 1 }",
        "Sphere { center -> vec3(0, 0, 0) radius -> nowhere }",
        "Sphere { center -> vec3(0, 0, 0) radius -> 1 / 0 }",
        "Sphere { center -> vec3(0, 0, 0) radius -> 1 material -> Material { diffuse -> 2 specular -> \"x\" } }",
        "Box { cornerA -> vec3(0, 0, 0) cornerB -> vec3(1, 1, 1) material -> Material { color -> 5 shininess -> -3 } }",
        "Plane { normal -> vec3(0, 0, 0) position -> vec3(0, 0, 0) }",
        "Sphere { center -> vec3(0, 0, 0) radius -> 1 material -> Material { color -> Checker { color1 -> rgb(1, 1, 1) scale -> 0 } } }",
        "Cone { from -> vec3(0, 0, 0) to -> vec3(0, 0, 0) radius -> 1 }",
    })
    void aLiteralInALoopOrAMacroGivesWhatItGivesAtTheTopLevel(String literal) {
        CompileResult top = sameInALoopAsAtTheTopLevel(literal);

        // In a macro called twice: the plan is made on the first call and used on the second.
        String macro = "m = Macro () { " + literal + " }";
        String inMacro = Scripts.CAMERA + macro + "\nScene { m() m() }";
        CompileResult called = Scripts.compile(inMacro);
        List<String> messages = called.diagnostics().stream().map(LoopObjectsTest::withoutPlaces).distinct().toList();
        assertThat(messages).as(Scripts.render(called, inMacro))
                .isEqualTo(top.diagnostics().stream().map(LoopObjectsTest::withoutPlaces).toList());
        if (top.scene() != null) {
            assertThat(called.scene().entities()).hasSize(2 * top.scene().entities().size());
        }
    }

    /**
     * Expressions in a loop run as closures compiled once, with the operators and names read from
     * their tokens then and a sign applied to a literal worked out then; they must give what the
     * top level's direct evaluation gives, the values and the mistakes (reported when they run).
     */
    @ParameterizedTest
    @ValueSource(strings = {
        "-10", "-(2.5)", "- -3", "+4", "-vec3(1, 2, 3)[0]", "-rgb(0.5, 0.25, 1)[1]", "2 * 3 % 4 - 1 / 8", "1 - 2 + 3",
        "(1 < 2 ? -1 : 1) * 3", "-\"a\"", "-true", "1 < \"a\"", "\"a\" == 1 ? 1 : 0", "2 % 0", "-1 / 0",
        "vec3(1, 2, 3) * 2 - vec3(1, 1, 1)", "[1, 2] + 3", "4 - [1]",
    })
    void anExpressionInALoopGivesWhatItGivesAtTheTopLevel(String expression) {
        String literal = "Sphere { center -> vec3(" + expression + ", 0, 0) radius -> 1 }";
        sameInALoopAsAtTheTopLevel(literal);
    }

    /** Compiles {@code literal} in a loop and at the top level; checks both give the same diagnostics and entities; returns the top level's. */
    private static CompileResult sameInALoopAsAtTheTopLevel(String literal) {
        String inLoop = Scripts.CAMERA + LOOP + literal + LOOP_END;
        String topLevel = Scripts.CAMERA + "Scene { " + " ".repeat(LOOP.length() - "Scene { ".length()) + literal + " }";
        CompileResult loop = Scripts.compile(inLoop), top = Scripts.compile(topLevel);
        assertThat(loop.diagnostics()).as("diagnostics in a loop:\n%s\nat the top level:\n%s", Scripts.render(loop, inLoop),
                Scripts.render(top, topLevel)).isEqualTo(top.diagnostics());
        assertThat(loop.scene() == null ? null : loop.scene().entities())
                .isEqualTo(top.scene() == null ? null : top.scene().entities());
        return top;
    }

    /** A diagnostic's severity and message, with the places it names ("first at 2:49") left out. */
    private static String withoutPlaces(Diagnostic d) {
        return d.severity() + " " + d.message().replaceAll("\\d+:\\d+", "L:C");
    }
}
