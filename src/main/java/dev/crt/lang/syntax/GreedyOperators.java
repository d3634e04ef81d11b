package dev.crt.lang.syntax;

import dev.crt.lang.parser.CRTParser;
import java.util.Arrays;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.TokenStream;
import org.antlr.v4.runtime.atn.ATN;
import org.antlr.v4.runtime.atn.ATNState;
import org.antlr.v4.runtime.atn.DecisionState;
import org.antlr.v4.runtime.atn.ParserATNSimulator;
import org.antlr.v4.runtime.atn.PrecedencePredicateTransition;
import org.antlr.v4.runtime.atn.PredictionContextCache;
import org.antlr.v4.runtime.atn.StarLoopEntryState;
import org.antlr.v4.runtime.atn.Transition;
import org.antlr.v4.runtime.misc.IntervalSet;

/**
 * Decides in O(1) whether an operator continues the expression before it.
 *
 * <p>Statements have no terminator and may start with {@code +}, {@code -}, {@code (} or
 * {@code [}, so after {@code 1 + 1} the next {@code + 1} could continue the sum or start a new
 * statement. The language settles it greedily (such a line continues the one before it), but
 * ANTLR's adaptive prediction proves the ambiguity by reading ahead to the end of the chain, at
 * every operator: N terms cost N² token reads (a 20,000-term sum took 7 s). This simulator
 * answers that one decision (the operator loop of {@code arithmetic}) from the next token and the
 * precedence the grammar gives it; a {@code <} (a modifier list or a comparison) still goes to
 * ANTLR, which tells them apart from the token after it.
 */
final class GreedyOperators extends ParserATNSimulator {
    private static final PredictionContextCache SHARED_CONTEXTS = new PredictionContextCache();
    private static final int LOOP_DECISION;
    // Precedence of the operator alternative each token type starts, or -1 when none does.
    private static final int[] PRECEDENCE_OF;

    static {
        ATN atn = CRTParser._ATN;
        int found = -1;
        int[] precedence = new int[atn.maxTokenType + 2];
        Arrays.fill(precedence, -1);
        for (int d = 0; d < atn.getNumberOfDecisions(); d++) {
            DecisionState state = atn.getDecisionState(d);
            if (state instanceof StarLoopEntryState loop && loop.isPrecedenceDecision
                    && state.ruleIndex == CRTParser.RULE_arithmetic) {
                found = d;
                // Transition 0 enters the loop's block; each of its alternatives is a precedence
                // predicate followed by the operator's token.
                ATNState block = loop.transition(0).target;
                for (int alt = 0; alt < block.getNumberOfTransitions(); alt++) {
                    operatorOf(block.transition(alt).target, -1, precedence, 0);
                }
            }
        }
        if (found < 0) throw new IllegalStateException("the grammar has no operator loop in 'arithmetic'");
        LOOP_DECISION = found;
        PRECEDENCE_OF = precedence;
    }

    /** Installs the simulator in {@code parser}. */
    static void install(CRTParser parser) {
        parser.setInterpreter(new GreedyOperators(parser));
    }

    private GreedyOperators(CRTParser parser) {
        super(parser, CRTParser._ATN, parser.getInterpreter().decisionToDFA, SHARED_CONTEXTS);
    }

    private static void operatorOf(ATNState state, int precedence, int[] into, int depth) {
        if (depth > 8) return;
        for (int i = 0; i < state.getNumberOfTransitions(); i++) {
            Transition t = state.transition(i);
            if (t instanceof PrecedencePredicateTransition p) {
                operatorOf(t.target, p.precedence, into, depth + 1);
            } else if (t.isEpsilon()) {
                operatorOf(t.target, precedence, into, depth + 1);
            } else if (precedence >= 0) {
                IntervalSet tokens = t.label();
                if (tokens == null) continue;
                for (int type : tokens.toList()) if (type >= 0 && type < into.length) into[type] = precedence;
            }
        }
    }

    @Override
    public int adaptivePredict(TokenStream input, int decision, ParserRuleContext outerContext) {
        if (decision == LOOP_DECISION) {
            int next = input.LA(1);
            if (next >= 0 && next < PRECEDENCE_OF.length && PRECEDENCE_OF[next] >= 0 && next != CRTParser.LT) {
                // Alternative 1 takes the loop once more, 2 leaves it: the operator binds here
                // only if its precedence is at least that of the operand being parsed.
                return parser.precpred(outerContext, PRECEDENCE_OF[next]) ? 1 : 2;
            }
        }
        return super.adaptivePredict(input, decision, outerContext);
    }
}
