package dev.crt.cli;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Diagnostic;
import dev.crt.lang.DiagnosticFormatter;
import dev.crt.lang.Source;
import dev.crt.render.RenderCancelledException;
import dev.crt.render.RenderMonitor;
import dev.crt.scene.Scene;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.UnaryOperator;

/**
 * Renders frames on a number of workers. Each frame is one independent unit: the script compiled
 * afresh with t set to the frame number, then {@link FrameJob} renders it and writes it atomically.
 * A failing frame stops the run (frames in progress are cancelled and write nothing) unless the run
 * keeps going, in which case every failure is collected for the end.
 */
final class AnimationRun {
    /** A frame to render and the file it goes to. */
    record Frame(int number, Path file) {}

    /** A frame that could not be made, with the exit code its failure calls for. */
    record Failure(int frame, int exitCode, String reason) {}

    /** How the run ended: failures in frame order, whether Ctrl-C stopped it, and what it cost. */
    record Outcome(List<Failure> failures, boolean cancelled, AnimationTotals totals, long wallNanos) {}

    private final Source source;
    private final CompileOptions options;
    private final UnaryOperator<Scene> commandLineSettings;
    private final int jobs;
    private final int threadsPerFrame;
    private final boolean keepGoing;
    private final PrintWriter err;

    private final AtomicBoolean stopping = new AtomicBoolean();
    private final AtomicReference<Throwable> bug = new AtomicReference<>();
    private final List<Failure> failures = new ArrayList<>();
    private final Set<String> warningsShown = ConcurrentHashMap.newKeySet();
    private final AnimationTotals totals = new AnimationTotals();

    AnimationRun(Source source, CompileOptions options, UnaryOperator<Scene> commandLineSettings, int jobs,
            int threadsPerFrame, boolean keepGoing, PrintWriter err) {
        this.source = source;
        this.options = options;
        this.commandLineSettings = commandLineSettings;
        this.jobs = jobs;
        this.threadsPerFrame = threadsPerFrame;
        this.keepGoing = keepGoing;
        this.err = err;
    }

    Outcome run(List<Frame> frames, Cancellation cancel, AnimationProgress progress) {
        long start = System.nanoTime();
        AtomicInteger next = new AtomicInteger();
        Runnable worker = () -> {
            int i;
            while (!stopping.get() && !cancel.isCancelled() && (i = next.getAndIncrement()) < frames.size()) {
                renderOne(frames.get(i), cancel, progress);
            }
        };
        List<Thread> workers = new ArrayList<>();
        for (int w = 0; w < Math.min(jobs, frames.size()); w++) {
            Thread t = new Thread(worker, "crt-frame-" + w);
            workers.add(t);
            t.start();
        }
        for (Thread t : workers) joinUninterruptibly(t);
        Throwable b = bug.get();
        if (b instanceof RuntimeException e) throw e;
        if (b instanceof Error e) throw e;
        List<Failure> sorted = new ArrayList<>(failures);
        sorted.sort(Comparator.comparingInt(Failure::frame));
        return new Outcome(sorted, cancel.isCancelled(), totals, System.nanoTime() - start);
    }

    private void renderOne(Frame frame, Cancellation cancel, AnimationProgress progress) {
        progress.started(frame.number());
        boolean written = false;
        try {
            long compileStart = System.nanoTime();
            CompileResult result = CrtCompiler.compile(source, options.withTime(frame.number()));
            long compileNanos = System.nanoTime() - compileStart;
            report(frame, result);
            if (result.hasErrors()) {
                fail(new Failure(frame.number(), ExitCode.ofErrors(result), "the script has errors at t = " + frame.number()));
                return;
            }
            Scene scene = commandLineSettings.apply(result.scene());
            RenderMonitor monitor = new RenderMonitor() {
                @Override
                public void progress(long done, long total) { progress.rendering(frame.number(), done, total); }

                @Override
                public boolean isCancelled() { return cancel.isCancelled() || stopping.get(); }
            };
            FrameJob.Outcome outcome = FrameJob.run(scene, frame.file(), threadsPerFrame, monitor);
            totals.add(compileNanos, outcome);
            written = true;
        } catch (CliFailure f) {
            fail(new Failure(frame.number(), f.exitCode(), f.getMessage()));
        } catch (RenderCancelledException e) {
            // Stopped by Ctrl-C or by another frame's failure: nothing was written for this frame.
        } catch (RuntimeException | Error e) {
            bug.compareAndSet(null, e);
            stopping.set(true);
        } finally {
            progress.finished(frame.number(), written);
        }
    }

    /** Prints a frame's errors under a line naming the frame, and each distinct warning once per run. */
    private void report(Frame frame, CompileResult result) {
        StringBuilder text = new StringBuilder();
        if (result.hasErrors()) text.append("crt: frame ").append(frame.number()).append(" (t = ").append(frame.number()).append("):\n");
        for (Diagnostic d : result.diagnostics()) {
            String formatted = DiagnosticFormatter.format(d, source.text());
            if (!d.isWarning() || warningsShown.add(formatted)) text.append(formatted).append('\n');
        }
        if (text.length() == 0) return;
        synchronized (err) {
            err.print(text);
            err.flush();
        }
    }

    private void fail(Failure failure) {
        synchronized (failures) {
            failures.add(failure);
        }
        if (!keepGoing) stopping.set(true);
    }

    private static void joinUninterruptibly(Thread t) {
        boolean interrupted = false;
        while (true) {
            try {
                t.join();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) Thread.currentThread().interrupt();
    }
}
