package dev.crt.cli;

import dev.crt.animation.AnimationRun;
import java.io.PrintWriter;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentSkipListMap;

/**
 * Shows how an animate run goes: on a terminal a bar of frames with the ETA and the progress of the
 * frames being rendered; in a log (a render farm's output file) one line per finished frame with
 * the count and the ETA; nothing when quiet.
 */
final class AnimationProgress implements AutoCloseable, AnimationRun.Listener {
    private enum Mode { BAR, LINES, NONE }

    private final Mode mode;
    private final Progress bar;
    private final PrintWriter err;
    private final int total;
    private final long start = System.nanoTime();
    /** Percent done of each frame being rendered, by frame number. */
    private final Map<Integer, Integer> running = new ConcurrentSkipListMap<>();
    private int finished;

    private AnimationProgress(Mode mode, Progress bar, PrintWriter err, int total) {
        this.mode = mode;
        this.bar = bar;
        this.err = err;
        this.total = total;
    }

    static AnimationProgress start(int total, boolean quiet, PrintWriter err) {
        if (quiet || total == 0) return new AnimationProgress(Mode.NONE, Progress.NONE, err, total);
        if (Progress.stderrIsTerminal()) {
            return new AnimationProgress(Mode.BAR, Progress.start("Frames", total, "frames", false), err, total);
        }
        return new AnimationProgress(Mode.LINES, Progress.NONE, err, total);
    }

    @Override
    public void started(int frame) {
        running.put(frame, 0);
        showRunning();
    }

    /** Called from render threads, often: the bar's text changes only when a percentage does. */
    @Override
    public void rendering(int frame, long done, long of) {
        int percent = of == 0 ? 0 : (int) (100 * done / of);
        Integer before = running.put(frame, percent);
        if (before == null || before != percent) showRunning();
    }

    /** Frame {@code frame} is over: written, or failed when {@code written} is false. */
    @Override
    public synchronized void finished(int frame, boolean written) {
        running.remove(frame);
        finished++;
        if (mode == Mode.BAR) {
            bar.update(finished, total);
            showRunning();
        } else if (mode == Mode.LINES && written) {
            long elapsed = System.nanoTime() - start;
            long left = finished == total ? 0 : elapsed / finished * (total - finished);
            synchronized (err) {
                err.printf(Locale.ROOT, "crt: frame %d written (%d of %d, %s elapsed, about %s left)%n",
                        frame, finished, total, duration(elapsed), duration(left));
                err.flush();
            }
        }
    }

    private void showRunning() {
        if (mode != Mode.BAR) return;
        StringBuilder text = new StringBuilder();
        running.forEach((frame, percent) -> text.append(text.length() == 0 ? "" : ", ").append("t=").append(frame)
                .append(' ').append(percent).append('%'));
        bar.message(text.toString());
    }

    /** A duration as people read it: "4.2 s", "3 min 05 s", "2 h 07 min". */
    static String duration(long nanos) {
        if (nanos < 59_950_000_000L) return String.format(Locale.ROOT, "%.1f s", nanos / 1e9);
        long s = Math.round(nanos / 1e9);
        if (s < 3600) return String.format(Locale.ROOT, "%d min %02d s", s / 60, s % 60);
        return String.format(Locale.ROOT, "%d h %02d min", s / 3600, s / 60 % 60);
    }

    @Override
    public void close() { bar.close(); }
}
