import java.lang.management.ManagementFactory;
import java.lang.reflect.*;
import java.net.*;
import java.nio.file.*;
import java.util.*;

/**
 * Side by side: two CRT jars in one JVM (one class loader each), alternating renders of one scene
 * on one thread, process CPU time per render (less disturbed by other work on a shared machine
 * than wall time), after two warm-up rounds. Run:
 * java bench/SideBySide.java BASE.jar NEW.jar SCENE.crt WIDTH HEIGHT ROUNDS [SAMPLER]
 * SAMPLER (grid, jittered, sobol, adaptive) is given to each jar that knows samplers, as
 * {@code --sampler} would be: {@code grid} makes a build with samplers draw the same picture as a
 * build from before them (f05acbf) on a scene with a lens, where its default differs. Each build
 * renders as {@code crt render} does for a PNG file (see {@link #forPng}).
 *
 * <p>Prints each round as it ends (both builds' seconds and their ratio), then the ratio of the
 * medians and the median of the rounds' ratios. A render of drops.crt at 800 x 600 takes half a
 * minute to a minute and a half, and this machine's speed moves by up to half within minutes: the
 * two renders of one round run a minute apart, the medians of the run ten minutes apart, so the
 * rounds' own ratios are the steadier measure when the machine's speed moves.
 */
public class SideBySide {
    public static void main(String[] a) throws Exception {
        String text = Files.readString(Path.of(a[2]));
        int w = Integer.parseInt(a[3]), h = Integer.parseInt(a[4]), rounds = Integer.parseInt(a[5]);
        Object[] renderers = new Object[2];
        Method[] render = new Method[2];
        Object[] none = new Object[2];
        for (int k = 0; k < 2; k++) {
            ClassLoader cl = new URLClassLoader(new URL[] {Path.of(a[k]).toUri().toURL()}, null);
            Class<?> src = cl.loadClass("dev.crt.lang.Source"), opts = cl.loadClass("dev.crt.lang.CompileOptions");
            Object source = src.getMethod("of", String.class, String.class).invoke(null, "s", text);
            Object result = cl.loadClass("dev.crt.lang.CrtCompiler").getMethod("compile", src, opts)
                    .invoke(null, source, opts.getField("DEFAULT").get(null));
            Object scene = result.getClass().getMethod("scene").invoke(result);
            Class<?> sceneC = cl.loadClass("dev.crt.scene.Scene"), settingsC = cl.loadClass("dev.crt.scene.Settings");
            Object settings = sceneC.getMethod("settings").invoke(scene);
            settings = settingsC.getMethod("withSize", int.class, int.class).invoke(settings, w, h);
            if (a.length > 6) settings = withSampler(cl, settingsC, settings, a[6]);
            Object name = sceneC.getMethod("sourceName").invoke(scene), ents = sceneC.getMethod("entities").invoke(scene);
            scene = sceneC.getConstructor(String.class, settingsC, List.class).newInstance(name, settings, ents);
            Class<?> rc = cl.loadClass("dev.crt.render.Renderer"), mon = cl.loadClass("dev.crt.render.RenderMonitor");
            renderers[k] = forPng(rc, rc.getMethod("prepare", sceneC).invoke(null, scene));
            render[k] = rc.getMethod("render", int.class, mon);
            none[k] = mon.getField("NONE").get(null);
        }
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        List<List<Double>> cpu = List.of(new ArrayList<>(), new ArrayList<>());
        List<Double> ratios = new ArrayList<>();
        for (int r = -2; r < rounds; r++) {
            double[] round = new double[2];
            for (int k0 = 0; k0 < 2; k0++) {
                int k = (r & 1) == 0 ? k0 : 1 - k0;
                long c0 = os.getProcessCpuTime();
                render[k].invoke(renderers[k], 1, none[k]);
                round[k] = (os.getProcessCpuTime() - c0) / 1e9;
                if (r >= 0) cpu.get(k).add(round[k]);
            }
            if (r >= 0) {
                ratios.add(round[1] / round[0]);
                System.out.printf("round %d: base %.2f s, new %.2f s, new/base %.4f%n", r + 1, round[0], round[1], round[1] / round[0]);
            }
        }
        for (int k = 0; k < 2; k++) Collections.sort(cpu.get(k));
        Collections.sort(ratios);
        double m0 = cpu.get(0).get(rounds / 2), m1 = cpu.get(1).get(rounds / 2);
        System.out.printf("median of the rounds' ratios %.4f%n", ratios.get(rounds / 2));
        System.out.printf("base median CPU %.3f s, new median CPU %.3f s, new/base %.4f%n", m0, m1, m1 / m0);
        System.out.println("base " + cpu.get(0));
        System.out.println("new  " + cpu.get(1));
    }

    /**
     * The renderer as {@code crt render} uses it for a .png file: {@code forClampedOutput()} where the
     * build has it (pixels stop once they are white; the same PNG), else as prepared. The system
     * property {@code sidebyside.linear=true} keeps every build's plain renderer (as for .pfm).
     */
    private static Object forPng(Class<?> rc, Object renderer) throws Exception {
        if (Boolean.getBoolean("sidebyside.linear")) return renderer;
        try {
            return rc.getMethod("forClampedOutput").invoke(renderer);
        } catch (NoSuchMethodException e) {
            return renderer;
        }
    }

    /** The settings with the named sampler, or as they are when this build has no samplers. */
    private static Object withSampler(ClassLoader cl, Class<?> settingsC, Object settings, String name) throws Exception {
        Class<?> samplerC;
        try {
            samplerC = cl.loadClass("dev.crt.scene.Sampler");
        } catch (ClassNotFoundException e) {
            return settings;
        }
        Object kind = samplerC.getMethod("valueOf", String.class).invoke(null, name.toUpperCase(Locale.ROOT));
        double noise = (double) settingsC.getMethod("noise").invoke(settings);
        return settingsC.getMethod("withSampler", samplerC, double.class).invoke(settings, kind, noise);
    }
}
