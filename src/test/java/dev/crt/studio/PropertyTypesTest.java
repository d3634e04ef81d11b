package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Diagnostic;
import dev.crt.lang.Source;
import dev.crt.lang.eval.Vocabulary;
import dev.crt.studio.PropertyTypes.Spec;
import dev.crt.studio.PropertyTypes.Type;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** The property sheet's table of attributes agrees with the compiler: names, defaults, ranges, words. */
class PropertyTypesTest {
    /** A script in which {@code attribute} of {@code type} is written as {@code literal}, every other requirement met. */
    private static String script(String type, String attribute, String literal) {
        String a = attribute + " -> " + literal;
        return switch (type) {
            case "Sphere", "Torus" -> "Scene { " + type + " { " + a + " } }";
            case "Box" -> "Scene { Box { " + without(attribute, "cornerA -> vec3(0, 0, 0) cornerB -> vec3(1, 1, 1)") + a + " } }";
            case "Plane" -> "Scene { Plane { " + without(attribute, "normal -> vec3(0, 1, 0)") + a + " } }";
            case "Cylinder" -> "Scene { Cylinder { " + without(attribute, "from -> vec3(0, 0, 0) to -> vec3(0, 1, 0)") + a + " } }";
            case "Cone" -> "Scene { Cone { " + without(attribute, "from -> vec3(0, 0, 0) to -> vec3(0, 1, 0)")
                    + (attribute.startsWith("radius") ? (attribute.equals("radius") ? "radius2 -> 0.5 " : "radius -> 1 ") : "") + a + " } }";
            case "Material" -> "Scene { Sphere { material -> Material { " + a + " } } }";
            case "Checker" -> "Scene { Sphere { material -> Material { color -> Checker { " + a + " } } } }";
            case "PointLight" -> "Settings { lights -> [PointLight { " + without(attribute, "origin -> vec3(0, 1, 0)") + a + " }] }";
            case "ParallelLight" -> "Settings { lights -> [ParallelLight { "
                    + without(attribute, "from -> vec3(0, 1, 0) pointing -> vec3(0, 0, 0)") + a + " }] }";
            case "SpotLight" -> "Settings { lights -> [SpotLight { "
                    + without(attribute, "origin -> vec3(0, 1, 0) pointing -> vec3(0, 0, 0) angle -> 40") + a + " }] }";
            case "AreaLight" -> "Settings { lights -> [AreaLight { "
                    + without(attribute, "corner -> vec3(0, 1, 0) edge1 -> vec3(1, 0, 0) edge2 -> vec3(0, 0, 1)") + a + " }] }";
            case "Camera" -> "Settings { camera -> Camera { "
                    + without(attribute, "position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0)") + a + " } }";
            case "Background" -> "Settings { background -> Background { " + a + " } }";
            case "Settings" -> "Settings { " + a + " }";
            default -> null;
        };
    }

    /** The required attributes, less the one under test. */
    private static String without(String attribute, String required) {
        StringBuilder out = new StringBuilder();
        for (String part : required.split("(?<=\\)) ")) {
            if (!part.startsWith(attribute + " ")) out.append(part).append(' ');
        }
        return out.toString();
    }

    private static String errorsOf(String text) {
        CompileResult r = CrtCompiler.compile(Source.of("t.crt", text + "\nScene { }"), CompileOptions.DEFAULT);
        return r.diagnostics().stream().filter(Diagnostic::isError).map(Diagnostic::message).collect(Collectors.joining("; "));
    }

    @Test
    void everyTypeAndAttributeIsOneTheCompilerKnows() {
        Map<String, java.util.List<String>> known = Vocabulary.objectTypes();
        PropertyTypes.all().forEach((type, specs) -> {
            java.util.List<String> names = type.equals("Settings") ? Vocabulary.settingsAttributes() : known.get(type);
            assertThat(names).as(type).isNotNull();
            assertThat(names).as(type).containsAll(specs.keySet());
        });
    }

    @Test
    void defaultsRangesAndWordsAreTheCompilers() {
        int checked = 0;
        for (Map.Entry<String, Map<String, Spec>> type : PropertyTypes.all().entrySet()) {
            for (Spec spec : type.getValue().values()) {
                if (spec.type() == Type.OTHER || spec.type() == Type.MATERIAL) continue;
                String t = type.getKey();
                if (script(t, spec.name(), "1") == null) continue;
                if (spec.defaultText() != null && !t.equals("Background")) {
                    assertThat(errorsOf(script(t, spec.name(), spec.defaultText()))).as(t + "." + spec.name() + " default").isEmpty();
                    checked++;
                }
                if (spec.type() == Type.NUMBER || spec.type() == Type.INTEGER) {
                    double step = spec.type() == Type.INTEGER ? 1 : 0.5;
                    if (Double.isFinite(spec.low())) {
                        double outside = spec.lowOpen() ? spec.low() : spec.low() - step;
                        assertThat(errorsOf(script(t, spec.name(), ScriptEdits.number(outside)))).as(t + "." + spec.name() + " below")
                                .contains(spec.name());
                        if (!spec.lowOpen()) {
                            assertThat(errorsOf(script(t, spec.name(), ScriptEdits.number(spec.low())))).as(t + "." + spec.name() + " at low")
                                    .isEmpty();
                        }
                        checked += 2;
                    }
                    if (Double.isFinite(spec.high())) {
                        double outside = spec.highOpen() ? spec.high() : spec.high() + step;
                        assertThat(errorsOf(script(t, spec.name(), ScriptEdits.number(outside)))).as(t + "." + spec.name() + " above")
                                .contains(spec.name());
                        checked++;
                    }
                }
                if (spec.type() == Type.CHOICE) {
                    for (String word : spec.choices()) {
                        assertThat(errorsOf(script(t, spec.name(), "\"" + word + "\""))).as(t + "." + spec.name() + " " + word).isEmpty();
                    }
                    assertThat(errorsOf(script(t, spec.name(), "\"nonsense\""))).contains(spec.name());
                    checked++;
                }
            }
        }
        assertThat(checked).isGreaterThan(60);
    }
}
