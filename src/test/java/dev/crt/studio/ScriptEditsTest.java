package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.lang.SourceMap;
import dev.crt.lang.SourceMap.ObjectInfo;
import dev.crt.scene.Sphere;
import dev.crt.studio.SceneOutline.Kind;
import dev.crt.studio.SceneOutline.Node;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** Property edits as text edits, and the navigator's tree, without a window. */
class ScriptEditsTest {
    private static CompileResult compile(String text) {
        CompileResult r = CrtCompiler.compile(Source.of("e.crt", text), CompileOptions.DEFAULT.withSourceMap());
        assertThat(r.hasErrors()).as(r.diagnostics().toString()).isFalse();
        return r;
    }

    private static ObjectInfo entity(CompileResult r, int index) {
        return r.sourceMap().objectAt(r.scene().entities().get(index).span().start());
    }

    private static String set(String text, int entity, String attribute, String literal) throws ScriptEdits.Refused {
        CompileResult r = compile(text);
        // The navigator hands the sheet the call that made the entity: for a macro called from a macro, the inner call.
        ScriptEdits.Edit e = ScriptEdits.setAttribute(text, r.sourceMap(), entity(r, entity), r.sourceMap().makerOf(entity), attribute, literal);
        String edited = e.applyTo(text);
        assertThat(ScriptEdits.breaks("e.crt", 0, edited)).as(edited).isNull();
        return edited;
    }

    @Test
    void aLiteralIsRewrittenInPlaceAndNothingElseMoves() throws Exception {
        String text = "Scene {\n  Sphere { center -> vec3(0, 0, 0)  radius ->  2.0  -- big\n  }\n}\n";
        assertThat(set(text, 0, "radius", "1.25")).isEqualTo(text.replace("2.0", "1.25"));
        assertThat(set(text, 0, "center", ScriptEdits.vec3(1, -2, 0.5))).isEqualTo(text.replace("vec3(0, 0, 0)", "vec3(1, -2, 0.5)"));
    }

    @Test
    void aDefaultedAttributeIsInsertedInTheObjectsOwnLayout() throws Exception {
        assertThat(set("Scene { Sphere { } }", 0, "radius", "3")).isEqualTo("Scene { Sphere { radius -> 3 } }");
        assertThat(set("Scene { Sphere {} }", 0, "radius", "3")).isEqualTo("Scene { Sphere { radius -> 3 } }");
        assertThat(set("Scene { Sphere { radius -> 2 } }", 0, "center", "vec3(0, 1, 0)"))
                .isEqualTo("Scene { Sphere { radius -> 2 center -> vec3(0, 1, 0) } }");
        String multi = "Scene {\n  Sphere {\n    radius -> 2\n  }\n}\n";
        assertThat(set(multi, 0, "center", "vec3(0, 1, 0)"))
                .isEqualTo("Scene {\n  Sphere {\n    radius -> 2\n    center -> vec3(0, 1, 0)\n  }\n}\n");
        String edited = set("Scene { Sphere { radius -> 2 } }", 0, "material", "Material { color -> rgb(1, 0, 0) }");
        Sphere s = (Sphere) compile(edited).scene().entities().get(0);
        assertThat(s.material().color().g()).isZero();
    }

