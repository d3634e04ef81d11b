import java.lang.management.ManagementFactory;
import java.lang.reflect.Field;
import java.lang.management.ThreadMXBean;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * What each switchable feature (-Dcrt.without, dev.crt.render.Features) costs a scene that does not
 * use it: one CRT jar loaded once per setting, each in a class loader of its own whose Features read
 * the property while it was set to that setting ({@link #CONTROLS} copies with every feature
 * present; every one off; each one off alone), all in one JVM. Rounds render the scene once per
 * setting on one thread, in an order rotated each round, after warm-up rounds (until every setting
 * has rendered for {@link #WARMUP_SECONDS}); the render thread's CPU time per render (read by a
 * monitor at every finished tile: the thread is new for each render, so its clock starts at 0; the
 * JIT's and GC's threads are not counted). A feature's cost is the ratio of "all present" (the
 * copies' renders nearest in time) to "that one off", median over rounds, so that the load of a
 * shared machine, which drifts, cancels. A setting whose feature the scene uses is
 * refused by the renderer and reported as such. Run:
 * java [-Dcrt.assets=DIR] bench/FeatureCost.java JAR SCENE.crt WIDTH HEIGHT ROUNDS [CSV|-] [ONLY,THESE,SETTINGS]
 */
public class FeatureCost {
    /** Every setting renders at least this much CPU time before the rounds count, so that C2 has compiled each copy of the code. */
    private static final double WARMUP_SECONDS = 3;
    /**
     * Copies of the jar with every feature present, spread through each round: a render's reference
     * is the mean of the copies' renders nearest before and after it, and the copies' own ratios
     * show what the method cannot tell apart (each copy is compiled by the JIT on its own).
     */
    private static final int CONTROLS = 4;
    private static final ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    /** The render thread's CPU time (ns) at its last finished tile. */
    private static volatile long renderCpu;

    public static void main(String[] a) throws Exception {
        Path jar = Path.of(a[0]);
        String text = Files.readString(Path.of(a[1]));
        int w = Integer.parseInt(a[2]), h = Integer.parseInt(a[3]), rounds = Integer.parseInt(a[4]);
        Path csv = a.length > 5 && !a[5].equals("-") ? Path.of(a[5]) : null;
        List<String> only = a.length > 6 ? List.of(a[6].split(",")) : null;

        Map<String, String> names = featureNames(jar);
        List<String> settings = new ArrayList<>();
        List<String> off = new ArrayList<>(names.keySet());
        off.add(0, "all");
        if (only != null) off.retainAll(only);
        // The copies with every feature present spread evenly through the order of a round.
        int group = (off.size() + CONTROLS - 1) / CONTROLS;
        for (int c = 0; c < CONTROLS; c++) {
            settings.add("");
            settings.addAll(off.subList(Math.min(off.size(), c * group), Math.min(off.size(), (c + 1) * group)));
        }

        List<String> used = new ArrayList<>();
        List<String> run = new ArrayList<>();
        List<Object> renderers = new ArrayList<>();
        List<Method> render = new ArrayList<>(), stats = new ArrayList<>();
        List<Object> monitors = new ArrayList<>();
        for (String without : settings) {
            ClassLoader cl = new URLClassLoader(new URL[] {jar.toUri().toURL()}, null);
            System.setProperty("crt.without", without);
            Class.forName("dev.crt.render.Features", true, cl);
            System.clearProperty("crt.without");
            Object scene = scene(cl, text, w, h);
            Class<?> sceneC = cl.loadClass("dev.crt.scene.Scene");
            Class<?> rc = cl.loadClass("dev.crt.render.Renderer"), mon = cl.loadClass("dev.crt.render.RenderMonitor");
            Object renderer;
            try {
                renderer = rc.getMethod("prepare", sceneC).invoke(null, scene);
            } catch (java.lang.reflect.InvocationTargetException e) {
                if (!e.getCause().getClass().getSimpleName().equals("FeatureSwitchedOffException")) throw e;
                used.add(without);
                System.out.println("the scene uses " + without + ": " + e.getCause().getMessage());
                continue;
            }
            run.add(without);
            renderers.add(renderer);
            render.add(rc.getMethod("render", int.class, mon));
            stats.add(rc.getMethod("stats"));
            monitors.add(Proxy.newProxyInstance(cl, new Class<?>[] {mon}, (proxy, method, args) -> {
                if (method.getName().equals("tileDone")) renderCpu = threads.getCurrentThreadCpuTime();
                return method.getReturnType() == boolean.class ? Boolean.FALSE : null;
            }));
        }

        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        double loadBefore = os.getSystemLoadAverage();
        int n = run.size();
        double[][] cpu = new double[n][rounds];
        // The renders in the order they ran: setting, round.
        int[] ranK = new int[n * rounds], ranR = new int[n * rounds];
        int ran = 0;
        long[] rays = new long[n];
        double[] warm = new double[n];
        int warmup = 0;
        for (; min(warm) < WARMUP_SECONDS; warmup++) {
            for (int k = 0; k < n; k++) {
                render.get(k).invoke(renderers.get(k), 1, monitors.get(k));
                warm[k] += renderCpu / 1e9;
            }
        }
        for (int r = 0; r < rounds; r++) {
            for (int i = 0; i < n; i++) {
                int k = Math.floorMod(i + r, n);
                if ((r & 1) != 0) k = n - 1 - k;
                render.get(k).invoke(renderers.get(k), 1, monitors.get(k));
                double c = renderCpu / 1e9;
                cpu[k][r] = c;
                ranK[ran] = k;
                ranR[ran++] = r;
                Object st = stats.get(k).invoke(renderers.get(k));
                rays[k] = (long) st.getClass().getMethod("totalRays").invoke(st);
            }
        }
        double loadAfter = os.getSystemLoadAverage();

        // Each render's reference: the mean of the all-present renders nearest before and after it.
        double[][] reference = new double[n][rounds];
        double referenceMin = Double.POSITIVE_INFINITY;
        for (int i = 0; i < ran; i++) {
            int k = ranK[i], r = ranR[i];
            if (run.get(k).isEmpty()) referenceMin = Math.min(referenceMin, cpu[k][r]);
            double sum = 0;
            int count = 0;
            for (int step : new int[] {-1, 1}) {
                for (int j = i + step; j >= 0 && j < ran; j += step) {
                    if (run.get(ranK[j]).isEmpty()) {
                        sum += cpu[ranK[j]][ranR[j]];
                        count++;
                        break;
                    }
                }
            }
            reference[k][r] = sum / count;
        }
        StringBuilder out = new StringBuilder();
        out.append(String.format(Locale.ROOT, "%s, %d×%d, %d rounds after %d warm-up rounds, one thread, render thread CPU time; load average %.2f before, %.2f after%n",
                a[1], w, h, rounds, warmup, loadBefore, loadAfter));
        out.append("on/off: the time with every feature present (the mean of the renders of the " + CONTROLS
                + " copies marked (none) nearest before and after) over the time of the row's render; median over rounds and its 95 % interval;"
                + " min ratio: the fastest render of those copies over the row's fastest\n");
        out.append(String.format(Locale.ROOT, "%-12s %9s %8s %8s %11s %8s %15s %9s%n", "without", "median s", "ns/ray", "min s",
                "rays", "on/off", "95 % interval", "min ratio"));
        StringBuilder table = new StringBuilder("without,median_cpu_s,ns_per_ray,min_cpu_s,rays,on_over_off,ci_low,ci_high,min_ratio\n");
        for (int k = 0; k < n; k++) {
            double median = median(cpu[k]);
            double[] ratio = new double[rounds];
            for (int r = 0; r < rounds; r++) ratio[r] = reference[k][r] / cpu[k][r];
            double[] q = medianInterval(ratio);
            double minRatio = referenceMin / min(cpu[k]);
            String name = run.get(k).isEmpty() ? "(none)" : run.get(k);
            out.append(String.format(Locale.ROOT, "%-12s %9.4f %8.1f %8.4f %11d %8.4f %7.4f–%.4f %9.4f%n", name, median,
                    median * 1e9 / rays[k], min(cpu[k]), rays[k], q[1], q[0], q[2], minRatio));
            table.append(String.format(Locale.ROOT, "%s,%.5f,%.2f,%.5f,%d,%.4f,%.4f,%.4f,%.4f%n", name, median, median * 1e9 / rays[k],
                    min(cpu[k]), rays[k], q[1], q[0], q[2], minRatio));
            if (rays[k] != rays[0]) out.append("  (a different ray count from every feature present: the picture differs)\n");
        }
        for (String u : used) table.append(u).append(",used by the scene,,,,,\n");
        System.out.print(out);
        if (csv != null) {
            Files.createDirectories(csv.toAbsolutePath().getParent());
            Path tmp = csv.resolveSibling(csv.getFileName() + ".tmp");
            Files.writeString(tmp, table);
            Files.move(tmp, csv, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        }
    }

    /** Features.NAMES of the jar: the switches and what each leaves out. */
    @SuppressWarnings("unchecked")
    private static Map<String, String> featureNames(Path jar) throws Exception {
        ClassLoader cl = new URLClassLoader(new URL[] {jar.toUri().toURL()}, null);
        Field f = cl.loadClass("dev.crt.render.Features").getDeclaredField("NAMES");
        f.setAccessible(true);
        return new LinkedHashMap<>((Map<String, String>) f.get(null));
    }

    /** The scene of {@code text} compiled by the classes of {@code cl}, at width × height. */
    private static Object scene(ClassLoader cl, String text, int w, int h) throws Exception {
        Class<?> src = cl.loadClass("dev.crt.lang.Source"), opts = cl.loadClass("dev.crt.lang.CompileOptions");
        Object source = src.getMethod("of", String.class, String.class).invoke(null, "s", text);
        Object result = cl.loadClass("dev.crt.lang.CrtCompiler").getMethod("compile", src, opts)
                .invoke(null, source, opts.getField("DEFAULT").get(null));
        Object scene = result.getClass().getMethod("scene").invoke(result);
        if (scene == null) throw new IllegalArgumentException("the scene does not compile: " + result);
        Class<?> sceneC = cl.loadClass("dev.crt.scene.Scene"), settingsC = cl.loadClass("dev.crt.scene.Settings");
        Object settings = sceneC.getMethod("settings").invoke(scene);
        settings = settingsC.getMethod("withSize", int.class, int.class).invoke(settings, w, h);
        Object name = sceneC.getMethod("sourceName").invoke(scene), ents = sceneC.getMethod("entities").invoke(scene);
        return sceneC.getConstructor(String.class, settingsC, List.class).newInstance(name, settings, ents);
    }

    private static double median(double[] v) {
        return medianInterval(v)[1];
    }

    private static double min(double[] v) {
        double m = Double.POSITIVE_INFINITY;
        for (double x : v) m = Math.min(m, x);
        return m;
    }

    /**
     * The median of {@code v} between the order statistics that bound it with about 95 % confidence
     * whatever the distribution (ranks n/2 ∓ 0.98·√n, from the binomial distribution of the count below the median).
     */
    private static double[] medianInterval(double[] v) {
        List<Double> s = new ArrayList<>();
        for (double x : v) s.add(x);
        Collections.sort(s);
        int n = s.size();
        int lo = Math.max(0, (int) Math.floor(n / 2.0 - 0.98 * Math.sqrt(n))), hi = Math.min(n - 1, (int) Math.ceil(n / 2.0 + 0.98 * Math.sqrt(n)) - 1);
        return new double[] {s.get(lo), s.get(n / 2), s.get(hi)};
    }
}
