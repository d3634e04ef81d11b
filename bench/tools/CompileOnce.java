import dev.crt.lang.CompileOptions;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

/**
 * Compiles one script once in a fresh JVM and prints the wall time and the outcome, with a time
 * budget of 600 s (so that a loaded machine does not stop it). Run with the jar to measure:
 * java -Xmx1g -cp target/crt.jar bench/tools/CompileOnce.java SCRIPT.crt
 */
public class CompileOnce {
    public static void main(String[] args) throws Exception {
        String text = Files.readString(Path.of(args[0]));
        long start = System.nanoTime();
        var result = CrtCompiler.compile(Source.of(args[0], text),
                new CompileOptions(0, List.of(), 100_000_000L, Duration.ofSeconds(600)));
        System.out.printf("%.1f s, %s%n", (System.nanoTime() - start) / 1e9, result.scene() != null
                ? result.scene().entities().size() + " entities" : result.diagnostics().get(0).message());
    }
}