    @Test
    void aVariableAssignedOnceWithALiteralIsEditedWhereItIsAssigned() throws Exception {
        String text = "r = 0.5\nScene { Sphere { radius -> r } Sphere { radius -> r * 2 } }\n";
        assertThat(set(text, 0, "radius", "0.75")).isEqualTo(text.replace("r = 0.5", "r = 0.75"));
        CompileResult c = compile(text);
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, c.sourceMap(), entity(c, 1), null, "radius", "3"))
                .isInstanceOf(ScriptEdits.Refused.class).hasMessageContaining("computed by r * 2");
        String twice = "r = 0.5\nr = 0.7\nScene { Sphere { radius -> r } }\n";
        CompileResult t = compile(twice);
        assertThatThrownBy(() -> ScriptEdits.setAttribute(twice, t.sourceMap(), entity(t, 0), null, "radius", "3"))
                .isInstanceOf(ScriptEdits.Refused.class).hasMessageContaining("variable 'r'");
    }

    @Test
    void aMacroMadeEntityEditsItsLiteralArgumentOrIsRefused() throws Exception {
        String text = """
                m = Macro (size, c) { Sphere { radius -> size center -> c material -> Material { color -> rgb(1, 0, 0) } } }
                Scene { m(0.5, vec3(0, 1, 0)) m(0.25 * 2, vec3(2, 0, 0)) }
                """;
        assertThat(set(text, 0, "radius", "0.3")).isEqualTo(text.replace("m(0.5,", "m(0.3,"));
        assertThat(set(text, 1, "center", "vec3(3, 0, 0)")).isEqualTo(text.replace("vec3(2, 0, 0)", "vec3(3, 0, 0)"));
        CompileResult c = compile(text);
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, c.sourceMap(), entity(c, 1), c.sourceMap().callOf(1), "radius", "1"))
                .isInstanceOf(ScriptEdits.Refused.class).hasMessageContaining("0.25 * 2").hasMessageContaining("not a plain literal");
        ObjectInfo material = c.sourceMap().objectAt(entity(c, 0).attributes().get("material").start());
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, c.sourceMap(), material, c.sourceMap().callOf(0), "color", "rgb(0, 1, 0)"))
                .isInstanceOf(ScriptEdits.Refused.class).hasMessageContaining("inside a macro");
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, c.sourceMap(), entity(c, 0), c.sourceMap().callOf(0), "material", "red"))
                .isInstanceOf(ScriptEdits.Refused.class);
    }

    @Test
    void anEntityMadeByAMacroCalledFromAMacroEditsTheArgumentTheValueComesFrom() throws Exception {
        String text = """
                inner = Macro (size, at) { Sphere { center -> at radius -> size } }
                outer = Macro (s, x) {
                  inner(s, vec3(x, 0, 0))
                  inner(0.2, vec3(x, 1, 0))
                  inner(s * 2, vec3(x, 2, 0))
                }
                Scene { outer(0.5, 1) outer(0.4 * 1, 3) }
                """;
        // size is passed on as s, which the top-level call writes as 0.5: that literal is rewritten.
        String edited = set(text, 0, "radius", "0.3");
        assertThat(edited).isEqualTo(text.replace("outer(0.5, 1)", "outer(0.3, 1)"));
        CompileResult after = compile(edited);
        assertThat(((Sphere) after.scene().entities().get(0)).radius()).isEqualTo(0.3);
        assertThat(((Sphere) after.scene().entities().get(2)).radius()).as("s * 2 follows").isEqualTo(0.6);
        CompileResult c = compile(text);
        SourceMap map = c.sourceMap();
        // inner(0.2, …) is written inside outer: the literal is shared by both calls of outer.
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, map, entity(c, 1), map.makerOf(1), "radius", "1"))
                .isInstanceOf(ScriptEdits.Refused.class)
                .hasMessage("'radius' comes from the argument size = 0.2 of the call inner(…) at line 4, written inside the macro "
                        + "outer and shared by every call of it: change it there, or make it a parameter of outer");
        // Computed on the way: in the inner call (s * 2), in the outer call (0.4 * 1), or a vec3 of a parameter.
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, map, entity(c, 2), map.makerOf(2), "radius", "1"))
                .isInstanceOf(ScriptEdits.Refused.class).hasMessageContaining("size = s * 2 of the call inner(…) at line 5")
                .hasMessageContaining("computed");
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, map, entity(c, 3), map.makerOf(3), "radius", "1"))
                .isInstanceOf(ScriptEdits.Refused.class)
                .hasMessage("'radius' comes from the argument size = s of the call inner(…) at line 3, from the argument s = 0.4 * 1 "
                        + "of the call outer(…) at line 7, which is computed, not a plain literal: edit the call");
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, map, entity(c, 0), map.makerOf(0), "center", "vec3(0, 0, 0)"))
                .isInstanceOf(ScriptEdits.Refused.class).hasMessageContaining("at = vec3(x, 0, 0)");
        // The outermost call alone (what was recorded before the chain) does not name the parameter size: refused, never a wrong edit.
        assertThatThrownBy(() -> ScriptEdits.setAttribute(text, map, entity(c, 0), map.callOf(0), "radius", "1"))
                .isInstanceOf(ScriptEdits.Refused.class).hasMessageContaining("macro parameter 'size'");
    }

    @Test
    void theChainIsFollowedThroughEveryLevelAndThroughRecursion() throws Exception {
        String deep = """
                a = Macro (r) { Sphere { radius -> r } }
                b = Macro (r2) { a(r2) }
                c = Macro (r3) { b(r3) }
                Scene { c(0.7) }
                """;
        assertThat(set(deep, 0, "radius", "0.9")).isEqualTo(deep.replace("c(0.7)", "c(0.9)"));
        String tower = """
                tower = Macro (n, size) {
                  Sphere { center -> vec3(0, n, 0) radius -> size }
                  if (n > 0) { tower(n - 1, size) }
                }
                Scene { tower(2, 0.3) }
                """;
        CompileResult c = compile(tower);
        assertThat(c.scene().entities()).hasSize(3);
        assertThat(c.sourceMap().makerOf(2).caller().caller()).isSameAs(c.sourceMap().callOf(2));
        for (int i = 0; i < 3; i++) assertThat(set(tower, i, "radius", "0.25")).isEqualTo(tower.replace("tower(2, 0.3)", "tower(2, 0.25)"));
    }

    @Test
    void anEditThatWouldBreakTheScriptIsCaught() {
        String text = "Scene { Sphere { radius -> 1 } }";
        assertThat(ScriptEdits.errors("e.crt", text)).isZero();
        assertThat(ScriptEdits.breaks("e.crt", 0, text.replace("1", "-1"))).contains("radius");
        assertThat(ScriptEdits.breaks("e.crt", 0, text.replace("1", "2"))).isNull();
        // A script that already had an error may be edited as long as the edit adds none.
        assertThat(ScriptEdits.breaks("e.crt", 1, "x = nothing\n" + text.replace("1", "2"))).isNull();
    }

    @Test
    void numbersAreWrittenAsAPersonWritesThem() {
        assertThat(ScriptEdits.number(2)).isEqualTo("2");
        assertThat(ScriptEdits.number(0.1 + 0.2)).isEqualTo("0.3");
        assertThat(ScriptEdits.number(-1.5)).isEqualTo("-1.5");
        assertThat(Double.parseDouble(ScriptEdits.number(1e-9))).isEqualTo(1e-9);
        assertThat(ScriptEdits.string("say \"hi\" \\")).isEqualTo("\"say \\\"hi\\\" \\\\\"");
        assertThat(ScriptEdits.parseString(ScriptEdits.string("say \"hi\" \\"))).isEqualTo("say \"hi\" \\");
        assertThat(ScriptEdits.parseTriple("rgb(1, -0.5, 2e-1)")).containsExactly(1, -0.5, 0.2);
    }

    @Test
    void theOutlineNamesNestsAndFindsObjects() throws IOException {
        String text;
        try (InputStream in = getClass().getResourceAsStream("objects.crt")) {
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        Node root = SceneOutline.of(compile(text), text);
        assertThat(root.children()).extracting(Node::label)
                .containsExactly("Settings", "Camera", "Background", "Lights", "Entities");
        Node entities = root.children().get(4);
        assertThat(entities.children()).extracting(Node::label)
                .containsExactly("Sphere ball", "Difference cut", "row(3, 0.3)", "Plane");
        Node cut = entities.children().get(1);
        assertThat(cut.kind()).isEqualTo(Kind.OPERATION);
        assertThat(cut.children()).extracting(Node::key)
                .containsExactly("Entities/Difference cut/Box", "Entities/Difference cut/Sphere");
        assertThat(entities.children().get(2).children()).extracting(Node::label).containsExactly("Sphere", "Sphere #2", "Sphere #3");
        assertThat(entities.children().get(2).children()).extracting(Node::entityIndex).containsExactly(2, 3, 4);
        // The caret inside an object selects the innermost one there.
        assertThat(SceneOutline.at(root, text.indexOf("radius -> 0.8")).key()).isEqualTo("Entities/Sphere ball");
        assertThat(SceneOutline.at(root, text.indexOf("cornerB")).key()).isEqualTo("Entities/Difference cut/Box");
        assertThat(SceneOutline.at(root, text.indexOf(" - Sphere") + 1).key()).isEqualTo("Entities/Difference cut");
        assertThat(SceneOutline.at(root, text.indexOf("fov")).kind()).isEqualTo(Kind.CAMERA);
        assertThat(SceneOutline.at(root, text.indexOf("width")).kind()).isEqualTo(Kind.SETTINGS);
        assertThat(SceneOutline.at(root, text.indexOf("row(3") + 2).kind()).isEqualTo(Kind.CALL);
        assertThat(SceneOutline.at(root, 0)).isNull();
        assertThat(SceneOutline.ofEntity(root, 1).label()).isEqualTo("Difference cut");
    }

    @Test
    void insertionGoesAfterTheObjectTheCaretIsIn() {
        String text = "Settings {\n  width -> 10\n}\nScene { Sphere { radius -> 1 } }\n";
        SourceMap map = compile(text).sourceMap();
        assertThat(ObjectPanels.statementEnd(text, text.indexOf("width"), map)).isEqualTo(text.indexOf("}\nScene") + 1);
        assertThat(ObjectPanels.statementEnd(text, text.indexOf("radius"), map)).isEqualTo(text.length() - 1);
    }
}
