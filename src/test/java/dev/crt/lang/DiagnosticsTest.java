package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static dev.crt.lang.Scripts.error;
import static dev.crt.lang.Scripts.errors;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every diagnostic of the language reference: message, line and column. */
class DiagnosticsTest {
    private static void at(Diagnostic d, int line, int column, String message) {
        assertThat(d.message()).isEqualTo(message);
        assertThat(d.span().line()).as("line of: " + message).isEqualTo(line);
        assertThat(d.span().column()).as("column of: " + message).isEqualTo(column);
    }

    @Test
    void evaluationStopsAfterTwentyErrorsWithANoteThatIsNotCountedAsAnError() {
        CompileResult r = Scripts.compile(CAMERA + "x = 1 + true\n".repeat(25) + "Scene { }\n");
        assertThat(r.scene()).isNull();
        assertThat(r.hasErrors()).isTrue();
        assertThat(r.errorCount()).isEqualTo(20);
        assertThat(r.warningCount()).isZero();
        List<Diagnostic> all = r.diagnostics();
        assertThat(all).hasSize(21);
        assertThat(all.get(20).severity()).isEqualTo(Severity.NOTE);
        at(all.get(20), 21, 5, "too many errors; stopped after 20");
    }

    @Test
    void unknownTypeSuggestsTheClosest() {
        at(error("s = Sphre { radius -> 1 }\n"), 1, 5, "unknown type 'Sphre' (did you mean 'Sphere'?)");
    }

    @Test
    void unknownTypeWithNothingCloseHasNoSuggestion() {
        at(error("s = Teapot { }\n"), 1, 5, "unknown type 'Teapot'");
    }

    @Test
    void unknownAttributeSuggestsTheClosest() {
        at(error("s = Sphere {\n  radus -> 2\n}\n"), 2, 3, "unknown attribute 'radus' for Sphere (did you mean 'radius'?)");
    }

    @Test
    void duplicatedAttribute() {
        at(error("m = Material { diffuse -> 1\n  diffuse -> 0.5 }\n"), 2, 3, "attribute 'diffuse' is given twice (first at 1:16)");
    }

    @Test
    void missingRequiredAttribute() {
        at(error("b = Box { cornerA -> vec3(0,0,0) }\n"), 1, 5, "Box needs the attribute 'cornerB'");
    }

    @Test
    void anAttributeWhoseValueFailsIsNotAlsoReportedMissing() {
        // The value's own mistake is the one diagnostic: the attribute is written, not missing.
        at(error("b = Box { cornerA -> vec3(0,0,0) cornerB -> vec3(1, rand(), 1) }\n"), 1, 53,
                "rand takes 2 arguments, rand(number, number), got 0");
        at(error("b = Box { cornerA -> vec3(0,0,0) cornerB -> Material { ior -> 0 } }\n"), 1, 56, "ior must be > 0, got 0");
        at(error("m = Mesh { vertices -> [vec3(0,0,0), vec3(1,0,0), nowhere] faces -> [[0, 1, 2]] }\n"), 1, 51,
                "variable 'nowhere' is not assigned");
        at(error("g = Background { horizon -> rgb(1, 1, 1) sky -> rgb(0, 0, nowhere) }\n"), 1, 59,
                "variable 'nowhere' is not assigned");
    }

    @Test
    void wrongAttributeType() {
        at(error("s = Sphere { center -> rgb(1, 0, 0) }\n"), 1, 14, "attribute 'center' of Sphere expects a vec3, got rgb");
        at(error("s = Sphere { material -> 3 }\n"), 1, 14, "attribute 'material' of Sphere expects a material, got number");
    }

    @Test
    void outOfRangeAttributes() {
        at(error("c = Camera { position -> vec3(0,0,-5) pointing -> vec3(0,0,0) fov -> 180 }\n"), 1, 63,
                "fov must be in (0, 180), got 180");
        at(error("m = Material { reflectivity -> 1.5 }\n"), 1, 16, "reflectivity must be in [0, 1], got 1.5");
        at(error("m = Material { transparency -> -0.1 }\n"), 1, 16, "transparency must be in [0, 1], got -0.1");
        at(error("m = Material { ior -> 0 }\n"), 1, 16, "ior must be > 0, got 0");
        at(error("l = PointLight { origin -> vec3(0,0,0) falloff -> -1 }\n"), 1, 40, "falloff must be >= 0, got -1");
        at(error("s = Sphere { radius -> -1 }\n"), 1, 14, "radius must be >= 0, got -1");
        at(error("Settings { supersampling -> 0 }\n"), 1, 12, "supersampling must be an integer >= 1, got 0");
        at(error("Settings { gamma -> 0 }\n"), 1, 12, "gamma must be > 0, got 0");
    }

