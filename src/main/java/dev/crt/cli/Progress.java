package dev.crt.cli;

import java.io.PrintStream;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarStyle;

/** A progress bar with ETA on stderr, shown only when there is a terminal to show it on. */
final class Progress implements AutoCloseable {
    static final Progress NONE = new Progress(null);

    private final ProgressBar bar;

    private Progress(ProgressBar bar) { this.bar = bar; }

    /** A bar named {@code task} counting to {@code total}, or a silent one when quiet or not on a terminal. */
    static Progress start(String task, long total, String unit, boolean quiet) {
        if (quiet || System.console() == null) return NONE;
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

    synchronized void update(long done, long total) {
        if (bar == null) return;
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
