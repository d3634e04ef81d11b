package dev.crt.lang.syntax;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.lang.parser.CRTLexer;
import java.time.Duration;
import java.util.Collections;
import java.util.List;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.junit.jupiter.api.Test;

/**
 * Parsing reads each token a bounded number of times, whatever the length of an operator chain,
 * and the compile's time budget covers the parse. Token reads are counted rather than seconds
 * timed, so the test is exact on a busy machine: before the fix a chain of N terms cost about
 * N²/2 reads (a 50,000-term sum parsed for 39 s).
 */
class ParseTimeTest {
    /** A token stream that counts the tokens the parser consumes, lookahead included. */
    private static final class CountingTokens extends CommonTokenStream {
        long consumed;

        CountingTokens(String script) {
            super(new CRTLexer(CharStreams.fromString(script)));
            fill();
        }

        @Override
        public void consume() {
            consumed++;
            super.consume();
        }
    }

    private static double readsPerToken(String script) {
        CountingTokens tokens = new CountingTokens(script);
        ParseClock unlimited = new ParseClock(System.nanoTime(), Duration.ofDays(1));
        ScriptParser.checkingParser(tokens, unlimited).script();
        return (double) tokens.consumed / tokens.size();
    }

    private static String chain(String term, String operator, int n) {
        return String.join(" " + operator + " ", Collections.nCopies(n, term));
    }

    @Test
    void longOperatorChainsAreReadAboutOnce() {
        List<String> scripts = List.of(
                "x = " + chain("1", "+", 4000),
                "x = " + chain("1", "-", 4000),
                "x = " + chain("2 * 3", "^", 2000),
                "a = " + chain("Sphere { radius -> 1 }", "+", 1000) + "\nScene { a }",
                "x = f" + "(1)".repeat(3000),
                "x = v" + "[0]".repeat(3000),
                "x = " + chain("1", "<", 3000),
                "x = " + chain("true", "&&", 3000),
                "s = Sphere { }" + " <translate vec3(1, 0, 0)>".repeat(1000),
                String.join("\n", Collections.nCopies(3000, "x = 1 + 2")));
        for (String script : scripts) {
            assertThat(readsPerToken(script)).as(script.substring(0, 30)).isLessThan(3.0);
        }
    }

    @Test
    void aLineStartingWithAnOperatorStillContinuesTheExpression() {
        CompileResult r = CrtCompiler.compile(Source.of("t.crt", "x = 1\n- 3\nScene { Sphere { radius -> x * -1 } }\n"),
                CompileOptions.DEFAULT);
        assertThat(r.diagnostics()).noneMatch(d -> d.severity() == dev.crt.lang.Severity.ERROR);
        assertThat(r.scene()).isNotNull();
    }

    @Test
    void theTimeBudgetCoversTheParse() {
        String script = "x = " + chain("1", "+", 100_000) + "\n";
        CompileOptions options = new CompileOptions(0, List.of(), CompileOptions.DEFAULT_LOOP_BUDGET, Duration.ofMillis(1));
        CompileResult r = CrtCompiler.compile(Source.of("big.crt", script), options);
        assertThat(r.scene()).isNull();
        assertThat(r.diagnostics()).hasSize(1);
        assertThat(r.diagnostics().get(0).message())
                .isEqualTo("parsing stopped: it took longer than the time budget of 1 ms (--time-budget gives more time)");
        assertThat(r.diagnostics().get(0).span().line()).isEqualTo(1);
    }
}
