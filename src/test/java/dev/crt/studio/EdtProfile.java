package dev.crt.studio;

import java.awt.AWTEvent;
import java.awt.EventQueue;
import java.awt.Toolkit;
import java.awt.event.InvocationEvent;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The Event Dispatch Thread's own CPU time per kind of event while it is on: what the studio makes
 * the EDT do, apart from the time it waits for a core, the X server or the garbage collector (which
 * a loaded machine stretches and the watchdog counts as stalls). For StudioBench.
 */
final class EdtProfile extends EventQueue {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    private final Map<String, long[]> byKind = new HashMap<>();
    private final List<String> longest = new ArrayList<>();
    private volatile boolean on;

    /** Puts a profile in front of the system event queue. */
    static EdtProfile install() {
        EdtProfile p = new EdtProfile();
        Toolkit.getDefaultToolkit().getSystemEventQueue().push(p);
        if (Boolean.getBoolean("crt.bench.repaints")) {
            try {
                EventQueue.invokeAndWait(p::installRepaintCounter);
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }
        return p;
    }

    /** Counts the repaints and revalidations asked for while the profile is on, by component and the code that asked. */
    private final Map<String, long[]> repaints = new HashMap<>();

    private void installRepaintCounter() {
        java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().addPropertyChangeListener("focusOwner", e -> {
            if (on) System.out.println("focus owner " + name(e.getOldValue()) + " -> " + name(e.getNewValue()) + " at "
                    + ManagementFactory.getRuntimeMXBean().getUptime() / 1000.0);
        });
        javax.swing.RepaintManager.setCurrentManager(new javax.swing.RepaintManager() {
            @Override
            public void addInvalidComponent(javax.swing.JComponent c) {
                if (on) {
                    java.awt.Container root = c;
                    while (root != null && !root.isValidateRoot()) root = root.getParent();
                    count("revalidate " + c.getClass().getSimpleName() + " up to " + (root == null ? null : root.getClass().getSimpleName()) + " from " + asker());
                }
                super.addInvalidComponent(c);
            }

            @Override
            public void addDirtyRegion(javax.swing.JComponent c, int x, int y, int w, int h) {
                if (on && w > 0 && h > 0) count(c.getClass().getSimpleName() + " " + w + "x" + h + " from " + asker());
                super.addDirtyRegion(c, x, y, w, h);
            }
        });
    }

    private void count(String what) {
        synchronized (repaints) {
            repaints.computeIfAbsent(what, k -> new long[1])[0]++;
        }
    }

    /** The first caller outside the JDK and this class. */
    private static String asker() {
        for (StackTraceElement f : new Throwable().getStackTrace()) {
            String cl = f.getClassName();
            if (cl.startsWith("java.") || cl.startsWith("javax.") || cl.startsWith("sun.") || cl.startsWith("dev.crt.studio.EdtProfile")) continue;
            return cl + "." + f.getMethodName() + ":" + f.getLineNumber();
        }
        return "?";
    }

    private static String name(Object c) {
        if (!(c instanceof java.awt.Component comp)) return String.valueOf(c);
        return comp.getClass().getSimpleName() + "(" + comp.getName() + ", " + (comp.getAccessibleContext() == null ? "" : comp.getAccessibleContext().getAccessibleName()) + ")";
    }

    /** Starts counting (called on any thread; the EDT picks it up at its next event). */
    void start() {
        on = true;
    }

    @Override
    protected void dispatchEvent(AWTEvent event) {
        if (!on) {
            super.dispatchEvent(event);
            return;
        }
        long cpu = THREADS.getCurrentThreadCpuTime();
        long wall = System.nanoTime();
        super.dispatchEvent(event);
        cpu = THREADS.getCurrentThreadCpuTime() - cpu;
        wall = System.nanoTime() - wall;
        String kind = kind(event);
        long[] s = byKind.computeIfAbsent(kind, k -> new long[4]);
        s[0]++;
        s[1] += cpu;
        s[2] = Math.max(s[2], cpu);
        s[3] = Math.max(s[3], wall);
        if (cpu > 10_000_000L || wall > 30_000_000L) {
            longest.add(String.format("  %5.1f ms CPU, %5.1f ms wall at %.3f s of uptime: %s", cpu / 1e6, wall / 1e6,
                    ManagementFactory.getRuntimeMXBean().getUptime() / 1000.0, kind));
        }
    }

    private static String kind(AWTEvent event) {
        String name = event.getClass().getName();
        if (event instanceof InvocationEvent) {
            String p = event.paramString();
            int r = p.indexOf("runnable=");
            if (r >= 0) {
                String what = p.substring(r + 9);
                int end = what.indexOf(',');
                if (end >= 0) what = what.substring(0, end);
                what = what.replaceAll("/0x[0-9a-f]+", "").replaceAll("@[0-9a-f]+$", "");
                if (what.startsWith("javax.swing.Timer$DoPostEvent")) what += timerListeners(event);
                return "invocation " + what;
            }
        }
        return name + " " + event.getID();
    }

    /**
     * Whose timer fired: the classes of its listeners, when the JVM lets the profile look into the
     * event ({@code --add-opens java.desktop/java.awt.event=ALL-UNNAMED --add-opens java.desktop/javax.swing=ALL-UNNAMED}).
     */
    private static String timerListeners(AWTEvent event) {
        try {
            java.lang.reflect.Field runnable = InvocationEvent.class.getDeclaredField("runnable");
            runnable.setAccessible(true);
            Object post = runnable.get(event);
            java.lang.reflect.Field outer = post.getClass().getDeclaredField("this$0");
            outer.setAccessible(true);
            javax.swing.Timer timer = (javax.swing.Timer) outer.get(post);
            StringBuilder b = new StringBuilder(" [");
            for (java.awt.event.ActionListener l : timer.getActionListeners()) {
                b.append(l.getClass().getName().replaceAll("/0x[0-9a-f]+", "").replaceAll("\\$\\$Lambda.*", "\\$\\$Lambda")).append(' ');
            }
            return b.append(']').toString();
        } catch (ReflectiveOperationException | RuntimeException e) {
            return "";
        }
    }

    /** Stops counting and prints the totals per kind (the largest first) and every long event, on the EDT. */
    void stopAndPrint(String what) throws Exception {
        EventQueue.invokeAndWait(() -> {
            on = false;
            long total = 0;
            for (long[] s : byKind.values()) total += s[1];
            System.out.printf("EDT CPU during %s: %.1f ms in all%n", what, total / 1e6);
            byKind.entrySet().stream().sorted((a, b) -> Long.compare(b.getValue()[1], a.getValue()[1])).limit(12)
                    .forEach(e -> System.out.printf("  %7.1f ms in %4d events (longest %5.1f ms CPU, %5.1f ms wall): %s%n",
                            e.getValue()[1] / 1e6, e.getValue()[0], e.getValue()[2] / 1e6, e.getValue()[3] / 1e6, e.getKey()));
            System.out.println("events over 10 ms of CPU or 30 ms of wall time:");
            longest.forEach(System.out::println);
            synchronized (repaints) {
                if (!repaints.isEmpty()) System.out.println("repaints and revalidations asked for:");
                repaints.entrySet().stream().sorted((a, b) -> Long.compare(b.getValue()[0], a.getValue()[0]))
                        .forEach(e -> System.out.printf("  %4d × %s%n", e.getValue()[0], e.getKey()));
                repaints.clear();
            }
            byKind.clear();
            longest.clear();
        });
    }
}
