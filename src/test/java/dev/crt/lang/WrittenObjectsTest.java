package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.parser.CRTParser;
import dev.crt.lang.syntax.ParseClock;
import dev.crt.lang.syntax.ScriptParser;
import dev.crt.lang.syntax.WrittenStatement;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Top-level object literals of plain values are built straight from their tokens. That must give
 * exactly what the general path (the parse tree, visited) gives: the same scene, values bit for
 * bit and every source span, and the same diagnostics for scripts with mistakes, on the example
 * scenes, the 2015 sample when it is on the machine, and thousands of random written-out scripts,
 * whole and mangled.
 */
class WrittenObjectsTest {
    private static final Path DROPS = Path.of("/work/data/crt2015/drops.crt");
    private static final Path DROPS_ASSETS = Path.of("/work/data/crt2015/assets");

    @Test
    void theExampleScenesCompileAlikeBothWays() throws IOException {
        List<Path> scripts;
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            scripts = new ArrayList<>(files.filter(p -> p.toString().endsWith(".crt")).sorted().toList());
        }
        assertThat(scripts).hasSizeGreaterThan(5);
        if (Files.isRegularFile(DROPS)) scripts.add(DROPS);
        for (Path script : scripts) {
            Source source = new Source(script.getFileName().toString(), Files.readString(script), script.toAbsolutePath());
            CompileOptions options = new CompileOptions(0, script.equals(DROPS) ? List.of(DROPS_ASSETS) : List.of(),
                    CompileOptions.DEFAULT_LOOP_BUDGET, Duration.ofMinutes(2));
            assertSame(source, options);
        }
    }

    @Test
    void randomWrittenOutScriptsCompileAlikeBothWays() {
        Random random = new Random(20261202);
        int written = 0;
        for (int i = 0; i < 1000; i++) {
            String text = WrittenScripts.script(random, 1 + random.nextInt(12), false);
            written += writtenStatements(text);
            assertSame(Source.of("w" + i + ".crt", text), CompileOptions.DEFAULT);
        }
        // The comparison means something only if the scripts do take the new path.
        assertThat(written).isGreaterThan(3000);
    }

    @Test
    void randomScriptsWithMistakesGiveTheSameDiagnosticsBothWays() {
        Random random = new Random(15);
        int failing = 0;
        for (int i = 0; i < 1000; i++) {
            String text = WrittenScripts.script(random, 1 + random.nextInt(8), true);
            CompileResult result = assertSame(Source.of("m" + i + ".crt", text), CompileOptions.DEFAULT);
            if (result.hasErrors()) failing++;
        }
        assertThat(failing).isGreaterThan(200);
    }

    @Test
    void theBenchmarksWrittenOutScriptIsReadAsWrittenStatements() {
        String text = WrittenScripts.exported(200);
        assertThat(writtenStatements(text)).isEqualTo(200);
        assertSame(Source.of("exported.crt", text), CompileOptions.DEFAULT);
    }

    @Test
    void literalsNestedDeeplyAreLeftToTheGeneralReading() {
        String deep = "Sphere { material -> Material { color -> Checker { color1 -> rgb(1, 0, 0) } } }";
        assertThat(writtenStatements("Scene { " + deep + " }")).isEqualTo(1);
        StringBuilder absurd = new StringBuilder("Scene { ");
        for (int i = 0; i < 40; i++) absurd.append("Sphere { material -> ");
        absurd.append("m").append(" }".repeat(40)).append(" }");
        assertThat(writtenStatements(absurd.toString())).isZero();
        assertSame(Source.of("deep.crt", "m = Material { }\n" + absurd), CompileOptions.DEFAULT);
    }

    /** Compiles both ways, asserts the outcomes equal, and returns the new path's. */
    private static CompileResult assertSame(Source source, CompileOptions options) {
        CompileResult general = CrtCompiler.compile(source, options, false);
        CompileResult fromTokens = CrtCompiler.compile(source, options, true);
        assertThat(fromTokens.diagnostics()).as("diagnostics of %s:\n%s", source.name(), source.text())
                .isEqualTo(general.diagnostics());
        // Field by field, arrays by content, doubles by Double.equals (bit for bit); the spans are
        // fields of every entity, light and camera.
        assertThat(fromTokens.scene()).as("scene of %s", source.name()).usingRecursiveComparison()
                .withEqualsForType(Arrays::equals, double[].class).withEqualsForType(Arrays::equals, float[].class)
                .withEqualsForType(Arrays::equals, int[].class).withEqualsForType(Arrays::equals, byte[].class)
                .withEqualsForType(Arrays::equals, short[].class).isEqualTo(general.scene());
        return fromTokens;
    }

    /** How many statements of the script the reading hands out as written statements. */
    private static int writtenStatements(String text) {
        ScriptParser.Parsed parsed = ScriptParser.parse(new TextPositions("s.crt", text),
                new ParseClock(System.nanoTime(), Duration.ofMinutes(1)), true);
        if (parsed.statements() == null) return 0;
        int n = 0;
        for (Iterator<CRTParser.StatementContext> it = parsed.statements(); it.hasNext(); ) {
            CRTParser.StatementContext s = it.next();
            if (s instanceof WrittenStatement) n++;
            if (s instanceof CRTParser.SceneBlockContext scene) {
                for (CRTParser.StatementContext inner : scene.statement()) if (inner instanceof WrittenStatement) n++;
            }
        }
        return n;
    }

    /** Scripts as exporters write them, and the same with mistakes a person or a bad exporter makes. */
    static final class WrittenScripts {
        private WrittenScripts() {}

        private static final String[] TYPOS = {"radiuss", "centre", "colour", "Sphre", "Materal", "cornerb", "difuse"};

        /** The script of bench/compile-speed.sh, for {@code n} spheres. */
        static String exported(int n) {
            StringBuilder s = new StringBuilder();
            s.append("Settings {\n  camera -> Camera { position -> vec3(0, 0, -32) pointing -> vec3(0, 0, 0) fov -> 40 }\n")
                    .append("  lights -> [ PointLight { origin -> vec3(-30, 40, -50) color -> rgb(0.8, 0.8, 0.8) ambient -> 0.2 } ]\n")
                    .append("}\nScene {\n");
            Random r = new Random(12345);
            for (int i = 0; i < n; i++) {
                s.append(String.format(Locale.ROOT, "  Sphere {\n    center -> vec3(%.6f, %.6f, %.6f)\n    radius -> %.6f\n",
                        20 * r.nextDouble() - 10, 20 * r.nextDouble() - 10, 20 * r.nextDouble() - 10, 0.16));
                s.append(String.format(Locale.ROOT, "    material -> Material {\n      color -> rgb(%.4f, %.4f, %.4f)\n"
                        + "      diffuse -> 0.8\n      specular -> 0.4\n      shininess -> 30\n    }\n  }\n",
                        r.nextDouble(), r.nextDouble(), r.nextDouble()));
            }
            return s.append("}\n").toString();
        }

        static String script(Random r, int objects, boolean mangle) {
            StringBuilder s = new StringBuilder();
            if (r.nextInt(3) == 0) {
                // Lights and a camera assigned first, as some exporters write them.
                s.append("light = ").append(r.nextBoolean() ? "PointLight { origin -> " + vec(r, mangle) + " color -> " + color(r, mangle)
                        : "SpotLight { origin -> " + vec(r, mangle) + " pointing -> " + vec(r, mangle) + " angle -> " + number(r, mangle))
                        .append(" }\ncam = Camera { position -> ").append(vec(r, mangle)).append(" pointing -> ").append(vec(r, mangle))
                        .append(r.nextBoolean() ? " fov -> " + number(r, mangle) : "")
                        .append(r.nextInt(4) == 0 ? " apertureshape -> \"" + (mangle ? "hexagone" : "hexagon") + "\"" : "")
                        .append(" }\nSettings { camera -> cam lights -> [light] }\n");
            } else if (r.nextInt(4) > 0) {
                s.append("Settings { camera -> Camera { position -> vec3(0, 1, -8) pointing -> vec3(0, 0, 0) } ")
                        .append("lights -> [PointLight { origin -> vec3(2, 5, -4) }] }\n");
            }
            List<String> materials = new ArrayList<>();
            int named = r.nextInt(3);
            for (int i = 0; i < named; i++) {
                String name = "m" + i;
                s.append(name).append(" = ").append(material(r, mangle)).append('\n');
                materials.add(name);
            }
            if (r.nextInt(5) == 0) s.append("rad = ").append(number(r, false)).append('\n');
            if (r.nextInt(8) == 0) s.append(object(r, materials, mangle)).append('\n'); // a top-level value, dropped
            if (mangle && r.nextInt(10) == 0) s.append(r.nextBoolean() ? "vec3 = 2\n" : "t = Sphere { }\n");
            s.append("Scene {\n");
            for (int i = 0; i < objects; i++) {
                s.append("  ").append(object(r, materials, mangle));
                if (r.nextInt(15) == 0) s.append(" <translate vec3(1, 0, 0)>"); // not plain: the general path
                if (r.nextInt(20) == 0) s.append(" + Sphere { }");
                s.append('\n');
                if (mangle && r.nextInt(12) == 0) s.append("  Material { }\n"); // not an entity
            }
            s.append("}\n");
            String text = s.toString();
            if (mangle && r.nextInt(6) == 0) {
                // A character lost or doubled somewhere: mostly syntax errors, which ANTLR reports either way.
                int at = r.nextInt(text.length());
                text = r.nextBoolean() ? text.substring(0, at) + text.substring(at + 1) : text.substring(0, at + 1) + text.substring(at);
            }
            return text;
        }

        private static String object(Random r, List<String> materials, boolean mangle) {
            List<String> attrs = new ArrayList<>();
            String type;
            switch (r.nextInt(6)) {
                case 0 -> {
                    type = "Box";
                    attrs.add("cornerA -> " + vec(r, mangle));
                    attrs.add("cornerB -> " + vec(r, mangle));
                }
                case 1 -> {
                    type = "Cylinder";
                    attrs.add("from -> " + vec(r, mangle));
                    attrs.add("to -> " + vec(r, mangle));
                    attrs.add("radius -> " + number(r, mangle));
                    attrs.add("capped -> " + (r.nextBoolean() ? "true" : "false"));
                }
                case 2 -> {
                    type = "Torus";
                    attrs.add("center -> " + vec(r, mangle));
                    attrs.add("major -> " + number(r, mangle));
                    attrs.add("minor -> " + number(r, mangle));
                }
                case 3 -> {
                    type = "Plane";
                    attrs.add("normal -> " + vec(r, mangle));
                    attrs.add("position -> " + vec(r, mangle));
                }
                default -> {
                    type = "Sphere";
                    attrs.add("center -> " + vec(r, mangle));
                    attrs.add("radius -> " + (r.nextInt(6) == 0 && !mangle ? "rad" : number(r, mangle)));
                }
            }
            int m = r.nextInt(4);
            if (m == 1 && !materials.isEmpty()) attrs.add("material -> " + materials.get(r.nextInt(materials.size())));
            if (m >= 2) attrs.add("material -> " + material(r, mangle));
            if (mangle && r.nextInt(5) == 0) attrs.add(attrs.get(r.nextInt(attrs.size()))); // given twice
            if (mangle && r.nextInt(6) == 0) attrs.remove(r.nextInt(attrs.size())); // a needed one missing
            if (mangle && r.nextInt(8) == 0) attrs.add("material -> nowhere");
            java.util.Collections.shuffle(attrs, r);
            if (mangle && r.nextInt(8) == 0) type = TYPOS[r.nextInt(TYPOS.length)];
            return type + " { " + String.join(r.nextBoolean() ? " " : "\n    ", attrs) + " }";
        }

        private static String material(Random r, boolean mangle) {
            List<String> attrs = new ArrayList<>();
            if (r.nextBoolean()) attrs.add("color -> " + (r.nextInt(6) == 0 ? texture(r, mangle) : color(r, mangle)));
            if (r.nextBoolean()) attrs.add("diffuse -> " + unit(r, mangle));
            if (r.nextBoolean()) attrs.add("specular -> " + unit(r, mangle));
            if (r.nextBoolean()) attrs.add("shininess -> " + (1 + r.nextInt(100)));
            if (r.nextInt(4) == 0) attrs.add("reflectivity -> " + unit(r, mangle));
            if (r.nextInt(6) == 0) attrs.add("model -> \"" + (mangle && r.nextBoolean() ? "gooch\\n" : r.nextBoolean() ? "phong" : "gooch") + "\"");
            if (mangle && r.nextInt(10) == 0) attrs.add(TYPOS[r.nextInt(TYPOS.length)] + " -> 1");
            java.util.Collections.shuffle(attrs, r);
            return "Material { " + String.join(" ", attrs) + " }";
        }

        private static String texture(Random r, boolean mangle) {
            String type = new String[] {"Checker", "Noise", "Wood", "Marble"}[r.nextInt(4)];
            return type + " { color1 -> " + color(r, mangle) + " color2 -> " + color(r, mangle) + " scale -> " + number(r, mangle) + " }";
        }

        private static String vec(Random r, boolean mangle) {
            if (mangle && r.nextInt(12) == 0) return r.nextBoolean() ? "3" : "vec3(1, 2)";
            if (mangle && r.nextInt(15) == 0) return "rgb(1, 0, 0)";
            return "vec3(" + coordinate(r, mangle) + ", " + coordinate(r, mangle) + ", " + coordinate(r, mangle) + ")";
        }

        private static String color(Random r, boolean mangle) {
            if (mangle && r.nextInt(12) == 0) return "vec3(1, 0, 0)";
            return "rgb(" + unit(r, mangle) + ", " + unit(r, mangle) + ", " + unit(r, mangle) + ")";
        }

        private static String coordinate(Random r, boolean mangle) {
            return switch (r.nextInt(8)) {
                case 0 -> "-" + number(r, mangle);
                case 1 -> "+" + number(r, false);
                case 2 -> Integer.toString(r.nextInt(20) - 10);
                case 3 -> "-0";
                default -> String.format(Locale.ROOT, "%.6f", 20 * r.nextDouble() - 10);
            };
        }

        private static String unit(Random r, boolean mangle) {
            if (mangle && r.nextInt(15) == 0) return "-0.5";
            return switch (r.nextInt(5)) {
                case 0 -> "1";
                case 1 -> "0";
                case 2 -> String.format(Locale.ROOT, "%.3e", r.nextDouble());
                default -> String.format(Locale.ROOT, "%.4f", r.nextDouble());
            };
        }

        private static String number(Random r, boolean mangle) {
            if (mangle && r.nextInt(20) == 0) return r.nextBoolean() ? "1e999" : "-2";
            return switch (r.nextInt(6)) {
                case 0 -> (r.nextInt(3) == 0 ? "+" : "") + (1 + r.nextInt(9));
                case 1 -> String.format(Locale.ROOT, "%.17g", 0.1 + 5 * r.nextDouble());
                case 2 -> "." + (1 + r.nextInt(99));
                case 3 -> (1 + r.nextInt(9)) + "e-" + r.nextInt(3);
                default -> String.format(Locale.ROOT, "%.6f", 0.05 + 3 * r.nextDouble());
            };
        }
    }
}
