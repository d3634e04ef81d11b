package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

/** Runs crt in-process with its output captured, and compares folders of frames. */
final class AnimateTestSupport {
    /** A small scene whose sphere circles the origin as t goes on: 30 degrees per frame. */
    static final String ORBIT = """
            Settings { camera -> Camera { position -> vec3(0, 2, -6) pointing -> vec3(0, 0.5, 0) }
                       lights -> [PointLight { origin -> vec3(-4, 6, -5) }]
                       background -> Background { horizon -> rgb(0.8, 0.9, 1) sky -> rgb(0.2, 0.4, 0.9) }
                       width -> 32 height -> 24 }
            a = radians(t * 30)
            Scene { Sphere { center -> vec3(1.5 * cos(a), 0.8, 1.5 * sin(a)) radius -> 0.7
                             material -> Material { color -> rgb(1, 0.3, 0.2) specular -> 0.5 } }
                    Plane { normal -> vec3(0, 1, 0) } }
            """;

    /** What one run of crt did. */
    record Run(int exit, String out, String err) {}

    private AnimateTestSupport() {}

    /** Runs {@code crt args…}; calls from several threads share the captured streams. */
    static synchronized Run crtCaptured(String... args) {
        return crt(args);
    }

    static Run crt(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            int exit = Main.run(args);
            return new Run(exit, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
    }

    static Path write(Path file, String text) {
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            return Files.writeString(file, text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Every file under {@code dir} by relative name, with its bytes. */
    static Map<String, byte[]> contents(Path dir) {
        Map<String, byte[]> files = new TreeMap<>();
        if (!Files.exists(dir)) return files;
        try (Stream<Path> walk = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) walk.filter(Files::isRegularFile)::iterator) {
                files.put(dir.relativize(p).toString(), Files.readAllBytes(p));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return files;
    }

    /** Asserts both folders hold the same file names with the same bytes. */
    static void assertSameFiles(Path actual, Path expected) {
        Map<String, byte[]> a = contents(actual);
        Map<String, byte[]> e = contents(expected);
        assertThat(a.keySet()).isEqualTo(e.keySet());
        for (String name : e.keySet()) assertThat(a.get(name)).as(name).isEqualTo(e.get(name));
    }

    /** File names under {@code dir} that are temporary files of a write. */
    static Stream<String> temporaryFiles(Path dir) {
        return contents(dir).keySet().stream().filter(name -> name.contains(".tmp-"));
    }
}
