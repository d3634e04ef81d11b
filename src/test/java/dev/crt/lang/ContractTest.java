package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static dev.crt.lang.Scripts.error;
import static dev.crt.lang.Scripts.errors;
import static dev.crt.lang.Scripts.scene;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Csg;
import dev.crt.scene.Scene;
import dev.crt.scene.Sphere;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Statements of the language reference that the other tests leave uncovered, one by one. */
class ContractTest {
    /** The value of a top-level expression, read back through a sphere's radius. */
    private static double number(String expression) {
        Scene s = scene(CAMERA + "x = " + expression + "\nScene { Sphere { radius -> x } }\n");
        return ((Sphere) s.entities().get(0)).radius();
    }

    private static double truth(String condition) { return number("(" + condition + ") ? 1 : 0"); }

    private static void at(Diagnostic d, int line, int column, int length, String message) {
        assertThat(d.message()).isEqualTo(message);
        assertThat(d.span().line()).as("line of: " + message).isEqualTo(line);
        assertThat(d.span().column()).as("column of: " + message).isEqualTo(column);
        assertThat(d.span().end() - d.span().start()).as("length of: " + message).isEqualTo(length);
    }

    @Test
    void precedenceLevelsOfSection3() {
        assertThat(number("-[2, -3][1]")).as("index binds tighter than sign").isEqualTo(3);
        assertThat(truth("!false == true")).as("! binds tighter than ==").isEqualTo(1);
        assertThat(truth("!(false == true)")).isEqualTo(1);
        assertThat(number("(a = b = 3) + a + b")).as("= is right-associative").isEqualTo(9);
        assertThat(number("true ? 1 : true ? 2 : 3")).isEqualTo(1);
        assertThat(number("2 * 3 % 4")).as("* and % are left-associative").isEqualTo(2);
        assertThat(error("x = 1 < 2 == 2 < 3\n").message()).as("all comparisons share one left-associative level")
                .isEqualTo("operator '==' cannot apply to boolean and number");
        assertThat(truth("true || false && false")).as("&& binds tighter than ||").isEqualTo(1);
        assertThat(number("5\n- 2")).as("a line starting with - continues").isEqualTo(3);

        // Modifiers bind tighter than CSG: only the right operand moves.
        Scene s = scene(CAMERA + "a = Sphere { }\nb = Sphere { }\nScene { a - b <translate vec3(1, 0, 0)> }\n");
        Csg csg = (Csg) s.entities().get(0);
        assertThat(((Sphere) csg.left()).transform().translationPart().x()).isZero();
        assertThat(((Sphere) csg.right()).transform().translationPart().x()).isEqualTo(1);
    }

    @Test
    void equalityComparesNumbersByValueWhereverTheySit() {
        assertThat(truth("[1, [2]] == [1.0, [2.0]]")).isEqualTo(1);
        assertThat(truth("-vec3(0, 1, 0) == vec3(0, -1, 0)")).as("-0 equals 0").isEqualTo(1);
        assertThat(truth("-rgb(0, 0, 0) == rgb(0, 0, 0)")).isEqualTo(1);
        assertThat(truth("[vec3(0, 0, 0)] == [-vec3(0, 0, 0)]")).isEqualTo(1);
        assertThat(truth("[1, \"a\"] != [1, 2]")).as("items of different types differ").isEqualTo(1);
        assertThat(truth("[1, 2] != [1, 2, 3]")).isEqualTo(1);
        assertThat(truth("[] == []")).isEqualTo(1);
    }

    @Test
    void piIsPredefinedButOriginalScriptsMayStillNameAVariablePi() {
        // Compatibility: `pi` is an extension, so a 2015 script that assigns it must keep working.
        assertThat(number("pi")).isEqualTo(Math.PI);
        Scene s = scene(CAMERA + "pi = 3\nScene { Sphere { radius -> pi } }\n");
        assertThat(((Sphere) s.entities().get(0)).radius()).isEqualTo(3);
    }

    @Test
    void aWrongAttributeNameIsUnderlinedAlone() {
        at(error("s = Sphere { radus -> 2 }\n"), 1, 14, 5, "unknown attribute 'radus' for Sphere (did you mean 'radius'?)");
        at(error("s = Sphere { radius -> 1 radius -> 2 }\n"), 1, 26, 6, "attribute 'radius' is given twice (first at 1:14)");
    }

    @Test
    void aMissingCommaBetweenModifiersIsSaidSo() {
        Diagnostic d = errors(CAMERA + "Scene { Sphere { } <translate vec3(1, 0, 0) scale 2> }\n").get(0);
        assertThat(d.message()).isEqualTo("unexpected 'scale'; expected ',' between modifiers");
        assertThat(d.span().line()).isEqualTo(2);
        assertThat(d.span().column()).isEqualTo(45);
    }

