package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/**
 * Mangled scripts compile to exactly one of: a scene without errors, or no scene with at least
 * one error; every diagnostic has a sane span and formats; nothing throws and nothing hangs.
 */
class CompilerFuzzTest {
    private static final CompileOptions OPTIONS = new CompileOptions(0, List.of(), 200_000, Duration.ofSeconds(2));
    private static final String[] TOKENS = {
        "Settings", "Scene", "Macro", "scale", "translate", "rotate", "true", "false", "while", "if", "else",
        "Sphere", "Box", "Plane", "Camera", "Material", "Background", "PointLight", "ParallelLight", "Teapot",
        "{", "}", "(", ")", "[", "]", "<", ">", "<=", ">=", "==", "!=", "&&", "||", "!", "?", ":", ",", "=", "->",
        "+", "-", "*", "/", "%", "^", "--", "\"", "\\", "\n", "\r\n", "\r", "\t", " ", "0", "1", "-1", "1.5", ".5",
        "1.", "1e-3", "2.5E4", "1e999", "999999999999", "0.0", "\"s\"", "\"sky.png\"", "x", "i", "t", "pi", "vec3",
        "rgb", "rgba", "sqrt", "len", "rand", "radius", "center", "material", "cornerA", "normal", "ball", "ring",
        "spheres", "\uFEFF", "\u00e9", "\uD83D\uDE00", "\0", "#", "@", "$", "`", "'"
    };

    private static final List<String> SEEDS = seeds();

    private static List<String> seeds() {
        List<String> seeds = new ArrayList<>();
        try {
            for (String name : List.of("showcase.crt", "original-style.crt", "presentation-loop.crt")) {
                seeds.add(RobustnessTest.resource(name));
            }
            Path scenes = Path.of("scenes");
            if (Files.isDirectory(scenes)) {
                try (Stream<Path> files = Files.list(scenes)) {
                    for (Path f : files.filter(p -> p.toString().endsWith(".crt")).sorted().toList()) {
                        seeds.add(Files.readString(f));
                    }
                }
            }
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
        return seeds;
    }

    @Provide
    Arbitrary<String> mangledScripts() {
        return Combinators.combine(Arbitraries.integers().between(0, SEEDS.size() - 1), Arbitraries.longs(),
                Arbitraries.integers().between(1, 8)).as((seed, random, count) -> mangle(SEEDS.get(seed), new Random(random), count));
    }

    private static String mangle(String script, Random random, int mutations) {
        StringBuilder s = new StringBuilder(script);
        for (int m = 0; m < mutations; m++) {
            int at = s.length() == 0 ? 0 : random.nextInt(s.length() + 1);
            switch (random.nextInt(6)) {
                case 0 -> s.insert(at, TOKENS[random.nextInt(TOKENS.length)]);
                case 1 -> s.delete(at, Math.min(s.length(), at + 1 + random.nextInt(20)));
                case 2 -> swapWords(s, random);
                case 3 -> s.setLength(at);
                case 4 -> {
                    for (int i = random.nextInt(8); i >= 0; i--) s.insert(at, (char) random.nextInt(0x10000));
                }
                default -> s.insert(at, " " + TOKENS[random.nextInt(TOKENS.length)] + " ");
            }
        }
        return s.toString();
    }

    private static void swapWords(StringBuilder s, Random random) {
        String[] words = s.toString().split(" ", -1);
        if (words.length < 2) return;
        int i = random.nextInt(words.length), j = random.nextInt(words.length);
        String w = words[i];
        words[i] = words[j];
        words[j] = w;
        s.setLength(0);
        s.append(String.join(" ", words));
    }

    @Property(tries = 2000)
    void compilingAnythingGivesASceneOrErrors(@ForAll("mangledScripts") String script) throws Exception {
        CompileResult r = CompletableFuture.supplyAsync(() -> CrtCompiler.compile(Source.of("fuzz.crt", script), OPTIONS))
                .get(30, TimeUnit.SECONDS);
        assertThat(r).isNotNull();
        if (r.scene() != null) {
            assertThat(r.hasErrors()).isFalse();
        } else {
            assertThat(r.errorCount()).isGreaterThanOrEqualTo(1);
        }
        for (Diagnostic d : r.diagnostics()) {
            assertThat(d.message()).doesNotStartWith("internal error");
            assertThat(d.span().line()).isGreaterThanOrEqualTo(1);
            assertThat(d.span().column()).isGreaterThanOrEqualTo(1);
            assertThat(d.span().start()).isBetween(0, script.length());
            assertThat(d.span().end()).isBetween(d.span().start(), script.length());
            assertThat(DiagnosticFormatter.format(d, script)).startsWith("fuzz.crt:");
        }
    }

    @Property(tries = 300)
    void randomBytesGiveASceneOrErrors(@ForAll byte[] bytes) throws Exception {
        compilingAnythingGivesASceneOrErrors(new String(bytes, java.nio.charset.StandardCharsets.UTF_8));
    }
}
