package dev.crt.studio;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;

/** Starts the studio: the entry point {@code crt studio} calls. */
public final class Studio {
    private Studio() {}

    /** Why the studio cannot open a window here, or null when it can. */
    public static String whyNoDisplay() {
        if (GraphicsEnvironment.isHeadless()) {
            String display = System.getenv("DISPLAY");
            return display == null || display.isBlank()
                    ? "the studio needs a graphical display, and none is available (DISPLAY is not set)"
                    : "the studio needs a graphical display, and Java runs headless here";
        }
        return null;
    }

    /**
     * Opens the studio with {@code files} and waits until it is closed; returns the exit code.
     * @throws NoDisplayException when no window can be opened
     */
    public static int run(List<Path> files, StudioPaths paths) throws NoDisplayException {
        String why = whyNoDisplay();
        if (why != null) throw new NoDisplayException(why);
        CountDownLatch closed = new CountDownLatch(1);
        AtomicInteger code = new AtomicInteger();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        long start = System.nanoTime();
        try {
            SwingUtilities.invokeAndWait(() -> {
                StudioWindow window = new StudioWindow(paths);
                window.onExit(c -> {
                    code.set(c);
                    closed.countDown();
                });
                if (Boolean.getBoolean("crt.studio.train")) {
                    window.train(files);
                    return;
                }
                window.onFirstPaint(() -> ready(window, start));
                window.show(files);
            });
        } catch (InvocationTargetException e) {
            failure.set(e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        } catch (AWTError e) {
            throw new NoDisplayException("the studio cannot open a window: " + e.getMessage());
        }
        Throwable f = failure.get();
        if (f instanceof AWTError || f instanceof java.awt.HeadlessException) {
            throw new NoDisplayException("the studio cannot open a window: " + f.getMessage());
        }
        if (f instanceof RuntimeException r) throw r;
        if (f instanceof Error err) throw err;
        try {
            closed.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        }
        return code.get();
    }

    /**
     * The window is painted and takes keys: says how long that took. With the system property
     * {@code crt.studio.quitWhenReady} (start-up benchmarks: bench/studio-bench.sh)
     * the line goes to standard output and the studio quits.
     */
    private static void ready(StudioWindow window, long start) {
        long ms = (System.nanoTime() - start) / 1_000_000;
        long cpu = -1;
        if (java.lang.management.ManagementFactory.getOperatingSystemMXBean()
                instanceof com.sun.management.OperatingSystemMXBean os) cpu = os.getProcessCpuTime() / 1_000_000;
        String line = "studio ready in " + ms + " ms (" + uptime() + " ms since the JVM started"
                + (cpu >= 0 ? ", " + cpu + " ms of CPU" : "") + ")";
        window.console().log(ConsolePanel.Kind.INFO, line);
        if (Boolean.getBoolean("crt.studio.quitWhenReady")) {
            System.out.println(line);
            System.out.flush();
            System.exit(0);
        }
    }

    private static long uptime() {
        return java.lang.management.ManagementFactory.getRuntimeMXBean().getUptime();
    }

    /** No window can be opened: no display, or Java runs headless. */
    public static final class NoDisplayException extends Exception {
        public NoDisplayException(String message) {
            super(message);
        }
    }
}
