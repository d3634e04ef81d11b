package dev.crt.lang;

import dev.crt.lang.eval.Evaluator;
import dev.crt.lang.syntax.ParseClock;
import dev.crt.lang.syntax.ScriptParser;
import dev.crt.scene.Scene;
import dev.crt.scene.SourceSpan;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

/** Compiles a CRT script into a Scene, or into diagnostics. Never throws for any input text. */
public final class CrtCompiler {
    // Parsing and evaluating recurse once per nesting level; a thread with a large stack lets
    // absurdly deep scripts compile, and the rare deeper one ends in a diagnostic, not a crash.
    private static final long STACK_BYTES = 1L << 30;

    private CrtCompiler() {}

    public static CompileResult compile(Source source, CompileOptions options) { return compile(source, options, true); }

    /**
     * The same; {@code fromTokens} lets top-level object literals of plain values be built from
     * their tokens (as always outside tests, which compare that with the general path, false).
     */
    static CompileResult compile(Source source, CompileOptions options, boolean fromTokens) {
        AtomicReference<CompileResult> result = new AtomicReference<>();
        AtomicReference<Evaluator> running = new AtomicReference<>();
        Thread worker = new Thread(null, () -> result.set(compileHere(source, options, fromTokens, running)),
                "crt-compile", STACK_BYTES);
        worker.setDaemon(true);
        worker.start();
        boolean interrupted = false;
        while (true) {
            try {
                worker.join();
                break;
            } catch (InterruptedException e) {
                // The caller gave up: ask the evaluation to stop, and still return a result.
                interrupted = true;
                Evaluator evaluator = running.get();
                if (evaluator != null) evaluator.cancel();
            }
        }
        if (interrupted) Thread.currentThread().interrupt();
        CompileResult r = result.get();
        return r != null ? r : failure(source, "internal error: the compile ended without a result");
    }

    private static CompileResult compileHere(Source source, CompileOptions options, boolean fromTokens,
            AtomicReference<Evaluator> running) {
        String name = source.name() == null ? "script" : source.name();
        String text = source.text() == null ? "" : source.text();
        TextPositions positions = new TextPositions(name, text);
        if (!source.isText()) {
            int at = Math.min(Math.max(source.problemOffset(), 0), text.length());
            return new CompileResult(null, List.of(error(source.decodingProblem(), positions.span(at, at + 1))));
        }
        try {
            long started = System.nanoTime();
            // A source map describes objects from their trees: its compiles build every tree.
            ScriptParser.Parsed parsed = ScriptParser.parse(positions, new ParseClock(started, options.timeBudget()),
                    fromTokens && !options.sourceMap());
            if (parsed.statements() == null) return new CompileResult(null, parsed.errors());
            Path folder = source.file() == null ? null : source.file().toAbsolutePath().getParent();
            Evaluator evaluator = new Evaluator(positions, options, folder, started);
            running.set(evaluator);
            try {
                Scene scene = evaluator.run(parsed.statements(), parsed.assignedNames(), name);
                return new CompileResult(scene, evaluator.diagnostics(), scene == null ? null : evaluator.sourceMap(),
                        evaluator.ranOutOfMemory());
            } catch (StackOverflowError e) {
                List<Diagnostic> all = new ArrayList<>(evaluator.diagnostics());
                all.add(error("evaluation nested too deeply (an expression or list nested thousands of levels deep?)",
                        positions.span(0, 0)));
                return new CompileResult(null, all);
            }
        } catch (StackOverflowError e) {
            return new CompileResult(null, List.of(error("expression nested too deeply to parse", positions.span(0, 0))));
        } catch (OutOfMemoryError e) {
            return new CompileResult(null, List.of(error("the script needs more memory than the Java heap has"
                    + " (give Java more: CRT_JAVA_OPTS=-Xmx2g ./crt …)", positions.span(0, 0))), null, true);
        } catch (RuntimeException e) {
            // A bug in the compiler: say so plainly rather than throw at the caller.
            return new CompileResult(null, List.of(error("internal error: " + e, positions.span(0, 0))));
        }
    }

    private static CompileResult failure(Source source, String message) {
        String name = source.name() == null ? "script" : source.name();
        return new CompileResult(null, List.of(error(message, new SourceSpan(name, 1, 1, 0, 0))));
    }

    private static Diagnostic error(String message, SourceSpan span) {
        return new Diagnostic(Severity.ERROR, message, span, List.of());
    }
}
