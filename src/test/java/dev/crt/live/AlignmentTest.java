package dev.crt.live;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.render.Renderer;
import dev.crt.scene.Scene;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The live view draws what the ray tracer draws: for every example scene and a set of CSG test
 * scenes, the id passes of both agree on at least 99% of the pixels not within one pixel of a
 * silhouette, and where both see the same entity the distances agree within 1e-3 relative.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class AlignmentTest {
    static final int WIDTH = 160, HEIGHT = 120;
    private Preview preview;
    private final List<String> table = new ArrayList<>();

    @BeforeAll
    void open() {
        preview = GlAvailability.open();
    }

    @AfterAll
    void close() {
        if (preview != null) preview.close();
        System.out.println("| scene | compared pixels | id agreement | depth within 1e-3 | largest relative depth error |");
        System.out.println("|---|---|---|---|---|");
        table.forEach(System.out::println);
    }

    /**
     * Every example scene and the CSG cases; a scene holding a kind the live view does not draw yet
     * (SceneConverterTest.NOT_DRAWN_YET) must be refused with a sentence naming it.
     */
    static Stream<Path> scenes() throws IOException {
        Stream<Path> examples = Files.list(Path.of("scenes")).filter(p -> p.toString().endsWith(".crt")).sorted();
        Stream<Path> csg = Files.list(Path.of("src/test/resources/dev/crt/live"))
                .filter(p -> p.toString().endsWith(".crt")).sorted();
        return Stream.concat(examples, csg);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void idAndDepthPassesAgree(Path file) throws IOException {
        Scene scene = compile(file);
        scene = scene.withSettings(scene.settings().withSize(WIDTH, HEIGHT).withSampling(1, 1));
        String missing = notDrawnYet(scene);
        if (missing != null) {
            // A shape the live view does not draw yet: refused with one sentence, never drawn wrong.
            Scene refused = scene;
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> preview.draw(refused))
                    .isInstanceOf(UnsupportedSceneException.class).hasMessageContaining(missing);
            table.add("| " + file.getFileName() + " | not drawn yet: it holds a " + missing + " | | | |");
            return;
        }
        Renderer tracer = Renderer.prepare(scene);
        int[] traced = tracer.idPass();
        double[] tracedDepth = tracer.depthPass();
        preview.draw(scene);
        int[] drawn = preview.ids();
        float[] drawnDepth = preview.depth();

        Comparison c = compare(traced, tracedDepth, drawn, drawnDepth, WIDTH, HEIGHT);
        table.add(String.format(Locale.ROOT, "| %s | %d | %.2f%% | %.2f%% | %.1e |", file.getFileName(), c.compared,
                100.0 * c.agreeing / c.compared, 100.0 * c.depthWithin / Math.max(1, c.bothHit), c.worstDepth));
        assertThat(c.compared).as("pixels away from silhouettes").isGreaterThan(WIDTH * HEIGHT / 2);
        assertThat((double) c.agreeing / c.compared).as("id agreement of %s", file).isGreaterThanOrEqualTo(0.99);
        assertThat((double) c.depthWithin / Math.max(1, c.bothHit)).as("depth agreement of %s", file)
                .isGreaterThanOrEqualTo(0.99);
    }

    /** The first kind in {@code scene} the live view refuses for now, or null. */
    private static String notDrawnYet(Scene scene) {
        java.util.ArrayDeque<dev.crt.scene.Entity> todo = new java.util.ArrayDeque<>(scene.entities());
        while (!todo.isEmpty()) {
            dev.crt.scene.Entity e = todo.pop();
            if (e instanceof dev.crt.scene.Csg c) {
                todo.push(c.left());
                todo.push(c.right());
            } else if (SceneConverterTest.NOT_DRAWN_YET.containsKey(e.getClass())) {
                return e.getClass().getSimpleName();
            }
        }
        return null;
    }

    /**
     * The check can fail: a field of view 2% off moves silhouettes by about a pixel, which the
     * silhouette margin forgives, but not the distances; 10% off fails the ids too.
     */
    @org.junit.jupiter.api.Test
    void aCameraTwoPercentOffFailsTheCheck() throws IOException {
        Scene scene = compile(Path.of("scenes/csg-sculpture.crt"));
        scene = scene.withSettings(scene.settings().withSize(WIDTH, HEIGHT).withSampling(1, 1));
        Renderer tracer = Renderer.prepare(scene);
        dev.crt.scene.Camera c = scene.settings().camera();
        dev.crt.scene.Camera off = new dev.crt.scene.Camera(c.position(), c.pointing(), c.fov() * 1.02, c.roll(),
                c.aperture(), c.focalDistance(), c.apertureShape(), c.span());
        preview.draw(SceneConverter.convert(scene), ViewCamera.of(off), WIDTH, HEIGHT);
        int[] ids = tracer.idPass();
        double[] depth = tracer.depthPass();
        Comparison bad = compare(ids, depth, preview.ids(), preview.depth(), WIDTH, HEIGHT);
        assertThat((double) bad.depthWithin / bad.bothHit).isLessThan(0.99);
        dev.crt.scene.Camera wide = new dev.crt.scene.Camera(c.position(), c.pointing(), c.fov() * 1.1, c.roll(),
                c.aperture(), c.focalDistance(), c.apertureShape(), c.span());
        preview.draw(SceneConverter.convert(scene), ViewCamera.of(wide), WIDTH, HEIGHT);
        Comparison worse = compare(ids, depth, preview.ids(), preview.depth(), WIDTH, HEIGHT);
        assertThat((double) worse.agreeing / worse.compared).isLessThan(0.99);
    }

    record Comparison(int compared, int agreeing, int bothHit, int depthWithin, double worstDepth) {}

    /**
     * Pixels whose 3×3 neighbourhood shows more than one id in either pass are silhouette pixels and
     * not compared; the depth of a pixel counts where both passes see the same entity there.
     */
    static Comparison compare(int[] a, double[] da, int[] b, float[] db, int w, int h) {
        int compared = 0, agreeing = 0, bothHit = 0, within = 0;
        double worst = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = y * w + x;
                if (nearSilhouette(a, x, y, w, h) || nearSilhouette(b, x, y, w, h)) continue;
                compared++;
                if (a[i] != b[i]) continue;
                agreeing++;
                if (a[i] < 0) continue;
                bothHit++;
                double rel = Math.abs(db[i] - da[i]) / da[i];
                worst = Math.max(worst, rel);
                if (rel <= 1e-3) within++;
            }
        }
        return new Comparison(compared, agreeing, bothHit, within, worst);
    }

    private static boolean nearSilhouette(int[] ids, int x, int y, int w, int h) {
        int id = ids[y * w + x];
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int u = x + dx, v = y + dy;
                if (u >= 0 && v >= 0 && u < w && v < h && ids[v * w + u] != id) return true;
            }
        }
        return false;
    }

    static Scene compile(Path file) throws IOException {
        // The shipped assets (the panorama of csg-sculpture) as a folder option, not the JVM-wide crt.assets property.
        CompileOptions options = new CompileOptions(0, List.of(Path.of("assets")), CompileOptions.DEFAULT_LOOP_BUDGET,
                CompileOptions.DEFAULT_TIME_BUDGET);
        CompileResult r = CrtCompiler.compile(new Source(file.toString(), Files.readString(file), file), options);
        assertThat(r.hasErrors()).as("%s compiles: %s", file, r.diagnostics()).isFalse();
        return r.scene();
    }
}
