package dev.crt.lang;

/**
 * Prints how long compiles take: 100,000 objects placed by a macro and loops (first compile after
 * JVM start), and a 2,500-line script in the original CRT's style (warm, best of 20).
 * Run: {@code mvn -q -o test-compile dependency:build-classpath -Dmdep.outputFile=target/cp.txt}, then
 * {@code java -cp "target/classes:target/test-classes:$(cat target/cp.txt)" dev.crt.lang.CompileSpeed}.
 */
public final class CompileSpeed {
    private CompileSpeed() {}

    static String hundredThousandObjects() {
        return Scripts.CAMERA + """
                ball = Sphere { radius -> 0.1 material -> Material { color -> rgb(1, 0.5, 0) } }
                grid = Macro (n) {
                  i = 0
                  while (i < n) {
                    j = 0
                    while (j < n) { ball <translate vec3(i * 0.25, j * 0.25, 0)> j = j + 1 }
                    i = i + 1
                  }
                }
                Scene { grid(317) }
                """;
    }

    static String originalStyle(int boxes) {
        StringBuilder s = new StringBuilder(Scripts.CAMERA).append("red = Material { color -> rgb(162./255, 0.1, 0.1) }\n");
        for (int i = 0; i < boxes; i++) {
            s.append("b").append(i).append(" = Box {\n  cornerA -> vec3(").append(i).append(".0, 0.0, 0.0)\n  cornerB -> vec3(")
                    .append(i).append(".5, 1.0, 1.0)\n  material -> red\n}\n");
        }
        s.append("Scene {\n");
        for (int i = 0; i < boxes; i++) s.append(" b").append(i).append(i % 20 == 19 ? "\n" : "");
        return s.append("\n}\n").toString();
    }

    private static double millis(String script) {
        long start = System.nanoTime();
        CompileResult r = CrtCompiler.compile(Source.of("speed.crt", script), CompileOptions.DEFAULT);
        double ms = (System.nanoTime() - start) / 1e6;
        if (r.hasErrors()) throw new IllegalStateException(r.diagnostics().toString());
        return ms;
    }

    public static void main(String[] args) {
        String many = hundredThousandObjects();
        System.out.printf("100,000 objects via macro and loops, first compile after JVM start: %.0f ms%n", millis(many));
        String original = originalStyle(500);
        System.out.printf("original-style script of %d lines, first compile: %.0f ms%n", original.lines().count(), millis(original));
        double best = Double.MAX_VALUE;
        for (int i = 0; i < 20; i++) best = Math.min(best, millis(original));
        System.out.printf("original-style script of %d lines, warm (best of 20): %.1f ms%n", original.lines().count(), best);
        best = Double.MAX_VALUE;
        for (int i = 0; i < 5; i++) best = Math.min(best, millis(many));
        System.out.printf("100,000 objects, warm (best of 5): %.0f ms%n", best);
    }
}
