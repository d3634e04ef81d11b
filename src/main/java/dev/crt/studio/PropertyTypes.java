package dev.crt.studio;

import dev.crt.scene.ApertureShape;
import dev.crt.scene.Projection;
import dev.crt.scene.Sampler;
import dev.crt.scene.Shading;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What the property sheet knows about each attribute of each object type: how to edit it, its
 * default as a script writes it (null: required or computed), and its range, as the language
 * reference (section 5) gives them. PropertyTypesTest checks every range and default against the
 * compiler, so the sheet and the compiler cannot drift apart.
 */
final class PropertyTypes {
    /** How an attribute is edited. */
    enum Type { VECTOR, COLOR, NUMBER, INTEGER, BOOLEAN, CHOICE, STRING, MATERIAL, OTHER }

    /** One attribute: an interval [low, high] (open ends as flagged) for numbers, the words for choices. */
    record Spec(String name, Type type, String defaultText, double low, boolean lowOpen, double high, boolean highOpen,
            List<String> choices) {
        boolean contains(double v) {
            return (lowOpen ? v > low : v >= low) && (highOpen ? v < high : v <= high);
        }

        /** The range in words, as the compiler's messages write it ("≥ 0", "in [0, 1]"), or "" for any number. */
        String describe() {
            if ((type != Type.NUMBER && type != Type.INTEGER) || (low == Double.NEGATIVE_INFINITY && high == Double.POSITIVE_INFINITY)) {
                return "";
            }
            if (high == Double.POSITIVE_INFINITY) return (lowOpen ? "> " : "≥ ") + ScriptEdits.number(low);
            return "in " + (lowOpen ? "(" : "[") + ScriptEdits.number(low) + ", " + ScriptEdits.number(high) + (highOpen ? ")" : "]");
        }
    }

    private static final double INF = Double.POSITIVE_INFINITY;
    private static final Map<String, Map<String, Spec>> TYPES = new LinkedHashMap<>();

    static {
        type("Sphere", vec("center", "vec3(0, 0, 0)"), num("radius", "1", 0, false, INF, false), mat());
        type("Box", vec("cornerA", null), vec("cornerB", null), mat());
        type("Plane", vec("normal", null), vec("position", "vec3(0, 0, 0)"), mat());
        type("Cylinder", vec("from", null), vec("to", null), num("radius", "1", 0, true, INF, false), bool("capped", "true"), mat());
        type("Cone", vec("from", null), vec("to", null), num("radius", "1", 0, false, INF, false),
                num("radius2", "0", 0, false, INF, false), bool("capped", "true"), mat());
        type("Torus", vec("center", "vec3(0, 0, 0)"), vec("axis", "vec3(0, 1, 0)"), num("major", "1", 0, true, INF, false),
                num("minor", "0.25", 0, true, INF, false), mat());
        type("Mesh", str("file", null), bool("smooth", "true"), other("vertices"), other("faces"), mat());
        type("Material", color("color", "rgb(0.5, 0.5, 0.5)"), any("diffuse", "1"), any("specular", "0"), any("shininess", "30"),
                num("reflectivity", "0", 0, false, 1, false), num("transparency", "0", 0, false, 1, false),
                num("ior", "1", 0, true, INF, false), color("emission", "rgb(0, 0, 0)"), bool("fresnel", "false"),
                color("absorption", "rgb(0, 0, 0)"));
        type("PointLight", vec("origin", null), color("color", "rgb(1, 1, 1)"), num("falloff", "0", 0, false, INF, false),
                num("ambient", "0", 0, false, INF, false));
        type("ParallelLight", vec("from", null), vec("pointing", null), color("color", "rgb(1, 1, 1)"),
                num("ambient", "0", 0, false, INF, false));
        type("SpotLight", vec("origin", null), vec("pointing", null), num("angle", "30", 0, true, 90, false),
                num("innerangle", null, 0, false, 90, false), color("color", "rgb(1, 1, 1)"),
                num("falloff", "0", 0, false, INF, false), num("ambient", "0", 0, false, INF, false));
        type("AreaLight", vec("corner", null), vec("edge1", null), vec("edge2", null), integer("samples", "4", 1, 256),
                color("color", "rgb(1, 1, 1)"), num("falloff", "0", 0, false, INF, false), num("ambient", "0", 0, false, INF, false));
        type("Camera", vec("position", null), vec("pointing", null), num("fov", "60", 0, true, 180, true), any("roll", "0"),
                num("aperture", "0", 0, false, INF, false), num("focaldistance", null, 0, true, INF, false),
                choice("apertureshape", Arrays.stream(ApertureShape.values()).map(ApertureShape::scriptName).toList()),
                choice("projection", Arrays.stream(Projection.values()).map(Projection::scriptName).toList()));
        type("Background", color("color", null), color("horizon", null), color("sky", null), str("image", null), any("angle", "0"));
        type("Checker", color("color1", "rgb(1, 1, 1)"), color("color2", "rgb(0, 0, 0)"), num("scale", "1", 0, true, INF, false));
        type("Settings", str("title", "\"\""), str("author", "\"\""), str("date", "\"\""), str("notes", "\"\""),
                integer("width", "800", 1, Integer.MAX_VALUE), integer("height", "600", 1, Integer.MAX_VALUE),
                integer("supersampling", "1", 1, 64), integer("dofsamples", "1", 1, 4096),
                integer("recursiondepth", "5", 0, Integer.MAX_VALUE), num("gamma", "1", 0, true, INF, false),
                choice("sampler", Arrays.stream(Sampler.values()).map(Sampler::word).toList()),
                integer("seed", null, 0, Integer.MAX_VALUE),
                choice("shading", Arrays.stream(Shading.values()).map(Shading::word).toList()),
                other("camera"), other("lights"), other("background"));
    }

