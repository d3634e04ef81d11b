import dev.crt.lang.CompileOptions;
import dev.crt.lang.TextPositions;
import dev.crt.lang.eval.Evaluator;
import dev.crt.lang.syntax.ParseClock;
import dev.crt.lang.syntax.ScriptParser;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

/**
 * Compiles one script once in a fresh JVM, as `crt render` does (no source map), and prints the
 * CPU time of the compiling thread for the parse and for the evaluation, the process's CPU time
 * (the JIT and the collector included) and the wall time. To start it from the launcher's AOT
 * cache, compile it first and put it after the jar on the class path:
 * javac -cp target/crt.jar -d /tmp/phases bench/tools/CompilePhases.java
 * java -XX:AOTCache=target/crt-25.0.3.aot --enable-native-access=ALL-UNNAMED --sun-misc-unsafe-memory-access=allow \
 *      -Xss16m -cp target/crt.jar:/tmp/phases CompilePhases SCRIPT.crt
 */
public class CompilePhases {
    public static void main(String[] args) throws Exception {
        String text = Files.readString(Path.of(args[0]));
        var threads = ManagementFactory.getThreadMXBean();
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        long process = os.getProcessCpuTime(), wall = System.nanoTime(), t0 = threads.getCurrentThreadCpuTime();
        TextPositions positions = new TextPositions(args[0], text);
        ScriptParser.Parsed parsed = ScriptParser.parse(positions, new ParseClock(System.nanoTime(), Duration.ofSeconds(600)), true);
        long t1 = threads.getCurrentThreadCpuTime();
        if (parsed.statements() == null) {
            System.out.println("syntax errors: " + parsed.errors());
            return;
        }
        Evaluator evaluator = new Evaluator(positions, CompileOptions.DEFAULT, null, System.nanoTime());
        var scene = evaluator.run(parsed.statements(), parsed.assignedNames(), args[0]);
        long t2 = threads.getCurrentThreadCpuTime();
        System.out.printf("parse %.0f ms, evaluation %.0f ms (thread CPU); process CPU %.0f ms, wall %.0f ms; %s%n",
                (t1 - t0) / 1e6, (t2 - t1) / 1e6, (os.getProcessCpuTime() - process) / 1e6, (System.nanoTime() - wall) / 1e6,
                scene != null ? scene.entities().size() + " entities" : "errors: " + evaluator.diagnostics());
    }
}