    @Test
    void planeNormalMustNotBeZero() {
        at(error("p = Plane { normal -> vec3(0,0,0) }\n"), 1, 13, "a Plane's normal must not be the zero vector");
    }

    @Test
    void apertureShapeMustBeKnown() {
        at(error("c = Camera { position -> vec3(0,0,-5) pointing -> vec3(0,0,0) apertureshape -> \"circel\" }\n"), 1, 63,
                "apertureshape must be one of \"circle\", \"triangle\", \"square\", \"pentagon\", \"hexagon\", \"octagon\", "
                        + "got \"circel\" (did you mean 'circle'?)");
    }

    @Test
    void floatWhereIntegerIsRequired() {
        at(error("Settings { width -> 640.5 }\n"), 1, 12, "attribute 'width' of Settings expects an integer, got the float 640.5");
        at(error("xs = [1, 2]\nx = xs[0.5]\n"), 2, 8, "an index must be an integer, got the float 0.5");
    }

    @Test
    void allMistakesOfOneObjectAreReported() {
        List<Diagnostic> es = errors("s = Sphere {\n radus -> 1\n center -> 2\n radius -> -1\n}\n");
        assertThat(es).extracting(d -> d.span().line()).containsExactly(2, 3, 4);
    }

    @Test
    void unassignedVariableSuggestsTheClosest() {
        at(error("sphere1 = Sphere { }\nScene { spher1 }\n"), 2, 9, "variable 'spher1' is not assigned (did you mean 'sphere1'?)");
    }

    @Test
    void unknownFunctionSuggestsTheClosest() {
        at(error("x = sqr(4)\n"), 1, 5, "unknown function or macro 'sqr' (did you mean 'sqrt'?)");
        at(error("spheres = Macro () { }\nScene { sphere() }\n"), 2, 9, "unknown function or macro 'sphere' (did you mean 'spheres'?)");
    }

    @Test
    void assigningTimeIsAnError() {
        at(error("t = 3\n"), 1, 1, "cannot assign to 't': it is the animation time, set from the command line");
    }

    @Test
    void listIndexOutOfRange() {
        at(error("xs = [1, 2, 3]\ny = xs[3]\n"), 2, 8, "index 3 is out of range for a list of length 3");
        at(error("v = vec3(1, 2, 3)\ny = v[-1]\n"), 2, 7, "index -1 is out of range for a vec3 of length 3");
    }

    @Test
    void badOperandTypesNameTheOperatorAndBothTypes() {
        at(error("x = \"a\" * vec3(1,2,3)\n"), 1, 5, "operator '*' cannot apply to string and vec3");
        at(error("s = Sphere { }\nx = s + 1\n"), 2, 5, "operator '+' cannot apply to entity and number");
        at(error("x = 2 ^ 3\n"), 1, 5, "operator '^' cannot apply to number and number (for powers, use pow(a, b))");
        at(error("x = 1 < \"b\"\n"), 1, 5, "operator '<' cannot apply to number and string");
        at(error("x = 1 == true\n"), 1, 5, "operator '==' cannot apply to number and boolean");
        at(error("x = 1 && true\n"), 1, 5, "operator '&&' takes booleans, got number");
        at(error("x = !3\n"), 1, 5, "operator '!' cannot apply to number");
        at(error("if (1) { }\n"), 1, 5, "the condition of 'if' must be a boolean, got number");
    }

