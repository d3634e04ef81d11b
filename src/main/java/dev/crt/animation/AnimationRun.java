package dev.crt.animation;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Diagnostic;
import dev.crt.lang.DiagnosticFormatter;
import dev.crt.lang.Source;
import dev.crt.render.RenderCancelledException;
import dev.crt.render.RenderMonitor;
import dev.crt.render.RenderStats;
import dev.crt.scene.Scene;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Settings;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.UnaryOperator;

/**
 * Renders frames on a number of workers: the engine of {@code crt animate} and of the studio's
 * animation panel. Each frame is one independent unit: the script compiled afresh with t set to the
 * frame number, then {@link FrameJob} renders it and writes it atomically. A failing frame stops the
 * run (frames in progress are cancelled and write nothing) unless the run keeps going, in which case
 * every failure is collected for the end.
 */
public final class AnimationRun {
    /** A frame to render and the file it goes to. */
    public record Frame(int number, Path file) {}

    /** A frame that could not be made, whose fault it was, and why. */
    public record Failure(int frame, FrameFailure.Kind kind, String reason) {}

    /** How the run ended: failures in frame order, whether it was cancelled, and what it cost. */
    public record Outcome(List<Failure> failures, boolean cancelled, AnimationTotals totals, long wallNanos) {}

    /** Told how the frames go, from the workers' threads. */
    public interface Listener {
        /** Frame {@code frame} starts: its script is about to be compiled. */
        default void started(int frame) {}

        /** {@code done} of {@code of} pixels of frame {@code frame} are traced; called often. */
        default void rendering(int frame, long done, long of) {}

        /** A render thread of frame {@code frame} traced {@code rays} more rays (see {@link RenderMonitor#raysTraced}). */
        default void raysTraced(int frame, long rays) {}

        /**
         * Frame {@code frame} is in its file; {@code image} is its picture in linear light, with the
         * settings it was made with and what tracing it cost.
         */
        default void written(Frame frame, FrameBuffer image, Settings settings, RenderStats stats) {}

        /** Frame {@code frame} is over: written, or failed or cancelled when {@code written} is false. */
        default void finished(int frame, boolean written) {}
    }

    private final Source source;
    private final CompileOptions options;
    private final UnaryOperator<Scene> commandLineSettings;
    private final int jobs;
    private final int threadsPerFrame;
    private final boolean keepGoing;
    private final Consumer<String> report;

    private final AtomicBoolean stopping = new AtomicBoolean();
    private final AtomicReference<Throwable> bug = new AtomicReference<>();
    private final List<Failure> failures = new ArrayList<>();
    private final Set<String> warningsShown = ConcurrentHashMap.newKeySet();
    private final AnimationTotals totals = new AnimationTotals();

    /**
     * A run of {@code source} compiled with {@code options} (t set per frame), each scene passed
     * through {@code settings} (the command line's or the session's overrides), {@code jobs} frames
     * at once on {@code threadsPerFrame} threads each; diagnostics go to {@code report} as text.
     */
    public AnimationRun(Source source, CompileOptions options, UnaryOperator<Scene> settings, int jobs,
            int threadsPerFrame, boolean keepGoing, Consumer<String> report) {
        this.source = source;
        this.options = options;
        this.commandLineSettings = settings;
        this.jobs = jobs;
        this.threadsPerFrame = threadsPerFrame;
        this.keepGoing = keepGoing;
        this.report = report;
    }

    /** Renders {@code frames} and returns how it went; {@code cancel} is polled to stop (frames in flight write nothing). */
    public Outcome run(List<Frame> frames, BooleanSupplier cancel, Listener progress) {
        long start = System.nanoTime();
        AtomicInteger next = new AtomicInteger();
        Runnable worker = () -> {
            int i;
            while (!stopping.get() && !cancel.getAsBoolean() && (i = next.getAndIncrement()) < frames.size()) {
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
        return new Outcome(sorted, cancel.getAsBoolean(), totals, System.nanoTime() - start);
    }

    private void renderOne(Frame frame, BooleanSupplier cancel, Listener progress) {
        progress.started(frame.number());
        boolean written = false;
        try {
            long compileStart = System.nanoTime();
            CompileResult result = CrtCompiler.compile(source, options.withTime(frame.number()));
            long compileNanos = System.nanoTime() - compileStart;
            report(frame, result);
            if (result.hasErrors()) {
                fail(new Failure(frame.number(), result.outOfMemory() ? FrameFailure.Kind.MEMORY : FrameFailure.Kind.SCRIPT,
                        "the script has errors at t = " + frame.number()));
                return;
            }
            Scene scene = commandLineSettings.apply(result.scene());
            RenderMonitor monitor = new RenderMonitor() {
                @Override
                public void progress(long done, long total) { progress.rendering(frame.number(), done, total); }

                @Override
                public void raysTraced(long rays) { progress.raysTraced(frame.number(), rays); }

                @Override
                public boolean isCancelled() { return cancel.getAsBoolean() || stopping.get(); }
            };
            FrameJob.Outcome outcome = FrameJob.run(scene, frame.file(), threadsPerFrame, monitor,
                    (image, stats) -> progress.written(frame, image, scene.settings(), stats));
            totals.add(compileNanos, outcome);
            written = true;
        } catch (FrameFailure f) {
            fail(new Failure(frame.number(), f.kind(), f.getMessage()));
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
        report.accept(text.toString());
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
