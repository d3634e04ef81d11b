package dev.crt.lang.eval;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.scene.Sphere;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** rand's generator draws java.util.Random's numbers: scripts keep the pictures they had. */
class ScriptRandomTest {
    @Test
    void drawsTheNumbersOfJavaUtilRandomForTheSameSeed() {
        for (long seed : new long[] {2015, 0, -1, 1L << 47, Long.MAX_VALUE, Long.MIN_VALUE, 0x5DEECE66DL}) {
            Random expected = new Random(seed);
            ScriptRandom r = new ScriptRandom(seed);
            for (int i = 0; i < 200_000; i++) {
                double want = expected.nextDouble();
                double got = r.nextDouble();
                if (Double.doubleToRawLongBits(got) != Double.doubleToRawLongBits(want)) {
                    throw new AssertionError("seed " + seed + ", draw " + i + ": " + got + " instead of " + want);
                }
            }
        }
    }

    @Test
    void aScriptsRandomSpheresSitWhereJavaUtilRandomOfSeed2015PutsThem() {
        String script = "Scene {\n  i = 0\n  while (i < 50) {\n"
                + "    Sphere { center -> vec3(rand(-10, 10), rand(-10, 10), rand(-10, 10)) radius -> rand(0.1, 0.5) }\n"
                + "    i = i + 1\n  }\n}\n";
        var result = CrtCompiler.compile(Source.of("r.crt", script), CompileOptions.DEFAULT);
        List<?> entities = result.scene().entities();
        assertThat(entities).hasSize(50);
        Random random = new Random(2015);
        for (Object e : entities) {
            Sphere s = (Sphere) e;
            double x = -10 + random.nextDouble() * 20, y = -10 + random.nextDouble() * 20, z = -10 + random.nextDouble() * 20;
            double r = 0.1 + random.nextDouble() * (0.5 - 0.1);
            assertThat(s.center().x()).isEqualTo(x);
            assertThat(s.center().y()).isEqualTo(y);
            assertThat(s.center().z()).isEqualTo(z);
            assertThat(s.radius()).isEqualTo(r);
        }
    }
}
