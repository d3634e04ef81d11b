package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.SourceMap.Expr;
import dev.crt.lang.SourceMap.Kind;
import dev.crt.lang.SourceMap.ObjectInfo;
import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.Scene;
import org.junit.jupiter.api.Test;

class SourceMapTest {
    private static CompileResult compile(String text) {
        return CrtCompiler.compile(Source.of("map.crt", text), CompileOptions.DEFAULT.withSourceMap());
    }

    private static String at(String text, Expr e) { return text.substring(e.start(), e.end()); }

    @Test
    void attributesHaveTheSpanOfTheirExpressionAndSayWhetherItIsALiteral() {
        String text = """
                r = 0.5
                Settings { width -> 64 height -> 48 title -> "map" }
                ball = Sphere { center -> vec3(0, -1.5, 2) radius -> r material -> Material { color -> rgb(1, 0.5, 0) } } <translate vec3(1, 0, 0)>
                Scene { ball Sphere { radius -> r * 2 center -> vec3(r, 0, 0) } Plane { normal -> vec3(0, 1, 0) position -> -2 * vec3(0, 1, 0) } }
                """;
        CompileResult result = compile(text);
        assertThat(result.hasErrors()).isFalse();
        SourceMap map = result.sourceMap();
        Scene scene = result.scene();

        ObjectInfo ball = map.objectAt(scene.entities().get(0).span().start());
        assertThat(ball.type()).isEqualTo("Sphere");
        assertThat(ball.variable()).isEqualTo("ball");
        assertThat(text.charAt(ball.closeBrace())).isEqualTo('}');
        assertThat(ball.inMacro()).isFalse();
        Expr center = ball.attributes().get("center");
        assertThat(at(text, center)).isEqualTo("vec3(0, -1.5, 2)");
        assertThat(center.kind()).isEqualTo(Kind.VECTOR);
        assertThat(center.kind().isLiteral()).isTrue();
        Expr radius = ball.attributes().get("radius");
        assertThat(radius.kind()).isEqualTo(Kind.VARIABLE);
        assertThat(radius.name()).isEqualTo("r");
        assertThat(radius.kind().isLiteral()).isFalse();
        Expr material = ball.attributes().get("material");
        assertThat(material.kind()).isEqualTo(Kind.OBJECT);
        ObjectInfo mat = map.objectAt(material.start());
        assertThat(mat.type()).isEqualTo("Material");
        assertThat(mat.variable()).isNull();
        assertThat(mat.attributes().get("color").kind()).isEqualTo(Kind.COLOR);
        assertThat(at(text, mat.attributes().get("color"))).isEqualTo("rgb(1, 0.5, 0)");

        ObjectInfo second = map.objectAt(scene.entities().get(1).span().start());
        assertThat(second.variable()).isNull();
        assertThat(second.attributes().get("radius").kind()).isEqualTo(Kind.EXPRESSION);
        assertThat(second.attributes().get("radius").text()).isEqualTo("r * 2");
        assertThat(second.attributes().get("center").kind()).as("vec3 of a variable is no literal").isEqualTo(Kind.EXPRESSION);
        ObjectInfo plane = map.objectAt(scene.entities().get(2).span().start());
        assertThat(plane.attributes().get("position").kind()).isEqualTo(Kind.EXPRESSION);

        ObjectInfo settings = map.settings().get(0);
        assertThat(settings.attributes().get("width").kind()).isEqualTo(Kind.NUMBER);
        assertThat(at(text, settings.attributes().get("title"))).isEqualTo("\"map\"");
        assertThat(settings.attributes().get("title").kind()).isEqualTo(Kind.STRING);

        Expr r = map.definitions().get("r");
        assertThat(r.kind()).isEqualTo(Kind.NUMBER);
        assertThat(at(text, r)).isEqualTo("0.5");
        assertThat(map.callOf(0)).isNull();
    }

    @Test
    void signedNumbersAreLiteralsAndLoopVariablesAreNoDefinitions() {
        String text = """
                i = 0
                Settings { camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) roll -> -10 } }
                Scene { while (i < 2) { Sphere { radius -> 0.5 center -> vec3(i, 0, 0) } i = i + 1 } }
                """;
        CompileResult result = compile(text);
        SourceMap map = result.sourceMap();
        assertThat(result.scene().entities()).hasSize(2);
        ObjectInfo sphere = map.objectAt(result.scene().entities().get(0).span().start());
        assertThat(sphere.attributes().get("center").kind()).isEqualTo(Kind.EXPRESSION);
        assertThat(map.definitions()).doesNotContainKey("i");
        assertThat(map.objects()).as("one description per literal, however often it ran").hasSize(2);
        ObjectInfo camera = map.objectAt(result.scene().settings().camera().span().start());
        assertThat(camera.attributes().get("roll").kind()).isEqualTo(Kind.NUMBER);
    }

