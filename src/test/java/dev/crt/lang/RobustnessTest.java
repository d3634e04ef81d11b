package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.PanoramaBackground;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** Inputs that must end in a scene or a diagnostic: never an exception, a stack overflow or a hang. */
class RobustnessTest {
    static String resource(String name) throws IOException {
        try (InputStream in = RobustnessTest.class.getResourceAsStream("/lang/" + name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    private static void noInternalError(CompileResult r) {
        assertThat(r.diagnostics()).noneSatisfy(d -> assertThat(d.message()).startsWith("internal error"));
    }

    @Test
    void thePresentationLoopCompilesWhileTheMacroIsNotCalled() throws IOException {
        CompileResult r = Scripts.compile(resource("presentation-loop.crt"));
        assertThat(r.hasErrors()).isFalse();
        assertThat(r.scene().entities()).hasSize(1);
    }

    @Test
    @Timeout(60)
    void thePresentationLoopStopsWithTheLoopBudgetWhenCalled() throws IOException {
        String script = resource("presentation-loop.crt").replace("  sphere1\n}", "  spheres(10)\n}");
        long start = System.nanoTime();
        CompileResult r = CrtCompiler.compile(Source.of("presentation.crt", script),
                new CompileOptions(0, List.of(), CompileOptions.DEFAULT_LOOP_BUDGET, Duration.ofSeconds(60)));
        System.out.printf("presentation loop stopped after %.1f s%n", (System.nanoTime() - start) / 1e9);
        assertThat(r.scene()).isNull();
        Diagnostic d = r.diagnostics().stream().filter(Diagnostic::isError).findFirst().orElseThrow();
        assertThat(d.message()).isEqualTo("evaluation stopped: loops ran 10,000,000 iterations (is the loop condition ever false?)");
        assertThat(d.span().line()).isEqualTo(8);
        assertThat(d.span().column()).isEqualTo(3);
        assertThat(d.callChain()).containsExactly("in macro 'spheres' called at 13:3");
    }

    @Test
    void emptyCommentOnlyCrlfAndBomFilesCompile() {
        for (String text : List.of("", "-- nothing here\n-- at all", "\r\n\r\n", "\uFEFF", "\uFEFF" + CAMERA.replace("\n", "\r\n"))) {
            CompileResult r = Scripts.compile(text);
            assertThat(r.hasErrors()).as(text).isFalse();
            assertThat(r.scene()).isNotNull();
        }
    }

    @Test
    @Timeout(60)
    void tenThousandNestedParentheses() {
        int depth = 10_000;
        String script = CAMERA + "x = " + "(".repeat(depth) + "1" + ")".repeat(depth) + "\nScene { Sphere { radius -> x } }\n";
        CompileResult r = Scripts.compile(script);
        noInternalError(r);
        assertThat(r.hasErrors()).isFalse();
    }

    @Test
    @Timeout(60)
    void absurdNestingEndsInADiagnostic() {
        int depth = 2_000_000;
        CompileResult r = Scripts.compile("x = " + "(".repeat(depth) + "1" + ")".repeat(depth) + "\n");
        noInternalError(r);
        // The time budget covers the parse: on a slow machine it may stop the parse before the stack runs out.
        if (r.hasErrors()) assertThat(r.diagnostics().get(0).message()).containsAnyOf("nested too deeply", "parsing stopped");
    }

    @Test
    @Timeout(60)
    void deeplyNestedListsIfsAndUnaryOperators() {
        int depth = 5_000;
        String lists = "xs = " + "[".repeat(depth) + "1" + "]".repeat(depth) + "\n";
        String ifs = "if (true) { ".repeat(depth) + "y = 1" + " }".repeat(depth) + "\n";
        String signs = "z = " + "- ".repeat(depth) + "1\n";
        String nots = "b = " + "!".repeat(depth) + "true\n";
        CompileResult r = Scripts.compile(CAMERA + lists + ifs + signs + nots + "Scene { Sphere { radius -> y * z } }\n");
        noInternalError(r);
        assertThat(r.hasErrors()).isFalse();
    }

    @Test
    @Timeout(60)
    void aThousandNestedMacros() {
        StringBuilder script = new StringBuilder(CAMERA + "m0 = Macro () { Sphere { } }\n");
        for (int i = 1; i <= 1000; i++) script.append("m").append(i).append(" = Macro () { m").append(i - 1).append("() }\n");
        script.append("Scene { m200() }\n");
        CompileResult ok = Scripts.compile(script.toString());
        assertThat(ok.hasErrors()).isFalse();
        assertThat(ok.scene().entities()).hasSize(1);

        CompileResult tooDeep = Scripts.compile(script.toString().replace("Scene { m200() }", "Scene { m1000() }"));
        assertThat(tooDeep.diagnostics().get(0).message()).isEqualTo("macro calls nested deeper than 256 (endless recursion?)");

        StringBuilder definitions = new StringBuilder(CAMERA + "m = ");
        for (int i = 0; i < 1000; i++) definitions.append("Macro () { ");
        definitions.append("Sphere { }").append(" }".repeat(1000)).append("\nScene { }\n");
        assertThat(Scripts.compile(definitions.toString()).hasErrors()).isFalse();
    }

    @Test
    @Timeout(120)
    void aTwentyMegabyteScript() {
        StringBuilder script = new StringBuilder(21_000_000).append(CAMERA);
        int i = 0;
        while (script.length() < 20_000_000) {
            script.append("b").append(i % 1000).append(" = Box { cornerA -> vec3(").append(i).append(", 0, 0) cornerB -> vec3(")
                    .append(i).append(".5, 1, 1) } -- box ").append(i).append('\n');
            i++;
        }
        script.append("Scene { b1 b2 b3 }\n");
        long start = System.nanoTime();
        // The default budget of 10 s covers the parse, which for 20 MB takes about that on the shared
        // 2-core machine: a script this large is compiled with --time-budget, as here.
        CompileResult r = CrtCompiler.compile(Source.of("test.crt", script.toString()), new CompileOptions(0, List.of(),
                CompileOptions.DEFAULT_LOOP_BUDGET, java.time.Duration.ofSeconds(110)));
        System.out.printf("20 MB script (%d lines) compiled in %.1f s%n", i, (System.nanoTime() - start) / 1e9);
        noInternalError(r);
        if (r.hasErrors()) {
            // A small heap may not hold the whole parse tree; then the one error must say so.
            assertThat(r.diagnostics()).singleElement().satisfies(d ->
                    assertThat(d.message()).isEqualTo("the script needs more memory than the Java heap has"));
        } else {
            assertThat(r.scene().entities()).hasSize(3);
        }
    }

    @Test
    @Timeout(60)
    void randomBinaryBytesAsText() {
        Random random = new Random(7);
        for (int n = 0; n < 20; n++) {
            byte[] bytes = new byte[1 + random.nextInt(5000)];
            random.nextBytes(bytes);
            String text = new String(bytes, StandardCharsets.ISO_8859_1);
            CompileResult r = Scripts.compile(text);
            noInternalError(r);
            assertThat(r.scene() == null).isEqualTo(r.hasErrors());
        }
    }

    @Test
    void panoramaIsFoundNextToTheScriptAndInAssetFolders(@TempDir Path dir) throws IOException {
        Path assets = Files.createDirectory(dir.resolve("assets"));
        BufferedImage image = new BufferedImage(4, 2, BufferedImage.TYPE_INT_RGB);
        ImageIO.write(image, "png", dir.resolve("near.png").toFile());
        ImageIO.write(image, "png", assets.resolve("far.png").toFile());
        CompileOptions options = new CompileOptions(0, List.of(assets), 1000, Duration.ofSeconds(5));
        Path script = dir.resolve("s.crt");
        for (String name : List.of("near.png", "/far.png", dir.resolve("near.png").toString())) {
            String text = CAMERA + "Settings { background -> Background { image -> \"" + name.replace("\\", "\\\\")
                    + "\" angle -> 1.5 } }\nScene { }\n";
            CompileResult r = CrtCompiler.compile(new Source("s.crt", text, script), options);
            assertThat(r.hasErrors()).as(Scripts.render(r, text)).isFalse();
            PanoramaBackground p = (PanoramaBackground) r.scene().settings().background();
            assertThat(p.angle()).isEqualTo(1.5);
            assertThat(p.image().width()).isEqualTo(4);
            assertThat(Path.of(p.path())).exists();
        }
    }
}
