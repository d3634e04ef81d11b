package dev.crt.lang.eval;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.lang.eval.Attributes.Range;
import dev.crt.lang.parser.CRTParser;
import dev.crt.lang.value.BackgroundValue;
import dev.crt.lang.value.CameraValue;
import dev.crt.lang.value.EntityValue;
import dev.crt.lang.value.LightValue;
import dev.crt.lang.value.ListValue;
import dev.crt.lang.value.MaterialValue;
import dev.crt.lang.value.NumberValue;
import dev.crt.lang.value.TextureValue;
import dev.crt.lang.value.Value;
import dev.crt.lang.value.VectorValue;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.AreaLight;
import dev.crt.scene.Background;
import dev.crt.scene.Box;
import dev.crt.scene.Checker;
import dev.crt.scene.Camera;
import dev.crt.scene.Cone;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Finish;
import dev.crt.scene.ImageTexture;
import dev.crt.scene.Marble;
import dev.crt.scene.Noise;
import dev.crt.scene.ShadingModel;
import dev.crt.scene.TextureMapping;
import dev.crt.scene.Wood;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Material;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.Plane;
import dev.crt.scene.PointLight;
import dev.crt.scene.Projection;
import dev.crt.scene.Rgb;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.SpotLight;
import dev.crt.scene.Texture;
import dev.crt.scene.Torus;
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
    /** A type of object literal: its attributes' names and its builder. */
    record ObjectType(Set<String> attributes, String[] names, BiFunction<ObjectBuilder, Attributes, Value> build) {
        /**
         * The table's own String of attribute {@code name}, or null when the type has none of that
         * name. An array in the table's order, not the set: this runs for every attribute of every
         * literal, mostly before the JIT has compiled it, and a set's iterator costs more there.
         */
        String canonical(String name) {
            for (String known : names) if (known.equals(name)) return known;
            return null;
        }
    }

    private static final Map<String, ObjectType> TYPES = new LinkedHashMap<>();
    /** The attributes of the Perlin-noise solid textures. */
    private static final String[] SOLID = {"color1", "color2", "scale", "turbulence", "octaves"};


    static {
        type("Camera", ObjectBuilder::camera, "position", "pointing", "fov", "roll", "aperture", "focaldistance", "apertureshape",
                "projection");
        type("PointLight", ObjectBuilder::pointLight, "origin", "color", "falloff", "ambient");
        type("ParallelLight", ObjectBuilder::parallelLight, "from", "pointing", "color", "ambient");
        type("SpotLight", ObjectBuilder::spotLight, "origin", "pointing", "angle", "innerangle", "color", "falloff", "ambient");
        type("AreaLight", ObjectBuilder::areaLight, "corner", "edge1", "edge2", "samples", "color", "falloff", "ambient");
        type("Material", ObjectBuilder::material, "color", "diffuse", "specular", "shininess", "reflectivity",
                "transparency", "ior", "emission", "fresnel", "absorption", "roughness", "glossysamples", "bump",
                "bumpscale", "model", "cool", "warm", "outline");
        type("Checker", ObjectBuilder::checker, "color1", "color2", "scale");
        type("Noise", (b, a) -> solid(a, Noise::new), SOLID);
        type("Wood", (b, a) -> solid(a, Wood::new), SOLID);
        type("Marble", (b, a) -> solid(a, Marble::new), SOLID);
        type("ImageTexture", ObjectBuilder::imageTexture, "file", "mapping", "scale", "rotate", "offset");
        type("Sphere", ObjectBuilder::sphere, "center", "radius", "material");
        type("Box", ObjectBuilder::box, "cornerA", "cornerB", "material");
        type("Plane", ObjectBuilder::plane, "normal", "position", "material");
        type("Cylinder", ObjectBuilder::cylinder, "from", "to", "radius", "capped", "material");
        type("Mesh", ObjectBuilder::mesh, "file", "vertices", "faces", "smooth", "material");
        type("Torus", ObjectBuilder::torus, "center", "axis", "major", "minor", "material");
        type("Cone", ObjectBuilder::cone, "from", "to", "radius", "radius2", "capped", "material");
        type("Background", ObjectBuilder::background, "color", "horizon", "sky", "image", "angle");
    }

    private static void type(String name, BiFunction<ObjectBuilder, Attributes, Value> build, String... attributes) {
        TYPES.put(name, new ObjectType(Set.copyOf(Arrays.asList(attributes)), attributes, build));
    }

    /** An area light's n is capped so that n² shadow rays per shading point stay a render, not a hang. */
    static final int MAX_AREA_SAMPLES = 256;

    /** The type of this name, or null. */
    static ObjectType type(String name) { return TYPES.get(name); }

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
        if (evaluator.repeats()) {
            Plan plan = ctx.cached instanceof Plan p ? p : plan(ctx);
            if (plan != null) return build(plan);
        }
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

    /**
     * An object literal in a loop or macro body, checked once: its type, its attributes' names as
     * the type table spells them (the builders' own strings), their spans and compiled expressions.
     * A million turns of a loop then do no lookups by name but the builder's own.
     */
    private record Plan(String typeName, ObjectType type, SourceSpan typeSpan, SourceSpan objectSpan,
            String[] names, SourceSpan[] spans, Evaluator.Code[] values) {}

    /** The plan of a literal without mistakes of name (kept on it), or null: the general path then reports them. */
    private Plan plan(CRTParser.ObjectContext ctx) {
        String typeName = ctx.NAME().getText();
        ObjectType type = TYPES.get(typeName);
        if (type == null) return null;
        List<CRTParser.AttributeContext> written = ctx.attribute();
        int n = written.size();
        String[] names = new String[n];
        SourceSpan[] spans = new SourceSpan[n];
        Evaluator.Code[] values = new Evaluator.Code[n];
        for (int i = 0; i < n; i++) {
            CRTParser.AttributeContext attr = written.get(i);
            String name = type.canonical(attr.key.getText());
            if (name == null) return null;
            for (int j = 0; j < i; j++) if (names[j] == name) return null;
            names[i] = name;
            spans[i] = evaluator.span(attr);
            values[i] = evaluator.code(attr.expression());
        }
        Plan plan = new Plan(typeName, type, evaluator.span(ctx.NAME().getSymbol()), evaluator.span(ctx), names, spans, values);
        ctx.cached = plan;
        return plan;
    }

    /** Does what {@link #evaluate} and the rest of {@link #build(CRTParser.ObjectContext)} do, from a plan. */
    private Value build(Plan plan) {
        Attributes a = new Attributes(evaluator, plan.typeName(), plan.typeSpan(), plan.objectSpan());
        String[] names = plan.names();
        for (int i = 0; i < names.length; i++) put(a, names[i], plan.values()[i], plan.spans()[i]);
        Value value = plan.type().build().apply(this, a);
        a.finish();
        return value;
    }

    /** Evaluates every attribute, reporting unknown, duplicated and failing ones without stopping. */
    Attributes evaluate(String typeName, Set<String> known, List<CRTParser.AttributeContext> written,
            SourceSpan typeSpan, SourceSpan objectSpan) {
        Attributes a = new Attributes(evaluator, typeName, typeSpan, objectSpan);
        for (CRTParser.AttributeContext attr : written) {
            String name = attr.key.getText();
            SourceSpan at = evaluator.span(attr);
            // A wrong name is the name's fault alone: underline just it, as the reference's example does.
            SourceSpan nameSpan = evaluator.span(attr.key);
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
            put(a, name, () -> evaluator.evaluate(attr.expression()), at);
        }
        return a;
    }

    /** Evaluates one attribute into {@code a}; a failure is reported and marks the object failed, the others still run. */
    private void put(Attributes a, String name, Evaluator.Code value, SourceSpan at) {
        try {
            a.put(name, new Attributes.Given(value.run(), at));
        } catch (EvaluationStopped stop) {
            throw stop;
        } catch (ScriptError e) {
            a.markFailed(name);
            evaluator.report(e);
        } catch (Failed f) {
            a.markFailed(name);
        }
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
        String projectionName = a.string("projection", "perspective");
        Projection projection = Projection.PERSPECTIVE;
        List<String> projections = new ArrayList<>();
        for (Projection p : Projection.values()) {
            projections.add(p.scriptName());
            if (p.scriptName().equals(projectionName)) projection = p;
        }
        if (!projections.contains(projectionName)) {
            a.error("projection", "projection must be one of \"" + String.join("\", \"", projections) + "\", got \""
                    + projectionName + "\"" + Spelling.suggestion(projectionName.toLowerCase(Locale.ROOT), projections));
        }
        return new CameraValue(new Camera(position, pointing, fov, roll, aperture, focalDistance, shape, projection,
                a.typeSpan()));
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

    private Value spotLight(Attributes a) {
        Vec3 origin = a.vector("origin", null), pointing = a.vector("pointing", null);
        if (a.has("origin") && a.has("pointing") && origin.minus(pointing).length() == 0) {
            a.error("pointing", "a SpotLight's pointing must differ from its origin");
        }
        double angle = a.number("angle", 30, new Range(0, true, 90, false));
        double inner = a.number("innerangle", angle, new Range(0, false, angle, false));
        return new LightValue(new SpotLight(origin, pointing, angle, inner, a.color("color", Rgb.WHITE),
                a.number("falloff", 0, Range.NOT_NEGATIVE), a.number("ambient", 0, Range.NOT_NEGATIVE), a.typeSpan()));
    }

    private Value areaLight(Attributes a) {
        Vec3 corner = a.vector("corner", null), e1 = a.vector("edge1", null), e2 = a.vector("edge2", null);
        if (a.has("edge1") && a.has("edge2") && e1.cross(e2).length() == 0) {
            a.error("edge2", "an AreaLight's edge1 and edge2 must span a parallelogram (not zero, not parallel)");
        }
        int samples = a.integer("samples", 4, 1);
        if (samples > MAX_AREA_SAMPLES) {
            a.error("samples", "samples must be at most " + MAX_AREA_SAMPLES + " (that is " + MAX_AREA_SAMPLES * MAX_AREA_SAMPLES
                    + " shadow rays per shading point), got " + samples);
        }
        return new LightValue(new AreaLight(corner, e1, e2, samples, a.color("color", Rgb.WHITE),
                a.number("falloff", 0, Range.NOT_NEGATIVE), a.number("ambient", 0, Range.NOT_NEGATIVE), a.typeSpan()));
    }

    private Value checker(Attributes a) {
        Texture t1 = a.texture("color1"), t2 = a.texture("color2");
        return new TextureValue(new Checker(t1 != null ? Rgb.WHITE : a.color("color1", Rgb.WHITE),
                t2 != null ? Rgb.BLACK : a.color("color2", Rgb.BLACK), a.number("scale", 1, Range.POSITIVE), t1, t2));
    }

    /** A solid texture of the Perlin-noise family, built by its record's constructor. */
    private interface SolidTexture {
        Texture make(Rgb color1, Rgb color2, double scale, double turbulence, int octaves);
    }

    /** The most octaves a noise sum takes: beyond about 16 the terms are below a double's resolution of the first. */
    static final int MAX_OCTAVES = 16;

    private static Value solid(Attributes a, SolidTexture make) {
        return new TextureValue(make.make(a.color("color1", Rgb.WHITE), a.color("color2", Rgb.BLACK),
                a.number("scale", 1, Range.POSITIVE), a.number("turbulence", 0, Range.NOT_NEGATIVE),
                a.integer("octaves", 4, 1, MAX_OCTAVES)));
    }

    private Value imageTexture(Attributes a) {
        String file = a.string("file", null);
        TextureMapping mapping = choice(a, "mapping", TextureMapping.UV, TextureMapping.values(), TextureMapping::scriptName);
        Vec3 scale = a.numberOrVector("scale", new Vec3(1, 1, 1));
        if (scale.x() == 0 || scale.y() == 0 || scale.z() == 0) a.error("scale", "an ImageTexture's scale must not be 0 in any axis");
        Vec3 rotate = a.vector("rotate", Vec3.ZERO), offset = a.vector("offset", Vec3.ZERO);
        if (file == null) return new TextureValue(new Checker(Rgb.WHITE, Rgb.BLACK, 1));
        try {
            Assets.Image image = assets.image(file);
            return new TextureValue(new ImageTexture(image.file().toString(), image.picture(), mapping, scale, rotate, offset));
        } catch (Assets.AssetProblem problem) {
            a.error("file", problem.getMessage());
            return new TextureValue(new Checker(Rgb.WHITE, Rgb.BLACK, 1));
        }
    }

    /** A string attribute naming one of {@code values}; anything else is a diagnostic listing them. */
    private static <T> T choice(Attributes a, String name, T fallback, T[] values, java.util.function.Function<T, String> script) {
        String given = a.string(name, script.apply(fallback));
        List<String> names = new ArrayList<>();
        for (T v : values) {
            names.add(script.apply(v));
            if (script.apply(v).equals(given)) return v;
        }
        a.error(name, name + " must be one of \"" + String.join("\", \"", names) + "\", got \"" + given + "\""
                + Spelling.suggestion(given.toLowerCase(Locale.ROOT), names));
        return fallback;
    }

    private Value material(Attributes a) {
        Material d = Material.DEFAULT;
        Finish f = Finish.NONE;
        Texture texture = a.texture("color"), emission = a.texture("emission");
        Texture specular = a.texture("specular"), reflectivity = a.texture("reflectivity"), transparency = a.texture("transparency");
        Finish finish;
        if (emission == null && specular == null && reflectivity == null && transparency == null && noneWritten(a, FINISH_ONLY)) {
            // Most materials: nothing of the finish is written, so it is NONE, with nothing to check
            // (a record's equals is slow before the JIT: a tenth of a written-out scene's compile).
            finish = f;
        } else {
            finish = new Finish(emission, specular, reflectivity, transparency,
                    a.requiredTexture("bump"), a.number("bumpscale", f.bumpScale(), Range.ANY),
                    a.number("roughness", f.roughness(), Range.UNIT), a.integer("glossysamples", f.glossySamples(), 1, MAX_GLOSSY_SAMPLES),
                    choice(a, "model", ShadingModel.PHONG, ShadingModel.values(), ShadingModel::scriptName),
                    a.color("cool", f.cool()), a.color("warm", f.warm()), a.number("outline", f.outline(), Range.NOT_NEGATIVE));
            if (finish.equals(Finish.NONE)) finish = Finish.NONE;
        }
        return new MaterialValue(new Material(
                texture != null ? d.color() : a.color("color", d.color()),
                a.number("diffuse", d.diffuse(), Range.ANY),
                a.numberOrTexture("specular", d.specular(), Range.ANY),
                a.number("shininess", d.shininess(), Range.ANY),
                a.numberOrTexture("reflectivity", d.reflectivity(), Range.UNIT),
                a.numberOrTexture("transparency", d.transparency(), Range.UNIT),
                a.number("ior", d.ior(), Range.POSITIVE),
                emission != null ? d.emission() : a.color("emission", d.emission()),
                a.has("diffuse"),
                a.bool("fresnel", false),
                absorption(a),
                texture,
                finish));
    }

    /** A Material's attributes that only its {@link Finish} reads. */
    private static final String[] FINISH_ONLY = {"bump", "bumpscale", "roughness", "glossysamples", "model", "cool", "warm", "outline"};

    private static boolean noneWritten(Attributes a, String[] names) {
        for (String n : names) if (a.written(n)) return false;
        return true;
    }

    /** Glossy lobe samples per shading point are capped, as area light samples are. */
    static final int MAX_GLOSSY_SAMPLES = 256;

    private static Rgb absorption(Attributes a) {
        Rgb c = a.color("absorption", Rgb.BLACK);
        if (c.r() < 0 || c.g() < 0 || c.b() < 0) {
            a.error("absorption", "absorption must not be negative, got rgb(" + NumberValue.format(c.r()) + ", "
                    + NumberValue.format(c.g()) + ", " + NumberValue.format(c.b()) + ")");
            return Rgb.BLACK;
        }
        return c;
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

    private Value cylinder(Attributes a) {
        Vec3 from = a.vector("from", null), to = a.vector("to", null);
        axis(a, "Cylinder", from, to);
        return EntityValue.of(new Cylinder(from, to, a.number("radius", 1, Range.POSITIVE), a.bool("capped", true),
                a.material("material"), Transform.IDENTITY, a.objectSpan()));
    }

    private Value mesh(Attributes a) {
        boolean smooth = a.bool("smooth", true);
        MeshData data = null;
        if (a.written("file") == (a.written("vertices") || a.written("faces"))) {
            String at = a.written("file") ? "file" : "";
            a.error(at, "a Mesh takes either file, or vertices with faces");
        } else if (a.written("file")) {
            String file = a.string("file", null);
            if (file != null) {
                try {
                    data = assets.mesh(file);
                } catch (Assets.AssetProblem problem) {
                    a.error("file", problem.getMessage());
                }
            }
        } else if (!a.written("vertices") || !a.written("faces")) {
            a.error(a.written("vertices") ? "vertices" : "faces", "an inline Mesh needs both vertices and faces");
        } else if (a.has("vertices") && a.has("faces")) {
            data = inlineMesh(a);
        }
        if (data == null) {
            a.markFailed();
            return EntityValue.of(new Sphere(Vec3.ZERO, 0, a.material("material"), Transform.IDENTITY, a.objectSpan()));
        }
        return EntityValue.of(new Mesh(data, smooth, a.material("material"), Transform.IDENTITY, a.objectSpan()));
    }

    /** vertices: a list of vec3; faces: a list of lists of 0-based vertex indices (polygons are fanned). */
    private MeshData inlineMesh(Attributes a) {
        MeshBuilder b = new MeshBuilder();
        String attribute = "vertices";
        try {
            if (!(a.value("vertices") instanceof ListValue vs)) {
                a.error("vertices", "vertices must be a list of vec3");
                return null;
            }
            for (int i = 0; i < vs.items().size(); i++) {
                if (!(vs.items().get(i) instanceof VectorValue v)) {
                    a.error("vertices", "vertices[" + i + "] must be a vec3, got " + vs.items().get(i).typeName());
                    return null;
                }
                b.position(v.vector().x(), v.vector().y(), v.vector().z(), "");
            }
            attribute = "faces";
            if (!(a.value("faces") instanceof ListValue fs)) {
                a.error("faces", "faces must be a list of lists of vertex indices");
                return null;
            }
            for (int i = 0; i < fs.items().size(); i++) {
                if (!(fs.items().get(i) instanceof ListValue face)) {
                    a.error("faces", "faces[" + i + "] must be a list of vertex indices");
                    return null;
                }
                int n = face.items().size();
                int[] corners = new int[3 * n];
                for (int k = 0; k < n; k++) {
                    if (!(face.items().get(k) instanceof NumberValue index) || !index.integral()) {
                        a.error("faces", "faces[" + i + "][" + k + "] must be a whole number");
                        return null;
                    }
                    corners[3 * k] = (int) Math.max(Integer.MIN_VALUE, Math.min(Integer.MAX_VALUE, index.value()));
                    corners[3 * k + 1] = -1;
                    corners[3 * k + 2] = -1;
                }
                b.polygon(corners, n, "faces[" + i + "]: ");
            }
            return b.finish("inline mesh");
        } catch (MeshBuilder.MeshProblem problem) {
            a.error(attribute, problem.getMessage());
            return null;
        }
    }

    private Value torus(Attributes a) {
        Vec3 axis = a.vector("axis", Vec3.Y);
        Vec3 unit = Builtins.unit(axis);
        if (a.has("axis") && unit == null) a.error("axis", "a Torus's axis must not be the zero vector");
        return EntityValue.of(new Torus(a.vector("center", Vec3.ZERO), unit == null ? Vec3.Y : unit,
                a.number("major", 1, Range.POSITIVE), a.number("minor", 0.25, Range.POSITIVE), a.material("material"),
                Transform.IDENTITY, a.objectSpan()));
    }

    private Value cone(Attributes a) {
        Vec3 from = a.vector("from", null), to = a.vector("to", null);
        axis(a, "Cone", from, to);
        double r0 = a.number("radius", 1, Range.NOT_NEGATIVE), r1 = a.number("radius2", 0, Range.NOT_NEGATIVE);
        if (r0 == 0 && r1 == 0) a.error(a.has("radius2") ? "radius2" : "radius", "a Cone's radius and radius2 cannot both be 0");
        return EntityValue.of(new Cone(from, to, r0, r1, a.bool("capped", true), a.material("material"),
                Transform.IDENTITY, a.objectSpan()));
    }

    /** The axis of a Cylinder or Cone must have a length (by distance: -0 and 0 are the same coordinate). */
    private static void axis(Attributes a, String type, Vec3 from, Vec3 to) {
        if (a.has("from") && a.has("to") && from.minus(to).length() == 0) {
            a.error("to", "a " + type + "'s to must differ from its from");
        }
    }

    private Value background(Attributes a) {
        List<String> forms = new ArrayList<>();
        if (a.written("color")) forms.add("color");
        if (a.written("horizon") || a.written("sky")) forms.add("horizon and sky");
        if (a.written("image")) forms.add("image");
        if (forms.size() != 1) {
            String got = forms.isEmpty() ? "none" : String.join(" and ", forms);
            String at = a.names().isEmpty() ? null : a.names().get(0);
            a.error(at == null ? "" : at, "a Background takes exactly one of: color, horizon with sky, or image (with angle); got " + got);
            return new BackgroundValue(Background.BLACK);
        }
        if (a.written("angle") && !a.written("image")) a.error("angle", "angle only goes with image");
        Background background = switch (forms.get(0)) {
            case "color" -> new SolidBackground(a.color("color", Rgb.BLACK));
            case "image" -> panorama(a);
            default -> gradient(a);
        };
        return new BackgroundValue(background);
    }

    private Background gradient(Attributes a) {
        if (!a.written("horizon")) a.error("sky", "a Background with sky needs horizon too");
        if (!a.written("sky")) a.error("horizon", "a Background with horizon needs sky too");
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