    @Test
    void errorsInLoopsAreTheSameAsAtTheTopLevel() {
        at(error("i = 0\nwhile (i < 3) {\n  x = \"a\" * vec3(1,2,3)\n  i = i + 1\n}\n"), 3, 7,
                "operator '*' cannot apply to string and vec3");
        at(error("m = Macro () { sqrt(-1) }\nm()\n"), 1, 16, "sqrt of a negative number (-1)");
        at(error("i = 0\nwhile (i < 3) { y = sin(1, 2) i = i + 1 }\n"), 2, 21, "sin takes 1 argument, sin(number), got 2");
    }

    @Test
    void functionArgumentsAreChecked() {
        at(error("x = sqrt(1, 2)\n"), 1, 5, "sqrt takes 1 argument, sqrt(number), got 2");
        at(error("x = sqrt(vec3(1,2,3))\n"), 1, 5, "wrong arguments: sqrt takes sqrt(number), got sqrt(vec3)");
        at(error("x = vec3(1, 2)\n"), 1, 5, "vec3 takes 3 arguments, vec3(number, number, number), got 2");
        at(error("x = dot(1, 2)\n"), 1, 5, "wrong arguments: dot takes dot(vec3, vec3), got dot(number, number)");
    }

    @Test
    void mathDomainProblemsAreErrorsNotNaN() {
        at(error("x = sqrt(-1)\n"), 1, 5, "sqrt of a negative number (-1)");
        at(error("x = log(0)\n"), 1, 5, "log of a number that is not positive (0)");
        at(error("x = normalize(vec3(0,0,0))\n"), 1, 5, "normalize of a zero vector");
        at(error("x = asin(2)\n"), 1, 5, "asin takes a number in [-1, 1], got 2");
        at(error("x = 1 / 0\n"), 1, 5, "division by zero");
    }

    @Test
    void macroArgumentCountMustMatch() {
        at(error("row = Macro (n, y) { }\nrow(1)\n"), 2, 1, "macro 'row' takes 2 arguments (n, y), got 1");
    }

    @Test
    void callingSomethingThatIsNotAMacro() {
        at(error("x = 3\ny = x(1)\n"), 2, 5, "cannot call number 'x': only macros and functions take arguments");
    }

    @Test
    void recursionDeeperThan256CallsIsAnError() {
        Diagnostic d = error("down = Macro (n) { down(n + 1) }\nScene { down(0) }\n");
        at(d, 1, 20, "macro calls nested deeper than 256 (endless recursion?)");
        assertThat(d.callChain()).first().isEqualTo("in macro 'down' called at 1:20");
        assertThat(d.callChain()).last().isEqualTo("in macro 'down' called at 2:9");
    }

    @Test
    void errorsInsideMacrosNameTheCallChain() {
        String script = "cell = Macro (x) { Sphere { radius -> x } }\n"
                + "row = Macro (n) {\n  cell(1)\n  cell(-n)\n}\n"
                + "Scene { row(2) }\n";
        Diagnostic d = error(script);
        at(d, 1, 29, "radius must be >= 0, got -2");
        assertThat(d.callChain()).containsExactly("in macro 'cell' called at 4:3", "in macro 'row' called at 6:9");
        assertThat(DiagnosticFormatter.format(d, script)).endsWith(
                "\n  in macro 'cell' called at 4:3\n  in macro 'row' called at 6:9");
    }

    @Test
    void loopBudgetStopsEndlessLoopsAtTheLoop() {
        CompileOptions small = new CompileOptions(0, List.of(), 1000, Duration.ofSeconds(10));
        CompileResult r = CrtCompiler.compile(Source.of("loop.crt", "i = 0\n  while (true) { i = i + 1 }\n"), small);
        assertThat(r.scene()).isNull();
        at(r.diagnostics().get(0), 2, 3, "evaluation stopped: loops ran 1,000 iterations (is the loop condition ever false?)");
    }

    @Test
    void timeBudgetStopsSlowScripts() {
        CompileOptions quick = new CompileOptions(0, List.of(), Long.MAX_VALUE, Duration.ofMillis(200));
        long start = System.nanoTime();
        CompileResult r = CrtCompiler.compile(Source.of("slow.crt", "i = 0\nwhile (i >= 0) { i = i + 1 }\n"), quick);
        assertThat(Duration.ofNanos(System.nanoTime() - start)).isLessThan(Duration.ofSeconds(5));
        at(r.diagnostics().get(0), 2, 1,
                "evaluation stopped: it took longer than the time budget of 200 ms (is a loop or a recursion endless?)");
    }

