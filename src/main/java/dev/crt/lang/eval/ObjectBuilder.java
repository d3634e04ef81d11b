package dev.crt.lang.eval;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.lang.eval.Attributes.Range;
import dev.crt.lang.parser.CRTParser;
import dev.crt.lang.value.BackgroundValue;
import dev.crt.lang.value.CameraValue;
import dev.crt.lang.value.EntityValue;
import dev.crt.lang.value.LightValue;
import dev.crt.lang.value.MaterialValue;
import dev.crt.lang.value.Value;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Background;
import dev.crt.scene.Box;
import dev.crt.scene.Camera;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Material;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.Plane;
import dev.crt.scene.PointLight;
import dev.crt.scene.Rgb;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Sphere;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.BiFunction;

/** Builds the values of object literals {@code Type { attr -> expr … }} per section 5 of the reference. */
final class ObjectBuilder {
    private record ObjectType(Set<String> attributes, BiFunction<ObjectBuilder, Attributes, Value> build) {}

    private static final Map<String, ObjectType> TYPES = new LinkedHashMap<>();

    static {
        type("Camera", ObjectBuilder::camera, "position", "pointing", "fov", "roll", "aperture", "focaldistance", "apertureshape");
        type("PointLight", ObjectBuilder::pointLight, "origin", "color", "falloff", "ambient");
        type("ParallelLight", ObjectBuilder::parallelLight, "from", "pointing", "color", "ambient");
        type("Material", ObjectBuilder::material, "color", "diffuse", "specular", "shininess", "reflectivity",
                "transparency", "ior", "emission");
        type("Sphere", ObjectBuilder::sphere, "center", "radius", "material");
        type("Box", ObjectBuilder::box, "cornerA", "cornerB", "material");
        type("Plane", ObjectBuilder::plane, "normal", "position", "material");
        type("Background", ObjectBuilder::background, "color", "horizon", "sky", "image", "angle");
    }

    private static void type(String name, BiFunction<ObjectBuilder, Attributes, Value> build, String... attributes) {
        TYPES.put(name, new ObjectType(Set.copyOf(Arrays.asList(attributes)), build));
    }

    /** Each type's attribute names, in the order of the table above. */
    static Map<String, Set<String>> attributeNames() {
        Map<String, Set<String>> names = new LinkedHashMap<>();
        TYPES.forEach((type, t) -> names.put(type, t.attributes()));
        return names;
    }

    private final Evaluator evaluator;
    private final Assets assets;

    ObjectBuilder(Evaluator evaluator, Assets assets) {
        this.evaluator = evaluator;
        this.assets = assets;
    }

    Value build(CRTParser.ObjectContext ctx) {
        String typeName = ctx.NAME().getText();
        SourceSpan typeSpan = evaluator.span(ctx.NAME().getSymbol());
        ObjectType type = TYPES.get(typeName);
        if (type == null) {
            throw evaluator.error("unknown type '" + typeName + "'" + Spelling.suggestion(typeName, TYPES.keySet()), typeSpan);
        }
        Attributes a = evaluate(typeName, type.attributes(), ctx.attribute(), typeSpan, evaluator.span(ctx));
        Value value = type.build().apply(this, a);
        a.finish();
        return value;
    }

    /** Evaluates every attribute, reporting unknown, duplicated and failing ones without stopping. */
    Attributes evaluate(String typeName, Set<String> known, List<CRTParser.AttributeContext> written,
            SourceSpan typeSpan, SourceSpan objectSpan) {
        Attributes a = new Attributes(evaluator, typeName, typeSpan, objectSpan);
        for (CRTParser.AttributeContext attr : written) {
            String name = attr.IDENT().getText();
            SourceSpan at = evaluator.span(attr);
            // A wrong name is the name's fault alone: underline just it, as the reference's example does.
            SourceSpan nameSpan = evaluator.span(attr.IDENT().getSymbol());
            if (!known.contains(name)) {
                a.markFailed();
                evaluator.report(evaluator.error("unknown attribute '" + name + "' for " + typeName
                        + Spelling.suggestion(name, known), nameSpan));
                continue;
            }
            if (a.has(name)) {
                SourceSpan first = a.spanOf(name);
                a.markFailed();
                evaluator.report(evaluator.error("attribute '" + name + "' is given twice (first at " + first.line()
                        + ":" + first.column() + ")", nameSpan));
                continue;
            }
            try {
                a.put(name, new Attributes.Given(evaluator.evaluate(attr.expression()), at));
            } catch (EvaluationStopped stop) {
                throw stop;
            } catch (ScriptError e) {
                a.markFailed();
                evaluator.report(e);
            } catch (Failed f) {
                a.markFailed();
            }
        }
        return a;
    }

