package dev.crt.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarStyle;

/** A progress bar with ETA on stderr, shown only when there is a terminal to show it on. */
final class Progress implements AutoCloseable {
    static final Progress NONE = new Progress(null);

    private final ProgressBar bar;
    /** Set while the bar stands at 0 for a step before the counted work (see {@link #preparing}). */
    private boolean waiting;

    private Progress(ProgressBar bar) { this.bar = bar; }

    /** A bar named {@code task} counting to {@code total}, or a silent one when quiet or not on a terminal. */
    static Progress start(String task, long total, String unit, boolean quiet) {
        if (quiet || !stderrIsTerminal()) return NONE;
        PrintStream err = System.err;
        ProgressBar bar = new ProgressBarBuilder()
                .setTaskName(task)
                .setInitialMax(total)
                .setStyle(ProgressBarStyle.COLORFUL_UNICODE_BLOCK)
                .setUnit(" " + unit, 1)
                .setUpdateIntervalMillis(200)
                .setConsumer(new ConsoleProgressBarConsumer(err))
                .build();
        return new Progress(bar);
    }

    /**
     * Whether stderr is a terminal. System.console() answers for stdin and stdout instead (and on
     * newer JDKs is there even when nothing is a terminal), so {@code 2> log} on a terminal would
     * fill the log with bars; on Linux the descriptor itself says where it goes.
     */
    static boolean stderrIsTerminal() {
        return isTerminal(Path.of("/proc/self/fd/2"));
    }

    /** Whether the descriptor link {@code fd} leads to a terminal device; elsewhere than Linux, the console decides. */
    static boolean isTerminal(Path fd) {
        String target;
        try {
            target = Files.readSymbolicLink(fd).toString();
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return System.console() != null;
        }
        return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty") || target.equals("/dev/console");
    }

    /**
     * Shows {@code what} beside the bar until the first update, and starts the bar's clock only
     * then: the elapsed time and the ETA are of the counted work alone, not of the step before it
     * (building the BVH of a million objects takes seconds in which no pixel is done).
     */
    synchronized void preparing(String what) {
        if (bar == null) return;
        bar.setExtraMessage(what);
        waiting = true;
    }

    synchronized void update(long done, long total) {
        if (bar == null) return;
        if (waiting) {
            waiting = false;
            bar.reset();
            bar.setExtraMessage("");
        }
        if (bar.getMax() != total) bar.maxHint(total);
        bar.stepTo(done);
    }

    synchronized void message(String text) {
        if (bar != null) bar.setExtraMessage(text);
    }

    @Override
    public synchronized void close() {
        if (bar != null) bar.close();
    }
}