    @Test
    void timeBudgetAlsoStopsExponentialRecursion() {
        CompileOptions quick = new CompileOptions(0, List.of(), Long.MAX_VALUE, Duration.ofMillis(200));
        CompileResult r = CrtCompiler.compile(Source.of("tree.crt",
                "tree = Macro (n) { if (n > 0) { tree(n - 1) tree(n - 1) } }\ntree(60)\n"), quick);
        assertThat(r.diagnostics().get(0).message()).startsWith("evaluation stopped: it took longer than the time budget");
    }

    @Test
    void listsCannotGrowWithoutBound() {
        at(error("xs = [1]\nwhile (true) { xs = xs + xs }\n"), 2, 21, "a list of 16,777,216 items is too long (at most 10,000,000)");
    }

    @Test
    void interruptingTheCallerCancelsTheCompile() throws InterruptedException {
        java.util.concurrent.atomic.AtomicReference<CompileResult> result = new java.util.concurrent.atomic.AtomicReference<>();
        Thread caller = new Thread(() -> result.set(CrtCompiler.compile(Source.of("spin.crt", "while (true) { }\n"),
                new CompileOptions(0, List.of(), Long.MAX_VALUE, Duration.ofSeconds(60)))));
        caller.start();
        Thread.sleep(300);
        caller.interrupt();
        caller.join(10_000);
        assertThat(caller.isAlive()).isFalse();
        at(result.get().diagnostics().get(0), 1, 1, "evaluation stopped: the compile was cancelled");
    }

    @Test
    void anEndlessTimeBudgetIsAccepted() {
        CompileResult r = CrtCompiler.compile(Source.of("x.crt", "while (true) { }\n"),
                new CompileOptions(0, List.of(), 5000, Duration.ofSeconds(Long.MAX_VALUE)));
        assertThat(r.diagnostics().get(0).message()).startsWith("evaluation stopped: loops ran 5,000 iterations");
    }

    @Test
    void settingsAttributesNeedTheRightKinds() {
        at(error("Settings { lights -> [PointLight { origin -> vec3(0,0,0) }, 3] }\n"), 1, 12,
                "attribute 'lights' of Settings expects a list of lights, but item 1 is a number");
        at(error("Settings { camera -> Sphere { } }\n"), 1, 12, "attribute 'camera' of Settings expects a camera, got entity");
        at(error("Settings { title -> 3 }\n"), 1, 12, "attribute 'title' of Settings expects a string, got number");
        at(error("Settings { colour -> 3 }\n"), 1, 12, "unknown attribute 'colour' for Settings");
        at(error("c = Camera { position -> vec3(1,1,1) pointing -> vec3(1,1,1) }\n"), 1, 38,
                "the camera's pointing must differ from its position");
    }

    @Test
    void scaleWithAZeroComponent() {
        at(error("s = Sphere { }\nt2 = s <scale vec3(1, 0, 1)>\n"), 2, 9,
                "scale with a zero component (vec3(1, 0, 1)) would flatten the entity");
        at(error("s = Sphere { }\nt2 = s <translate vec3(1,0,0), scale 0>\n"), 2, 32, "scale with a zero component (0) would flatten the entity");
    }

    @Test
    void modifiersNeedTheRightValues() {
        at(error("s = Sphere { }\nx = s <translate 1>\n"), 2, 8, "translate takes a vec3, got number");
        at(error("x = 3 <rotate vec3(0, 90, 0)>\n"), 1, 5, "modifiers apply to entities, got number");
    }

    @Test
    void backgroundTakesExactlyOneForm() {
        at(error("b = Background { color -> rgb(0,0,0) image -> \"sky.png\" }\n"), 1, 18,
                "a Background takes exactly one of: color, horizon with sky, or image (with angle); got color and image");
        at(error("b = Background { horizon -> rgb(0,0,0) }\n"), 1, 18, "a Background with horizon needs sky too");
    }

    @Test
    void sceneExpectsEntities() {
        at(error("Scene {\n  3\n}\n"), 2, 3, "Scene expects entities, got number");
        at(error("s = Sphere { }\nScene { [s, [s, \"x\"]] }\n"), 2, 9, "Scene expects entities, got a list containing string");
    }

