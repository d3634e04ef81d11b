import dev.crt.lang.CompileOptions;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.render.RenderMonitor;
import dev.crt.render.Renderer;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * CPU seconds of one JVM for the phases of a scene: compile, prepare (BVH builds included) and
 * RENDERS renders on one thread, with their median. Run against a jar, alternating jars to compare
 * two builds side by side on a loaded machine:
 *
 * <pre>java -cp target/crt.jar bench/tools/RenderCpu.java SCENE WIDTH HEIGHT RENDERS</pre>
 */
public final class RenderCpu {
    public static void main(String[] args) throws Exception {
        if (args.length != 4) {
            System.err.println("usage: java -cp crt.jar bench/tools/RenderCpu.java SCENE WIDTH HEIGHT RENDERS");
            System.exit(2);
        }
        Path scene = Path.of(args[0]).toAbsolutePath();
        int width = Integer.parseInt(args[1]), height = Integer.parseInt(args[2]), renders = Integer.parseInt(args[3]);
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        long c0 = os.getProcessCpuTime();
        var result = CrtCompiler.compile(new Source(scene.toString(), Files.readString(scene), scene), CompileOptions.DEFAULT);
        if (result.hasErrors()) {
            result.diagnostics().forEach(System.err::println);
            System.exit(1);
        }
        long c1 = os.getProcessCpuTime();
        Renderer renderer = Renderer.prepare(result.scene()).withImage(width, height, 1, 1);
        long c2 = os.getProcessCpuTime();
        double[] seconds = new double[renders];
        StringBuilder each = new StringBuilder();
        for (int i = 0; i < renders; i++) {
            long start = os.getProcessCpuTime();
            renderer.render(1, RenderMonitor.NONE);
            seconds[i] = (os.getProcessCpuTime() - start) / 1e9;
            each.append(String.format(" %.3f", seconds[i]));
        }
        Arrays.sort(seconds);
        System.out.printf("compile %.3f prepare %.3f renders%s median %.3f%n", (c1 - c0) / 1e9, (c2 - c1) / 1e9, each,
                seconds[renders / 2]);
    }
}