    private Value camera(Attributes a) {
        Vec3 position = a.vector("position", null);
        Vec3 pointing = a.vector("pointing", null);
        double fov = a.number("fov", 60, new Range(0, true, 180, true));
        double roll = a.number("roll", 0, Range.ANY);
        double aperture = a.number("aperture", 0, Range.NOT_NEGATIVE);
        double distance = position.minus(pointing).length();
        if (a.has("position") && a.has("pointing") && distance == 0) {
            a.error("pointing", "the camera's pointing must differ from its position");
        }
        double focalDistance = a.number("focaldistance", distance, Range.POSITIVE);
        String shapeName = a.string("apertureshape", "circle");
        ApertureShape shape = ApertureShape.CIRCLE;
        List<String> shapes = new ArrayList<>();
        for (ApertureShape s : ApertureShape.values()) {
            shapes.add(s.scriptName());
            if (s.scriptName().equals(shapeName)) shape = s;
        }
        if (!shapes.contains(shapeName)) {
            a.error("apertureshape", "apertureshape must be one of \"" + String.join("\", \"", shapes) + "\", got \""
                    + shapeName + "\"" + Spelling.suggestion(shapeName.toLowerCase(Locale.ROOT), shapes));
        }
        return new CameraValue(new Camera(position, pointing, fov, roll, aperture, focalDistance, shape, a.typeSpan()));
    }

    private Value pointLight(Attributes a) {
        return new LightValue(new PointLight(a.vector("origin", null), a.color("color", Rgb.WHITE),
                a.number("falloff", 0, Range.NOT_NEGATIVE), a.number("ambient", 0, Range.NOT_NEGATIVE), a.typeSpan()));
    }

    private Value parallelLight(Attributes a) {
        Vec3 from = a.vector("from", null);
        Vec3 pointing = a.vector("pointing", null);
        // By distance, not equals: -0 and 0 are the same coordinate.
        if (a.has("from") && a.has("pointing") && from.minus(pointing).length() == 0) {
            a.error("pointing", "a ParallelLight's pointing must differ from its from");
        }
        return new LightValue(new ParallelLight(from, pointing, a.color("color", Rgb.WHITE),
                a.number("ambient", 0, Range.NOT_NEGATIVE), a.typeSpan()));
    }

    private Value material(Attributes a) {
        Material d = Material.DEFAULT;
        return new MaterialValue(new Material(
                a.color("color", d.color()),
                a.number("diffuse", d.diffuse(), Range.ANY),
                a.number("specular", d.specular(), Range.ANY),
                a.number("shininess", d.shininess(), Range.ANY),
                a.number("reflectivity", d.reflectivity(), Range.UNIT),
                a.number("transparency", d.transparency(), Range.UNIT),
                a.number("ior", d.ior(), Range.POSITIVE),
                a.color("emission", d.emission()),
                a.has("diffuse")));
    }

    private Value sphere(Attributes a) {
        return EntityValue.of(new Sphere(a.vector("center", Vec3.ZERO), a.number("radius", 1, Range.NOT_NEGATIVE),
                a.material("material"), Transform.IDENTITY, a.objectSpan()));
    }

    private Value box(Attributes a) {
        return EntityValue.of(Box.ofCorners(a.vector("cornerA", null), a.vector("cornerB", null), a.material("material"),
                Transform.IDENTITY, a.objectSpan()));
    }

    private Value plane(Attributes a) {
        Vec3 normal = a.vector("normal", null);
        Vec3 unit = Builtins.unit(normal);
        if (a.has("normal") && unit == null) {
            a.error("normal", "a Plane's normal must not be the zero vector");
        }
        if (unit == null) unit = Vec3.Y;
        return EntityValue.of(new Plane(unit, a.vector("position", Vec3.ZERO), a.material("material"),
                Transform.IDENTITY, a.objectSpan()));
    }

    private Value background(Attributes a) {
        List<String> forms = new ArrayList<>();
        if (a.has("color")) forms.add("color");
        if (a.has("horizon") || a.has("sky")) forms.add("horizon and sky");
        if (a.has("image")) forms.add("image");
        if (forms.size() != 1) {
            String got = forms.isEmpty() ? "none" : String.join(" and ", forms);
            String at = a.given().isEmpty() ? null : a.given().keySet().iterator().next();
            a.error(at == null ? "" : at, "a Background takes exactly one of: color, horizon with sky, or image (with angle); got " + got);
            return new BackgroundValue(Background.BLACK);
        }
        if (a.has("angle") && !a.has("image")) a.error("angle", "angle only goes with image");
        Background background = switch (forms.get(0)) {
            case "color" -> new SolidBackground(a.color("color", Rgb.BLACK));
            case "image" -> panorama(a);
            default -> gradient(a);
        };
        return new BackgroundValue(background);
    }

    private Background gradient(Attributes a) {
        if (!a.has("horizon")) a.error("sky", "a Background with sky needs horizon too");
        if (!a.has("sky")) a.error("horizon", "a Background with horizon needs sky too");
        return new GradientBackground(a.color("horizon", Rgb.BLACK), a.color("sky", Rgb.BLACK));
    }

    private Background panorama(Attributes a) {
        String image = a.string("image", null);
        double angle = a.number("angle", 0, Range.ANY);
        if (image == null) return Background.BLACK;
        try {
            return assets.panorama(image, angle);
        } catch (Assets.AssetProblem problem) {
            a.error("image", problem.getMessage());
            return Background.BLACK;
        }
    }
}
