package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Each switch of -Dcrt.without holds to its meaning: with it off, every scene using its feature is
 * refused with a sentence naming the feature and the switch, and a plain scene (the box field:
 * CSG, mirrors, point and parallel lights, shadows) renders the same floats as with every feature
 * present. Each setting runs in a class loader of its own, since the switches are read once.
 */
class FeatureSwitchesTest {
    private static final String CAMERA = "Settings { camera -> Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) }"
            + " width -> 24 height -> 16 lights -> [PointLight { origin -> vec3(3, 5, -4) }] }\n";
    private static final String BALL = "Sphere { radius -> 1 }\n";

    /** Per switch, scenes that use its feature and nothing else of the second wave. */
    private static final Map<String, List<String>> USES = Map.ofEntries(
            Map.entry("lights", List.of(
                    CAMERA + "Settings { lights -> [SpotLight { origin -> vec3(0, 5, 0) pointing -> vec3(0, 0, 0) }] }\nScene { " + BALL + "}",
                    CAMERA + "Settings { lights -> [AreaLight { corner -> vec3(0, 5, 0) edge1 -> vec3(1, 0, 0) edge2 -> vec3(0, 0, 1) }] }\n"
                            + "Scene { " + BALL + "}")),
            Map.entry("fresnel", List.of(
                    CAMERA + "Scene { Sphere { material -> Material { transparency -> 1 ior -> 1.5 fresnel -> true } } }")),
            Map.entry("absorption", List.of(
                    CAMERA + "Scene { Sphere { material -> Material { transparency -> 0.8 absorption -> rgb(0.1, 0.2, 0.3) } } }")),
            Map.entry("textures", List.of(
                    CAMERA + "Scene { Sphere { material -> Material { color -> Checker { } } } }",
                    CAMERA + "Scene { Sphere { material -> Material { specular -> Noise { } } } }")),
            Map.entry("bump", List.of(
                    CAMERA + "Scene { Sphere { material -> Material { bump -> Noise { } } } }")),
            Map.entry("glossy", List.of(
                    CAMERA + "Scene { Sphere { material -> Material { reflectivity -> 0.5 roughness -> 0.2 } } }")),
            Map.entry("gooch", List.of(
                    CAMERA + "Scene { Sphere { material -> Material { model -> \"gooch\" } } }")),
            Map.entry("projections", List.of(
                    CAMERA + "Settings { camera -> Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) projection -> \"spherical\" } }\n"
                            + "Scene { " + BALL + "}")),
            Map.entry("shapes", List.of(
                    CAMERA + "Scene { Torus { major -> 1 minor -> 0.3 } }",
                    CAMERA + "Scene { Cylinder { from -> vec3(0, 0, 0) to -> vec3(0, 1, 0) radius -> 0.5 } }",
                    CAMERA + "Scene { Cone { from -> vec3(0, 0, 0) to -> vec3(0, 1, 0) radius -> 0.5 } }",
                    CAMERA + "Scene { Mesh { vertices -> [vec3(0,0,0), vec3(1,0,0), vec3(0,1,0), vec3(0,0,1)]"
                            + " faces -> [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] } }",
                    CAMERA + "Scene { Sphere { } - Cylinder { from -> vec3(0, -2, 0) to -> vec3(0, 2, 0) radius -> 0.5 } }")),
            Map.entry("samplers", List.of(
                    CAMERA + "Settings { sampler -> \"jittered\" }\nScene { " + BALL + "}",
                    CAMERA + "Settings { sampler -> \"sobol\" }\nScene { " + BALL + "}",
                    CAMERA + "Settings { sampler -> \"adaptive\" }\nScene { " + BALL + "}")),
            Map.entry("original", List.of(
                    CAMERA + "Settings { shading -> \"original\" }\nScene { " + BALL + "}")));

    private static String plain;
    private static float[] allPresent;

    @BeforeAll
    static void plainScene() throws Exception {
        plain = Files.readString(Path.of("scenes/box-field.crt")).replace("width -> 1280", "width -> 64")
                .replace("height -> 720", "height -> 36");
        allPresent = (float[]) FeatureProbe.render(plain);
    }

    /** FeatureProbe.render in a fresh class loader whose Features read {@code without}. */
    private static Method probeWithout(String without) throws Exception {
        List<URL> urls = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            urls.add(Path.of(entry).toUri().toURL());
        }
        ClassLoader loader = new URLClassLoader(urls.toArray(URL[]::new), ClassLoader.getPlatformClassLoader());
        String before = System.getProperty(Features.PROPERTY);
        System.setProperty(Features.PROPERTY, without);
        try {
            Class.forName(Features.class.getName(), true, loader);
        } finally {
            if (before == null) System.clearProperty(Features.PROPERTY);
            else System.setProperty(Features.PROPERTY, before);
        }
        Method render = Class.forName(FeatureProbe.class.getName(), true, loader).getDeclaredMethod("render", String.class);
        render.setAccessible(true);
        return render;
    }

    @Test
    void everySwitchIsTested() {
        assertThat(USES.keySet()).containsExactlyInAnyOrderElementsOf(Features.NAMES.keySet());
    }

    @Test
    void withEveryFeaturePresentTheScenesThatUseThemRender() {
        for (List<String> scenes : USES.values()) {
            for (String scene : scenes) assertThat(FeatureProbe.render(scene)).as(scene).isInstanceOf(float[].class);
        }
    }

    @Test
    void eachSwitchOffRefusesItsScenesAndRendersThePlainSceneTheSame() throws Exception {
        for (String name : Features.NAMES.keySet()) {
            Method render = probeWithout(name);
            for (String scene : USES.get(name)) {
                assertThat(render.invoke(null, scene)).as("without %s: %s", name, scene)
                        .isEqualTo("the scene uses " + Features.NAMES.get(name) + ", which this run leaves out (-Dcrt.without="
                                + name + ")");
            }
            assertThat((float[]) render.invoke(null, plain)).as("the box field without %s", name).isEqualTo(allPresent);
        }
    }

    @Test
    void withEverythingOffThePlainSceneRendersTheSame() throws Exception {
        Method render = probeWithout("all");
        assertThat((float[]) render.invoke(null, plain)).isEqualTo(allPresent);
        assertThat((String) render.invoke(null, USES.get("glossy").get(0))).contains("glossy reflection and refraction")
                .contains("-Dcrt.without=lights,fresnel,absorption,textures,bump,glossy,gooch,projections,shapes,samplers,original");
    }

    @Test
    void anUnknownNameIsRefusedWithTheKnownOnes() throws Exception {
        Method render = probeWithout(" Textures, glosy ");
        assertThat(render.invoke(null, plain)).isEqualTo("-Dcrt.without names 'glosy', which is no feature; the features are all, "
                + "lights, fresnel, absorption, textures, bump, glossy, gooch, projections, shapes, samplers, original");
    }
}
