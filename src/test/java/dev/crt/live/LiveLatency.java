package dev.crt.live;

import static org.lwjgl.opengl.GL11.glFinish;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.scene.Scene;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * Where the live view's compile-to-frame time goes, phase by phase, headless: compile, convert,
 * upload, draw, read back, copy into the panel's image; each phase closed by glFinish so the GPU's
 * share is counted where it is spent. Medians of 15 runs after 5 warm-up runs. Run with
 * bench/live-latency.sh SCENE... (each scene at 800×600 through its own camera).
 */
public final class LiveLatency {
    private LiveLatency() {}

    public static void main(String[] args) throws Exception {
        int w = 800, h = 600;
        try (Preview p = Preview.open()) {
            System.out.println(p.description() + ", " + w + "x" + h + ", medians of 15 runs after 5 warm-ups");
            LiveRenderer r = p.renderer();
            for (String a : args) {
                Path file = Path.of(a);
                String text = Files.readString(file);
                CompileOptions options = new CompileOptions(0, List.of(Path.of("assets")), CompileOptions.DEFAULT_LOOP_BUDGET,
                        CompileOptions.DEFAULT_TIME_BUDGET, true);
                String[] names = {"compile", "convert", "upload", "draw", "read back", "into image", "coarse draw and read back"};
                long[][] t = new long[names.length][15];
                long[] drawCpu = new long[15];
                for (int run = -5; run < 15; run++) {
                    long t0 = System.nanoTime();
                    CompileResult c = CrtCompiler.compile(new Source(file.toString(), text, file), options);
                    Scene scene = c.scene();
                    long t1 = System.nanoTime();
                    GpuScene g = SceneConverter.convert(scene);
                    long t2 = System.nanoTime();
                    r.setScene(g);
                    glFinish();
                    long t3 = System.nanoTime();
                    long cpu = cpu();
                    r.resize(w, h);
                    r.clear();
                    r.draw(ViewCamera.of(scene.settings().camera()), 0, 0, w, h, LiveRenderer.Overlay.NONE);
                    glFinish();
                    long t4 = System.nanoTime();
                    if (run >= 0) drawCpu[run] = cpu() - cpu;
                    int[] colour = r.readColour();
                    long t5 = System.nanoTime();
                    BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
                    System.arraycopy(colour, 0, ((DataBufferInt) image.getRaster().getDataBuffer()).getData(), 0, w * h);
                    long t6 = System.nanoTime();
                    // The view's first frame of a new scene: half the width and height, read back into its image.
                    r.clear();
                    r.draw(ViewCamera.of(scene.settings().camera()), 0, 0, w / 2, h / 2, LiveRenderer.Overlay.NONE);
                    BufferedImage coarse = new BufferedImage(w / 2, h / 2, BufferedImage.TYPE_INT_RGB);
                    r.readColour(w / 2, h / 2, ((DataBufferInt) coarse.getRaster().getDataBuffer()).getData());
                    long t7 = System.nanoTime();
                    if (run < 0) continue;
                    long[] at = {t0, t1, t2, t3, t4, t5, t6, t7};
                    for (int k = 0; k < names.length; k++) t[k][run] = at[k + 1] - at[k];
                }
                StringBuilder line = new StringBuilder(file.getFileName().toString()).append(":");
                double total = 0;
                for (int k = 0; k < names.length; k++) {
                    double ms = median(t[k]) / 1e6;
                    if (k > 0 && k < 6) total += ms;
                    line.append(String.format(Locale.ROOT, " %s %.1f ms,", names[k], ms));
                }
                line.append(String.format(Locale.ROOT, " convert to image %.1f ms; draw CPU (all threads) %.1f ms", total,
                        median(drawCpu) / 1e6));
                System.out.println(line);
            }
        }
    }

    private static long cpu() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    private static double median(long[] v) {
        long[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }
}
