package dev.crt.lang;

import static dev.crt.lang.Scripts.errors;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Syntax errors: human messages, all of them (up to 20), never ANTLR's console output. */
class SyntaxErrorsTest {
    private static void at(Diagnostic d, int line, int column, String message) {
        assertThat(d.message()).isEqualTo(message);
        assertThat(d.span().line()).as("line of: " + message).isEqualTo(line);
        assertThat(d.span().column()).as("column of: " + message).isEqualTo(column);
    }

    @Test
    void unclosedObjectNamesWhereItOpened() {
        List<Diagnostic> es = errors("a = 1\nb = 2\nc = Sphere { radius -> 1\n");
        assertThat(es).hasSize(1);
        at(es.get(0), 4, 1, "expected '}' to close Sphere opened at 3:5");
    }

    @Test
    void unexpectedToken() {
        at(errors("s = Sphere { -> 1 }\n").get(0), 1, 14, "unexpected '->'");
    }

    @Test
    void severalErrorsInOneFileAreAllReported() {
        String script = "a = (1 + 2\nb = Sphere { radius 1 }\nc = 3 +\nScene { a b }\nd = ]\n";
        List<Diagnostic> es = errors(script);
        assertThat(es).extracting(d -> d.span().line()).containsExactly(2, 2, 3, 5);
        at(es.get(0), 2, 1, "expected ')' to close '(' opened at 1:5 before 'b'");
        at(es.get(1), 2, 21, "expected '->' before '1'");
        // `c = 3 +` was cut at the end of its line: that is where the mistake is, not at 'Scene'.
        at(es.get(2), 3, 7, "expected an expression after '+' at the end of line 3");
        assertThat(es).allSatisfy(d -> assertThat(d.message()).doesNotContain("{").doesNotContain("<EOF>"));
    }

    @Test
    void atMostTwentyErrorsAreReportedThenANoteSaysWhereItStopped() {
        CompileResult r = Scripts.compile("x = ]\n".repeat(25));
        assertThat(r.scene()).isNull();
        assertThat(r.hasErrors()).isTrue();
        assertThat(r.errorCount()).isEqualTo(20);
        assertThat(r.warningCount()).isZero();
        List<Diagnostic> all = r.diagnostics();
        assertThat(all).hasSize(21);
        assertThat(all.subList(0, 20)).allSatisfy(d -> assertThat(d.severity()).isEqualTo(Severity.ERROR));
        assertThat(all.get(20).severity()).isEqualTo(Severity.NOTE);
        at(all.get(20), 20, 5, "too many errors; stopped after 20");
    }

    @Test
    void unterminatedString() {
        at(errors("Settings { title -> \"Hello\n}\n").get(0), 1, 21,
                "unterminated string (a string ends with \" on the line it starts)");
    }

    @Test
    void strayCharacter() {
        at(errors("a = 1 # 2\n").get(0), 1, 7, "unexpected character '#'");
    }

    @Test
    void assignmentNeedsAnIdentifierOnTheLeft() {
        at(errors("3 = x\n").get(0), 1, 3, "unexpected '='; only a variable can be assigned, as in 'name = value'");
    }

    @Test
    void reservedWordsCannotBeAssigned() {
        at(errors("scale = 2\n").get(0), 1, 1, "unexpected 'scale' (it is a reserved word and cannot name a variable)");
    }

    @Test
    void missingParenthesis() {
        at(errors("x = (1 + 2\n").get(0), 2, 1, "expected ')' to close '(' opened at 1:5");
    }

    @Test
    void syntaxErrorsStopBeforeEvaluation() {
        List<Diagnostic> es = errors("x = sqrt(-1)\ny = )\n");
        assertThat(es).singleElement().satisfies(d -> assertThat(d.span().line()).isEqualTo(2));
    }

    @Test
    void anAttributeGivenWithEqualsSaysArrow() {
        at(errors("s = Sphere { radius = 1 }\n").get(0), 1, 21,
                "unexpected '='; attributes are given with '->', as in 'radius -> value'");
        at(errors("Settings { width = 10 }\n").get(0), 1, 18,
                "unexpected '='; attributes are given with '->', as in 'width -> value'");
    }

    @Test
    void aCapitalisedKeywordSaysKeywordsAreLowercase() {
        at(errors("x = 1\nIf (x > 0) { y = 2 }\n").get(0), 2, 4, "unexpected '(' after 'If' (keywords are lowercase: 'if')");
        at(errors("While (true) { }\n").get(0), 1, 7, "unexpected '(' after 'While' (keywords are lowercase: 'while')");
    }

    @Test
    void anExpressionCutAtALineEndIsReportedWhereItEnds() {
        at(errors("x = 2 *\n\nScene { }\n").get(0), 1, 7, "expected an expression after '*' at the end of line 1");
        // `y` is taken as the missing operand, so the parse fails at '=': the cut is still the mistake.
        at(errors("x = 1 +\ny = 2\n").get(0), 1, 7, "expected an expression after '+' at the end of line 1");
        at(errors("b = x &&\n").get(0), 1, 7, "expected an expression after '&&' at the end of line 1");
    }

    @Test
    void aLineThatContinuesTheOneBeforeSaysSo() {
        at(errors("a = Sphere { }\n[a, a]\n").get(0), 2, 3, "unexpected ',' (the '[' at the start of line 2 continues"
                + " the expression of the line before it: a newline does not end a statement)");
        List<Diagnostic> evaluated = Scripts.compile("a = 1\nb = a\n- Sphere { }\n").diagnostics();
        assertThat(evaluated.get(0).message()).isEqualTo("operator '-' cannot apply to number and entity (the '-' at the"
                + " start of line 3 continues the expression of the line before it: a newline does not end a statement)");
    }
}
