package dev.crt.lang;

/**
 * Prints what recording a source map costs a compile: the scripts of {@link CompileSpeed}, each
 * compiled without and with the map in turn (interleaved, so that the machine's load hits both
 * alike), best of 30 after 10 warm-up rounds, the order alternating.
 * Run: {@code mvn -q -o test-compile dependency:build-classpath -Dmdep.outputFile=target/cp.txt}, then
 * {@code java -cp "target/classes:target/test-classes:$(cat target/cp.txt)" dev.crt.lang.SourceMapSpeed}.
 */
public final class SourceMapSpeed {
    private SourceMapSpeed() {}

    private static double millis(String script, CompileOptions options) {
        long start = System.nanoTime();
        CompileResult r = CrtCompiler.compile(Source.of("speed.crt", script), options);
        if (r.hasErrors()) throw new IllegalStateException(r.diagnostics().toString());
        return (System.nanoTime() - start) / 1e6;
    }

    public static void main(String[] args) {
        String[][] scripts = {{"2,500-line script", CompileSpeed.originalStyle(500)},
                {"100,000 objects by a macro", CompileSpeed.hundredThousandObjects()}};
        CompileOptions plain = CompileOptions.DEFAULT, mapped = CompileOptions.DEFAULT.withSourceMap();
        for (String[] s : scripts) {
            double without = Double.MAX_VALUE, with = Double.MAX_VALUE;
            for (int i = 0; i < 40; i++) {
                // Alternate which goes first, so that neither always runs right after the other's garbage.
                double a, b;
                if (i % 2 == 0) {
                    a = millis(s[1], plain);
                    b = millis(s[1], mapped);
                } else {
                    b = millis(s[1], mapped);
                    a = millis(s[1], plain);
                }
                if (i >= 10) {
                    without = Math.min(without, a);
                    with = Math.min(with, b);
                }
            }
            System.out.printf("%s: %.1f ms without the source map, %.1f ms with it (×%.2f)%n", s[0], without, with, with / without);
        }
    }
}
