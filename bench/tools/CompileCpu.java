import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.ScriptFiles;
import dev.crt.lang.Source;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;

/**
 * Reads and compiles one script once in a fresh JVM, as `crt render` does for its "compile" phase,
 * and prints the wall time and the process's CPU time (compiling thread, JIT compilers and
 * collector) in milliseconds. To start it from a build's AOT cache, compile it first and put it
 * after the jar on the class path:
 * javac -cp target/crt.jar -d /tmp/cpu bench/tools/CompileCpu.java
 * java -XX:AOTCache=target/crt-25.0.3.aot --enable-native-access=ALL-UNNAMED --sun-misc-unsafe-memory-access=allow \
 *      -Xss16m -cp target/crt.jar:/tmp/cpu CompileCpu SCRIPT.crt
 */
public class CompileCpu {
    public static void main(String[] args) throws Exception {
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        long cpu = os.getProcessCpuTime(), wall = System.nanoTime();
        Source source = ScriptFiles.read(Path.of(args[0]));
        CompileResult result = CrtCompiler.compile(source, CompileOptions.DEFAULT);
        long wallNanos = System.nanoTime() - wall, cpuNanos = os.getProcessCpuTime() - cpu;
        System.out.printf("%.1f %.1f%n", wallNanos / 1e6, cpuNanos / 1e6);
        if (result.scene() == null) System.out.println("errors: " + result.diagnostics());
    }
}