    @Test
    void missingPanoramaNamesEveryPlaceSearched(@TempDir Path dir) throws IOException {
        Path script = dir.resolve("scene.crt");
        Path assets = Files.createDirectory(dir.resolve("assets"));
        String text = "b = Background { image -> \"/sky.png\" }\n";
        CompileResult r = CrtCompiler.compile(new Source("scene.crt", text, script),
                new CompileOptions(0, List.of(assets), 1000, Duration.ofSeconds(5)));
        Diagnostic d = r.diagnostics().get(0);
        at(d, 1, 18, "panorama file '/sky.png' not found; looked for /sky.png, " + dir.resolve("sky.png") + ", "
                + assets.resolve("sky.png"));
    }

    @Test
    void undecodablePanoramaIsADiagnostic(@TempDir Path dir) throws IOException {
        Path script = dir.resolve("scene.crt");
        Files.writeString(dir.resolve("sky.png"), "this is not a picture");
        String text = "b = Background { image -> \"sky.png\" }\n";
        CompileResult r = CrtCompiler.compile(new Source("scene.crt", text, script), CompileOptions.DEFAULT);
        Diagnostic d = r.diagnostics().get(0);
        at(d, 1, 18, "cannot use panorama 'sky.png': " + dir.resolve("sky.png")
                + " is not an image CRT can decode (PNG, JPEG, GIF, BMP or PPM)");
    }

    @Test
    void escapesOtherThanQuoteAndBackslashAreErrors() {
        at(error("x = \"a\\nb\"\n"), 1, 7, "unknown escape '\\n' in a string (only \\\" and \\\\ are escapes)");
    }

    @Test
    void settingsAndSceneBlocksBelongAtTheTopLevel() {
        at(error("m = Macro () { Scene { } }\nm()\n"), 1, 16, "a Scene block cannot be inside a macro");
    }

    @Test
    void oneFailedAssignmentGivesOneError() {
        List<Diagnostic> es = errors("s = Sphere { radius -> -1 }\nb = s <translate vec3(1,0,0)>\nScene { s b }\n");
        assertThat(es).hasSize(1);
    }

    @Test
    void errorsInSeveralStatementsAreAllReported() {
        List<Diagnostic> es = errors("a = 1 + \"x\"\nb = sqrt(-1)\nScene { 3 }\n");
        assertThat(es).extracting(d -> d.span().line()).containsExactly(1, 2, 3);
    }

    @Test
    void warnings() {
        CompileResult noScene = Scripts.compile(CAMERA);
        assertThat(noScene.scene()).isNotNull();
        assertThat(noScene.diagnostics()).singleElement().satisfies(d -> {
            assertThat(d.severity()).isEqualTo(Severity.WARNING);
            at(d, 1, 1, "no Scene block: the picture shows only the background");
        });

        CompileResult noCamera = Scripts.compile("Scene { }\n");
        assertThat(noCamera.scene().settings().camera()).isEqualTo(dev.crt.scene.Camera.DEFAULT);
        assertThat(noCamera.diagnostics()).singleElement().satisfies(d ->
                at(d, 1, 1, "no camera in Settings: using the default camera at vec3(0, 0, -5) pointing at the origin"));

        CompileResult rgba = Scripts.compile(CAMERA + "Scene { }\nm = Material { color -> rgba(1, 0, 0, 0.5) }\n");
        assertThat(rgba.scene()).isNotNull();
        assertThat(rgba.diagnostics()).singleElement().satisfies(d -> {
            assertThat(d.severity()).isEqualTo(Severity.WARNING);
            at(d, 3, 25, "rgba: the alpha component is accepted and ignored");
        });
    }

    @Test
    void notATextFile() {
        CompileResult r = CrtCompiler.compile(new Source("file.crt", "", null, "not a text file (invalid UTF-8 at byte 17)"),
                CompileOptions.DEFAULT);
        assertThat(r.scene()).isNull();
        assertThat(DiagnosticFormatter.format(r.diagnostics().get(0), ""))
                .startsWith("file.crt:1:1: error: not a text file (invalid UTF-8 at byte 17)");
    }
}