    @Test
    void aTypeNameWithoutBracesDoesNotClaimAnOpenBrace() {
        List<Diagnostic> es = errors("x = Sphere\n");
        assertThat(es).extracting(Diagnostic::message).containsExactly("unexpected end of file");
        assertThat(errors("x = Settings\n")).extracting(Diagnostic::message).noneMatch(m -> m.contains("to close"));
    }

    @Test
    void lenSaysWhatItTakes() {
        assertThat(error("x = len(3)\n").message()).isEqualTo("wrong arguments: len takes len(list or string), got len(number)");
        assertThat(number("len(\"abc\") + len([1, 2])")).isEqualTo(5);
    }

    @Test
    void aWholeFloatWhereAnIntegerIsRequiredReadsAsAFloat() {
        // "expects an integer, got the float 2" would read as a contradiction.
        at(error("Settings { supersampling -> 2.0 }\n"), 1, 12, 20,
                "attribute 'supersampling' of Settings expects an integer, got the float 2.0");
        at(error("xs = [1, 2]\nx = xs[1.0]\n"), 2, 8, 3, "an index must be an integer, got the float 1.0");
        at(error("xs = [1, 2]\nx = xs[2 / 2]\n"), 2, 8, 5, "an index must be an integer, got the float 1.0");
    }

    @Test
    void anExponentWithoutDigitsIsOneClearError() {
        at(error("x = 2 * 1e\n"), 1, 9, 2, "malformed number '1e': an exponent needs digits, as in 1e3 or 2.5e-4");
        at(error("x = 2.5E-\n"), 1, 5, 5, "malformed number '2.5E-': an exponent needs digits, as in 1e3 or 2.5e-4");
        assertThat(number("1.e1 + 1E-1 + .5e+1 + 1.")).isEqualTo(16.1);
    }

    @Test
    void columnsCountCharactersAsSeenEvenBeyondTheBasicPlane() {
        // The emoji is one character (two Java chars); the offsets stay Java char offsets for editors.
        Diagnostic d = error("x = [\"\uD83D\uDE00\", 1 + \"a\"]\n");
        assertThat(d.span().column()).isEqualTo(11);
        assertThat(d.span().start()).isEqualTo(11);
    }

    @Test
    void aTypeWrittenInLowercaseGetsAHint() {
        Diagnostic d = errors("s = sphere { radius -> 1 }\n").get(0);
        assertThat(d.message()).isEqualTo("unexpected '{' after 'sphere' (type names start with an uppercase letter: 'Sphere')");
        assertThat(d.span().column()).isEqualTo(12);
    }

    @Test
    void theControlWordsAreReservedToo() {
        assertThat(errors("while = 2\n").get(0).message()).isEqualTo("unexpected '=' ('while' is a reserved word and cannot name a variable)");
        assertThat(errors("if = 2\n").get(0).message()).isEqualTo("unexpected '=' ('if' is a reserved word and cannot name a variable)");
        assertThat(errors("else = 2\n").get(0).message()).startsWith("unexpected 'else'");
    }

    @Test
    void aParallelLightFromAPointTowardsItselfIsAnErrorWhateverTheSignOfZero() {
        Diagnostic d = error("l = ParallelLight { from -> vec3(0, 0, 0) pointing -> -vec3(0, 0, 0) }\n");
        assertThat(d.message()).isEqualTo("a ParallelLight's pointing must differ from its from");
    }

    @Test
    void anUnterminatedStringIsOneErrorNotACascade() {
        at(error("s = \"abc\n"), 1, 5, 4, "unterminated string (a string ends with \" on the line it starts)");
        at(error("x = \"a\" \"b\n"), 1, 9, 2, "unterminated string (a string ends with \" on the line it starts)");
    }

    @Test
    void aWrongOrMissingCloserNamesTheConstructStillOpen() {
        assertThat(errors(CAMERA + "Scene { Sphere { } <translate vec3(1, 0, 0) }\n").get(0).message())
                .isEqualTo("unexpected '}'; expected '>' to close '<' opened at 2:20");
        assertThat(errors("x = [1, 2)\n").get(0).message()).isEqualTo("unexpected ')'; expected ']' to close '[' opened at 1:5");
        // The '(' of `if` was never written, so no message may say where it was opened.
        assertThat(errors("if x > 1 { }\n")).extracting(Diagnostic::message)
                .containsExactly("expected '(' before 'x'", "expected ')' before '{'");
    }

