package dev.crt.render;

import dev.crt.scene.Projection;
import dev.crt.scene.Sampler;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * The second wave's features as switches on the renderer's hot path, read once from the system
 * property {@value #PROPERTY} (a comma list of {@link #NAMES}, or {@code all}; by default every
 * feature is present). Each switch is a static final, so the JIT folds its tests and drops the code
 * behind a switched-off feature: a run with {@code -Dcrt.without=textures} measures the renderer as
 * if textures had never been written (docs/benchmarks.md, section 19). {@link #check} refuses a
 * scene that uses a switched-off feature rather than render a different picture.
 */
final class Features {
    static final String PROPERTY = "crt.without";
    /** Every switch's name and what it leaves out, in the order the documents list them. */
    static final Map<String, String> NAMES = names();
    /** The names of {@link #PROPERTY} that are switched off; read before the switches below. */
    private static final Set<String> OFF = new LinkedHashSet<>();
    /** The names given that are not switches, or null: {@link #check} reports them. */
    private static final String UNKNOWN = parse(System.getProperty(PROPERTY, ""));

    static final boolean LIGHTS = on("lights");
    static final boolean FRESNEL = on("fresnel");
    static final boolean ABSORPTION = on("absorption");
    static final boolean TEXTURES = on("textures");
    static final boolean BUMP = on("bump");
    static final boolean GLOSSY = on("glossy");
    static final boolean GOOCH = on("gooch");
    static final boolean PROJECTIONS = on("projections");
    static final boolean SHAPES = on("shapes");
    static final boolean SAMPLERS = on("samplers");
    static final boolean ORIGINAL = on("original");

    private Features() {}

    private static Map<String, String> names() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("lights", "spot and area lights");
        m.put("fresnel", "Fresnel reflectance");
        m.put("absorption", "Beer's-law absorption");
        m.put("textures", "textures (image, checker, noise, marble, wood; with their ray cones)");
        m.put("bump", "bump maps");
        m.put("glossy", "glossy reflection and refraction");
        m.put("gooch", "Gooch shading and outlines");
        m.put("projections", "spherical and cylindrical cameras");
        m.put("shapes", "tori, cylinders, cones and meshes");
        m.put("samplers", "the jittered, Sobol and adaptive samplers");
        m.put("original", "shading \"original\"");
        return m;
    }

    private static String parse(String value) {
        List<String> unknown = new ArrayList<>();
        for (String part : value.split(",")) {
            String name = part.trim().toLowerCase(Locale.ROOT);
            if (name.isEmpty()) continue;
            if (name.equals("all")) OFF.addAll(NAMES.keySet());
            else if (NAMES.containsKey(name)) OFF.add(name);
            else unknown.add("'" + part.trim() + "'");
        }
        return unknown.isEmpty() ? null : String.join(", ", unknown);
    }

    private static boolean on(String name) {
        return !OFF.contains(name);
    }

    /**
     * Throws when {@link #PROPERTY} names something that is not a switch, or when the scene (its
     * settings, materials, shapes and lights as prepared) uses a feature this run has switched off.
     */
    static void check(Settings settings, SceneGeometry geometry, Lights lights) {
        if (UNKNOWN != null) {
            throw new FeatureSwitchedOffException("-D" + PROPERTY + " names " + UNKNOWN
                    + ", which is no feature; the features are all, " + String.join(", ", NAMES.keySet()));
        }
        Materials materials = geometry.materials;
        boolean spotOrArea = false;
        for (int i = 0; i < lights.count; i++) spotOrArea |= lights.kind[i] == Lights.SPOT || lights.kind[i] == Lights.AREA;
        boolean newShape = false;
        for (int s = 0; s < geometry.shapes.count(); s++) newShape |= geometry.shapes.kind[s] >= Shapes.CONE;
        refuse(LIGHTS, "lights", spotOrArea);
        refuse(FRESNEL, "fresnel", materials.any(Materials.FRESNEL));
        refuse(ABSORPTION, "absorption", materials.absorbing());
        refuse(TEXTURES, "textures", !materials.textures.isEmpty());
        refuse(BUMP, "bump", materials.any(Materials.TEX_BUMP));
        refuse(GLOSSY, "glossy", materials.glossy());
        refuse(GOOCH, "gooch", materials.gooch());
        refuse(PROJECTIONS, "projections", settings.camera().projection() != Projection.PERSPECTIVE);
        refuse(SHAPES, "shapes", newShape);
        refuse(SAMPLERS, "samplers", settings.effectiveSampler() != Sampler.GRID);
        refuse(ORIGINAL, "original", settings.shading() == Shading.ORIGINAL);
    }

    private static void refuse(boolean on, String name, boolean used) {
        if (!on && used) {
            throw new FeatureSwitchedOffException("the scene uses " + NAMES.get(name) + ", which this run leaves out (-D"
                    + PROPERTY + "=" + String.join(",", OFF) + ")");
        }
    }
}