    @Test
    void macroMadeEntitiesKnowTheirCallAndParameters() {
        String text = """
                row = Macro (n, size) {
                  i = 0
                  while (i < n) {
                    Sphere { center -> vec3(i, 0, 0) radius -> size }
                    i = i + 1
                  }
                }
                Scene {
                  row(2, 0.25)
                  Box { cornerA -> vec3(0, 0, 0) cornerB -> vec3(1, 1, 1) }
                  row(1, 0.5 * 2)
                }
                """;
        CompileResult result = compile(text);
        assertThat(result.hasErrors()).isFalse();
        SourceMap map = result.sourceMap();
        assertThat(result.scene().entities()).hasSize(4);
        SourceMap.MacroCall first = map.callOf(0);
        assertThat(first.macro()).isEqualTo("row");
        assertThat(first.span().line()).isEqualTo(9);
        assertThat(map.callOf(1)).isSameAs(first);
        assertThat(map.callOf(2)).isNull();
        SourceMap.MacroCall third = map.callOf(3);
        assertThat(third.span().line()).isEqualTo(11);
        assertThat(third.argument("size").kind()).isEqualTo(Kind.EXPRESSION);
        assertThat(first.argument("size").kind()).isEqualTo(Kind.NUMBER);
        assertThat(at(text, first.argument("size"))).isEqualTo("0.25");

        ObjectInfo sphere = map.objectAt(result.scene().entities().get(0).span().start());
        assertThat(sphere.inMacro()).isTrue();
        assertThat(sphere.macroParameters()).containsExactly("n", "size");
        assertThat(sphere.attributes().get("radius").kind()).isEqualTo(Kind.PARAMETER);
    }

    @Test
    void macrosCalledFromMacrosRecordTheChainOfCalls() {
        String text = """
                leaf = Macro (size) { Sphere { radius -> size } }
                pair = Macro (s) {
                  leaf(s)
                  leaf(0.1)
                }
                Scene { pair(0.4) Sphere { } pair(0.6) }
                """;
        CompileResult result = compile(text);
        assertThat(result.hasErrors()).isFalse();
        SourceMap map = result.sourceMap();
        assertThat(result.scene().entities()).hasSize(5);
        SourceMap.MacroCall top = map.callOf(0);
        assertThat(top.macro()).isEqualTo("pair");
        assertThat(top.caller()).isNull();
        assertThat(map.callOf(1)).isSameAs(top);
        assertThat(map.callOf(2)).isNull();
        assertThat(map.makerOf(2)).isNull();
        assertThat(map.callOf(3)).isNotSameAs(top);
        assertThat(map.callOf(3).span().line()).isEqualTo(6);

        SourceMap.MacroCall inner = map.makerOf(0);
        assertThat(inner.macro()).isEqualTo("leaf");
        assertThat(inner.span().line()).isEqualTo(3);
        assertThat(inner.caller()).isSameAs(top);
        assertThat(inner.outermost()).isSameAs(top);
        // Inside pair's body, s is pair's parameter; 0.1 a literal written in the body.
        assertThat(inner.argument("size").kind()).isEqualTo(Kind.PARAMETER);
        assertThat(inner.argument("size").name()).isEqualTo("s");
        assertThat(map.makerOf(1).argument("size").kind()).isEqualTo(Kind.NUMBER);
        assertThat(map.makerOf(1).span().line()).isEqualTo(4);
        assertThat(map.makerOf(3).caller()).isSameAs(map.callOf(3));
        assertThat(at(text, map.makerOf(3).caller().argument("s"))).isEqualTo("0.6");
    }

    @Test
    void csgOperationsAreRecordedWithTheirVariable() {
        String text = """
                cut = Box { cornerA -> vec3(-1, -1, -1) cornerB -> vec3(1, 1, 1) } - Sphere { radius -> 1.3 }
                Scene { cut + Sphere { center -> vec3(0, 2, 0) radius -> 0.5 } }
                """;
        CompileResult result = compile(text);
        SourceMap map = result.sourceMap();
        Entity top = result.scene().entities().get(0);
        assertThat(top).isInstanceOf(Csg.class);
        ObjectInfo union = map.operation(top.span());
        assertThat(union.type()).isEqualTo("Union");
        Csg c = (Csg) top;
        ObjectInfo difference = map.operation(c.left().span());
        assertThat(difference.type()).isEqualTo("Difference");
        assertThat(difference.variable()).isEqualTo("cut");
        assertThat(map.objectAt(((Csg) c.left()).left().span().start()).type()).isEqualTo("Box");
    }

    @Test
    void noMapUnlessAskedFor() {
        CompileResult plain = CrtCompiler.compile(Source.of("a.crt", "Scene { Sphere {} }"), CompileOptions.DEFAULT);
        assertThat(plain.hasErrors()).isFalse();
        assertThat(plain.sourceMap()).isNull();
        assertThat(CompileOptions.DEFAULT.withTime(3).withSourceMap().withTime(4).sourceMap()).isTrue();
    }
}