    @Test
    void noFunctionHandsOnAnInfinity() {
        assertThat(error("x = dot(vec3(1e200, 0, 0), vec3(1e200, 0, 0))\n").message()).isEqualTo("the result of dot(…) is too large");
        assertThat(error("x = cross(vec3(1e200, 0, 0), vec3(0, 1e200, 0))\n").message()).isEqualTo("the result of cross(…) is too large");
        assertThat(error("x = degrees(1e308)\n").message()).isEqualTo("the result of degrees(…) is too large");
        assertThat(error("x = rand(-1e308, 1e308)\n").message()).isEqualTo("the result of rand(…) is too large");
        // Large but finite vectors keep their length and direction.
        assertThat(number("length(vec3(3e200, 4e200, 0)) / 1e200")).isCloseTo(5, org.assertj.core.api.Assertions.within(1e-12));
        assertThat(number("normalize(vec3(1e200, 1e200, 0))[0]")).isCloseTo(Math.sqrt(0.5), org.assertj.core.api.Assertions.within(1e-12));
        Scene s = scene(CAMERA + "Scene { Plane { normal -> vec3(0, 1e200, 1e200) } }\n");
        assertThat(((dev.crt.scene.Plane) s.entities().get(0)).normal().y()).isCloseTo(Math.sqrt(0.5), org.assertj.core.api.Assertions.within(1e-12));
    }

    @Test
    void hugeNumbersInMessagesAreWrittenAsInScripts() {
        assertThat(error("Settings { width -> 10000000000000000000000 }\n").message()).isEqualTo("width must be an integer >= 1, got 1e22");
        assertThat(error("xs = [1]\nx = xs[floor(1.5e300)]\n").message()).isEqualTo("index 1.5e300 is out of range for a list of length 1");
    }

    @Test
    void onlyAVariableCanBeAssigned() {
        String message = "unexpected '='; only a variable can be assigned, as in 'name = value'";
        assertThat(errors("v = [1]\nv[0] = 1\n").get(0).message()).isEqualTo(message);
        assertThat(errors("x = (a) = 2\n").get(0).message()).isEqualTo(message);
        assertThat(errors("Sphere = 1\n").get(0).message()).isEqualTo(message);
    }

    @Test
    void aMisspeltModifierIsNamed() {
        Diagnostic d = errors(CAMERA + "s = Sphere { }\nScene { s <rotat vec3(0, 90, 0)> }\n").get(0);
        assertThat(d.message()).isEqualTo("unknown modifier 'rotat' (did you mean 'rotate'?)");
        assertThat(d.span().line()).isEqualTo(3);
        assertThat(d.span().column()).isEqualTo(12);
        assertThat(errors("s = Sphere { }\nScene { s <scale 2, move vec3(1, 0, 0)> }\n").get(0).message())
                .isEqualTo("unknown modifier 'move' (the modifiers are translate, rotate and scale)");
        // `s <rotat v> t` is even valid syntax (two comparisons): the evaluation names the modifier.
        Diagnostic valid = errors("s = Sphere { }\nScene { s <rotat vec3(0, 90, 0)> s }\n").get(0);
        assertThat(valid.message()).isEqualTo("unknown modifier 'rotat' (did you mean 'rotate'?)");
        assertThat(valid.span().column()).isEqualTo(12);
        // A comparison with a variable of a modifier-like name is not mistaken for one.
        assertThat(errors("scal2 = 1\nok = 0 < scal2 && 2 > 1\ny = )\n")).extracting(Diagnostic::message)
                .containsExactly("unexpected ')'");
    }

    /** The original CRT's runaway sample (section 8), compiled in a JVM with a heap too small for 10,000,000 entities. */
    static final class SmallHeapSample {
        public static void main(String[] args) {
            String sample = "f = Macro (max) { i = 0\n"
                    + "while (i < max) { sphere1 <translate vec3(i*1.0, 0.0, 0.0)>  i = i - 1 } }\n"
                    + "sphere1 = Sphere { }\nScene { f(3) }\n";
            // A time budget well beyond what filling 96 MB takes, so that on a loaded machine the
            // memory, which this test is about, still runs out before the clock does.
            CompileOptions options = new CompileOptions(0, java.util.List.of(), CompileOptions.DEFAULT_LOOP_BUDGET,
                    java.time.Duration.ofSeconds(120));
            Diagnostic d = CrtCompiler.compile(Source.of("test.crt", sample), options).diagnostics().get(0);
            System.out.println(d.span().line() + ":" + d.span().column() + " " + d.message());
        }
    }

    @Test
    void theRunawaySampleStopsAtItsLoopEvenWhenTheHeapIsTooSmallForTheIterationBudget() throws Exception {
        String javaBin = java.nio.file.Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(javaBin, "-Xmx96m", "-XX:+UseSerialGC", "-cp", System.getProperty("java.class.path"),
                SmallHeapSample.class.getName()).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertThat(p.waitFor()).as(out).isZero();
        assertThat(out).startsWith("2:1 evaluation stopped: the loops' values filled the memory after ")
                .contains("iterations (is the loop condition ever false? if not, give Java more memory: CRT_JAVA_OPTS=-Xmx");
    }
}
