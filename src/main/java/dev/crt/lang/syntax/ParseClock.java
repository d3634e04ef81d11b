package dev.crt.lang.syntax;

import dev.crt.lang.parser.CRTLexer;
import dev.crt.lang.parser.CRTParser;
import java.time.Duration;
import org.antlr.v4.runtime.CharStream;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenStream;

/**
 * The compile's time budget as seen by the lexer and the parser: they look at the clock every
 * 4096 tokens and rule entries, so that no script, however long, parses past its budget.
 */
public final class ParseClock {
    /** Thrown out of the lexer or parser when the budget is spent. */
    public static final class OutOfTime extends RuntimeException {
        private final transient Token at;

        OutOfTime(String message, Token at) {
            super(message, null, false, false);
            this.at = at;
        }

        /** The token the parser had reached. */
        public Token at() { return at; }
    }

    private final long startNanos;
    private final long limitNanos;
    private final Duration limit;
    private int ticks;

    /** A clock started at {@code startNanos} (System.nanoTime) with {@code limit} to spend. */
    public ParseClock(long startNanos, Duration limit) {
        this.startNanos = startNanos;
        this.limit = limit;
        long nanos;
        try {
            nanos = Math.max(0, limit.toNanos());
        } catch (ArithmeticException tooLong) {
            nanos = Long.MAX_VALUE;
        }
        this.limitNanos = nanos;
    }

    /** Counts one token or rule entry; every 4096th looks at the clock. */
    void tick(Token at) {
        if (due()) check(at);
    }

    /** Counts one token; true for every 4096th, which must then {@link #check} the clock. */
    boolean due() { return (++ticks & 4095) == 0; }

    /** Stops the parse at {@code at} when the budget is spent. */
    void check(Token at) {
        if (System.nanoTime() - startNanos > limitNanos) {
            long ms = limit.toMillis();
            throw new OutOfTime("parsing stopped: it took longer than the time budget of "
                    + (ms % 1000 == 0 ? ms / 1000 + " s" : ms + " ms")
                    + " (--time-budget gives more time)", at);
        }
    }

    /** A lexer of {@code chars} that keeps to the budget. */
    CRTLexer lexer(CharStream chars) {
        return new CRTLexer(chars) {
            @Override
            public Token nextToken() {
                Token token = super.nextToken();
                tick(token);
                return token;
            }
        };
    }

    /** A parser of {@code tokens} that keeps to the budget. */
    CRTParser parser(TokenStream tokens) {
        return new CRTParser(tokens) {
            @Override
            public void enterRule(ParserRuleContext context, int state, int ruleIndex) {
                tick(getCurrentToken());
                super.enterRule(context, state, ruleIndex);
            }

            @Override
            public void enterRecursionRule(ParserRuleContext context, int state, int ruleIndex, int precedence) {
                tick(getCurrentToken());
                super.enterRecursionRule(context, state, ruleIndex, precedence);
            }
        };
    }
}
