import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * The compiler of two CRT jars side by side in one JVM, alternating compiles of one script, CPU
 * time of the compile (all threads of the process, as the compile runs on a thread of its own).
 * "cold" loads each jar afresh for every compile (new class loader: no JIT-compiled code of the
 * compiler yet, like a fresh process); "warm" keeps one loader per jar and warms it up twice.
 * Then, for each jar, the heap the compiled scene holds (used heap after a full GC with the result
 * kept, minus before), per entity of the scene (a script with errors is timed, not weighed). Run:
 * java bench/CompileSideBySide.java BASE.jar NEW.jar SCRIPT.crt cold|warm ROUNDS [TIME]
 */
public class CompileSideBySide {
    public static void main(String[] a) throws Exception {
        String text = Files.readString(Path.of(a[2]));
        boolean cold = a[3].equals("cold");
        int rounds = Integer.parseInt(a[4]);
        double time = a.length > 5 ? Double.parseDouble(a[5]) : 0;
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        Compiler[] jars = {new Compiler(Path.of(a[0])), new Compiler(Path.of(a[1]))};
        List<List<Double>> cpu = List.of(new ArrayList<>(), new ArrayList<>());
        List<List<Double>> wall = List.of(new ArrayList<>(), new ArrayList<>());
        for (int r = cold ? 0 : -2; r < rounds; r++) {
            for (int k0 = 0; k0 < 2; k0++) {
                int k = (r & 1) == 0 ? k0 : 1 - k0;
                if (cold) jars[k].reload();
                System.gc();
                long c0 = os.getProcessCpuTime(), w0 = System.nanoTime();
                Object result = jars[k].compile(text, time);
                double c = (os.getProcessCpuTime() - c0) / 1e9, w = (System.nanoTime() - w0) / 1e9;
                if (r >= 0) {
                    cpu.get(k).add(c);
                    wall.get(k).add(w);
                }
            }
        }
        double mb = text.getBytes(java.nio.charset.StandardCharsets.UTF_8).length / 1e6;
        for (int k = 0; k < 2; k++) {
            Collections.sort(cpu.get(k));
            Collections.sort(wall.get(k));
            double c = cpu.get(k).get(rounds / 2), w = wall.get(k).get(rounds / 2);
            System.out.printf("%s: median CPU %.3f s (%.2f MB/s), wall %.3f s (%.2f MB/s); CPU %s%n",
                    k == 0 ? "base" : "new ", c, mb / c, w, mb / w, cpu.get(k));
        }
        System.out.printf("new/base CPU %.3f%n", cpu.get(1).get(rounds / 2) / cpu.get(0).get(rounds / 2));
        if (jars[1].entities(jars[1].compile(text, time)) < 0) {
            System.out.println("(the script has errors: both compiles end in diagnostics; no scene to weigh)");
            return;
        }
        for (int k = 0; k < 2; k++) {
            Runtime rt = Runtime.getRuntime();
            System.gc();
            System.gc();
            long before = rt.totalMemory() - rt.freeMemory();
            Object result = jars[k].compile(text, time);
            System.gc();
            System.gc();
            long after = rt.totalMemory() - rt.freeMemory();
            long n = jars[k].entities(result);
            System.out.printf("%s: %d entities, heap held by the result %.1f MB, %.0f bytes per entity%n",
                    k == 0 ? "base" : "new ", n, (after - before) / 1e6, (after - before) / (double) n);
            Reference.reachabilityFence(result);
        }
    }

    private static final class Reference {
        static void reachabilityFence(Object o) { java.lang.ref.Reference.reachabilityFence(o); }
    }

    /** One jar's compiler, called through reflection. */
    private static final class Compiler {
        private final Path jar;
        private Method of, compile, scene, entities;
        private java.lang.reflect.Constructor<?> options;

        Compiler(Path jar) throws Exception {
            this.jar = jar;
            reload();
        }

        void reload() throws Exception {
            ClassLoader cl = new URLClassLoader(new URL[] {jar.toUri().toURL()}, null);
            Class<?> src = cl.loadClass("dev.crt.lang.Source"), opts = cl.loadClass("dev.crt.lang.CompileOptions");
            of = src.getMethod("of", String.class, String.class);
            compile = cl.loadClass("dev.crt.lang.CrtCompiler").getMethod("compile", src, opts);
            options = opts.getConstructor(double.class, List.class, long.class, java.time.Duration.class);
            Class<?> result = cl.loadClass("dev.crt.lang.CompileResult");
            scene = result.getMethod("scene");
            entities = cl.loadClass("dev.crt.scene.Scene").getMethod("entities");
        }

        Object compile(String text, double time) throws Exception {
            // A long time budget: a loaded machine must not stop the compile being measured.
            Object o = options.newInstance(time, List.of(), 100_000_000L, java.time.Duration.ofSeconds(600));
            return compile.invoke(null, of.invoke(null, "script.crt", text), o);
        }

        long entities(Object result) throws Exception {
            Object s = scene.invoke(result);
            return s == null ? -1 : ((List<?>) entities.invoke(s)).size();
        }
    }
}
