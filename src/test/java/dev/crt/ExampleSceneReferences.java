package dev.crt;

import dev.crt.image.FrameBuffer;
import dev.crt.image.ImageFiles;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.ScriptFiles;
import dev.crt.render.RenderMonitor;
import dev.crt.render.Renderer;
import dev.crt.scene.Scene;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/**
 * The small renders of the example scenes that ExampleScenesTest compares with. Run its main
 * (mvn -q test-compile exec, or from an IDE) only when a change of the pictures is intended, and
 * say in the commit what changed in them and why.
 */
public final class ExampleSceneReferences {
    static final int WIDTH = 48, HEIGHT = 27;
    static final Path FOLDER = Path.of("src/test/resources/example-scenes");

    private ExampleSceneReferences() {}

    static List<Path> scripts() throws IOException {
        List<Path> scripts = new ArrayList<>();
        for (String folder : List.of("scenes", "bench/scenes")) {
            try (Stream<Path> s = Files.list(Path.of(folder))) {
                scripts.addAll(s.filter(p -> p.toString().endsWith(".crt")).sorted().toList());
            }
        }
        return scripts;
    }

    static CompileResult compile(Path script) throws IOException {
        return CrtCompiler.compile(ScriptFiles.read(script), new CompileOptions(3, List.of(Path.of("assets")),
                CompileOptions.DEFAULT_LOOP_BUDGET, CompileOptions.DEFAULT_TIME_BUDGET));
    }

    static FrameBuffer render(Scene scene) {
        Scene small = scene.withSettings(scene.settings().withSize(WIDTH, HEIGHT).withSampling(1, 1));
        return Renderer.prepare(small).render(0, RenderMonitor.NONE);
    }

    static Path referenceOf(Path script) {
        return FOLDER.resolve(script.toString().replace('/', '_').replace(".crt", ".pfm"));
    }

    /** The linear floats of a PFM file (little-endian, rows bottom to top), rows top to bottom. */
    public static float[] readPfm(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        int newlines = 0, start = 0;
        while (newlines < 3) if (bytes[start++] == '\n') newlines++;
        String[] header = new String(bytes, 0, start, StandardCharsets.US_ASCII).split("\\s+");
        int w = Integer.parseInt(header[1]), h = Integer.parseInt(header[2]);
        ByteBuffer b = ByteBuffer.wrap(bytes, start, bytes.length - start).order(ByteOrder.LITTLE_ENDIAN);
        float[] rgb = new float[w * h * 3];
        for (int y = h - 1; y >= 0; y--) for (int i = 0; i < w * 3; i++) rgb[y * w * 3 + i] = b.getFloat();
        return rgb;
    }

    /** Writes the stored picture of every script that has none; {@code --all} writes them all again. */
    public static void main(String[] args) throws IOException {
        Files.createDirectories(FOLDER);
        boolean all = args.length > 0 && args[0].equals("--all");
        for (Path script : scripts()) {
            if (!all && Files.exists(referenceOf(script))) continue;
            CompileResult r = compile(script);
            if (r.hasErrors()) throw new IllegalStateException(script + ": " + r.diagnostics());
            ImageFiles.write(render(r.scene()), referenceOf(script), 1, Map.of());
            System.out.println("wrote " + referenceOf(script));
        }
    }
}