    private PropertyTypes() {}

    private static void type(String name, Spec... specs) {
        Map<String, Spec> m = new LinkedHashMap<>();
        for (Spec s : specs) m.put(s.name(), s);
        TYPES.put(name, m);
    }

    private static Spec vec(String n, String d) { return new Spec(n, Type.VECTOR, d, 0, false, 0, false, List.of()); }

    private static Spec color(String n, String d) { return new Spec(n, Type.COLOR, d, 0, false, 0, false, List.of()); }

    private static Spec num(String n, String d, double lo, boolean loOpen, double hi, boolean hiOpen) {
        return new Spec(n, Type.NUMBER, d, lo, loOpen, hi, hiOpen, List.of());
    }

    private static Spec any(String n, String d) { return num(n, d, Double.NEGATIVE_INFINITY, false, INF, false); }

    private static Spec integer(String n, String d, int lo, int hi) {
        return new Spec(n, Type.INTEGER, d, lo, false, hi == Integer.MAX_VALUE ? INF : hi, false, List.of());
    }

    private static Spec bool(String n, String d) { return new Spec(n, Type.BOOLEAN, d, 0, false, 0, false, List.of()); }

    private static Spec str(String n, String d) { return new Spec(n, Type.STRING, d, 0, false, 0, false, List.of()); }

    private static Spec choice(String n, List<String> words) {
        return new Spec(n, Type.CHOICE, "\"" + words.get(0) + "\"", 0, false, 0, false, List.copyOf(words));
    }

    private static Spec mat() { return new Spec("material", Type.MATERIAL, null, 0, false, 0, false, List.of()); }

    private static Spec other(String n) { return new Spec(n, Type.OTHER, null, 0, false, 0, false, List.of()); }

    /** The attributes of {@code type} in the order the sheet shows them (empty for an unknown type). */
    static Map<String, Spec> of(String type) { return TYPES.getOrDefault(type, Map.of()); }

    static Map<String, Map<String, Spec>> all() { return TYPES; }
}
