package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code crt accuracy}: the study's CSV, charts, reference cache and usage errors. */
class AccuracyCommandTest {
    @TempDir
    Path dir;

    private String previousCache;

    /** A ball with a hard silhouette in front of a gradient, without a lens: budgets are squares. */
    static final String SCENE = """
            Settings {
              camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) }
              lights -> [PointLight { origin -> vec3(-3, 3, -5) }]
              background -> Background { horizon -> rgb(1, 1, 1) sky -> rgb(0, 0.2, 0.8) }
              width -> 48 height -> 36
            }
            Scene { Sphere { material -> Material { color -> rgb(1, 0.2, 0.1) } } }
            """;

    @BeforeEach
    void privateCache() {
        previousCache = System.getProperty("crt.cache");
        System.setProperty("crt.cache", dir.resolve("cache").toString());
    }

    @AfterEach
    void restoreCache() {
        if (previousCache == null) System.clearProperty("crt.cache");
        else System.setProperty("crt.cache", previousCache);
    }

    private Path script() throws IOException {
        Path p = dir.resolve("ball.crt");
        Files.writeString(p, SCENE);
        return p;
    }

    @Test
    void writesTheCsvTheChartsAndTheReferenceAndCachesTheReference() throws IOException {
        Path out = dir.resolve("study");
        String[] args = {"accuracy", script().toString(), "-o", out.toString(), "--methods", "grid,sobol,adaptive",
                "--budgets", "1,4,16", "--reference-spp", "256"};
        CliRun run = CliRun.of(args);
        assertThat(run.exitCode()).as(run.err()).isZero();
        List<String> rows = Files.readAllLines(out.resolve("accuracy.csv"));
        assertThat(rows.get(0)).startsWith("method,spp,supersampling,dofsamples,seconds,primary_rays,total_rays,rmse,ssim");
        assertThat(rows).hasSize(1 + 3 * 3);
        double[] sobolRmse = new double[3];
        boolean anyFront = false;
        for (String row : rows.subList(1, rows.size())) {
            String[] f = row.split(",");
            int spp = Integer.parseInt(f[1]);
            long primary = Long.parseLong(f[5]);
            if (!f[0].equals("adaptive")) assertThat(primary).as(row).isEqualTo(48L * 36 * spp);
            else assertThat(primary).as(row).isLessThanOrEqualTo(48L * 36 * spp);
            double rmse = Double.parseDouble(f[7]), ssim = Double.parseDouble(f[8]);
            assertThat(rmse).isPositive();
            assertThat(ssim).isBetween(0.5, 1.0);
            if (f[0].equals("sobol")) sobolRmse[Integer.numberOfTrailingZeros(spp) / 2] = rmse;
            anyFront |= Boolean.parseBoolean(f[9]);
        }
        assertThat(sobolRmse[1]).isLessThan(sobolRmse[0]);
        assertThat(sobolRmse[2]).isLessThan(sobolRmse[1]);
        assertThat(anyFront).isTrue();
        for (String chart : new String[] {"rmse", "ssim"}) {
            BufferedImage png = ImageIO.read(out.resolve(chart + ".png").toFile());
            assertThat(png.getWidth()).isEqualTo(800);
            assertThat(Files.readString(out.resolve(chart + ".svg"))).contains("<svg").contains("<path");
        }
        assertThat(ImageIO.read(out.resolve("reference.png").toFile()).getWidth()).isEqualTo(48);
        try (Stream<Path> s = Files.list(out)) {
            assertThat(s.map(p -> p.getFileName().toString())).noneMatch(n -> n.startsWith("."));
        }

        CliRun again = CliRun.of(args);
        assertThat(again.exitCode()).as(again.err()).isZero();
        assertThat(again.err()).contains("using the cached reference");
        assertThat(Files.readAllLines(out.resolve("accuracy.csv"))).hasSize(rows.size());

        Files.delete(out.resolve("rmse.png"));
        CliRun replot = CliRun.of("accuracy", script().toString(), "-o", out.toString(), "--replot");
        assertThat(replot.exitCode()).as(replot.err()).isZero();
        assertThat(ImageIO.read(out.resolve("rmse.png").toFile()).getWidth()).isEqualTo(800);
        Files.writeString(out.resolve("accuracy.csv"), "method,spp\nfast,1\n");
        CliRun bad = CliRun.of("accuracy", script().toString(), "-o", out.toString(), "--replot");
        assertThat(bad.exitCode()).isEqualTo(3);
        assertThat(bad.err()).contains("is not a CSV crt accuracy wrote");
    }

    @Test
    void badMethodsAndBudgetsAreUsageErrors() throws IOException {
        String scene = script().toString();
        CliRun method = CliRun.of("accuracy", scene, "--methods", "grid,fast");
        assertThat(method.exitCode()).isEqualTo(2);
        assertThat(method.err()).contains("--methods takes grid, jittered, sobol and adaptive, not 'fast'");
        CliRun budget = CliRun.of("accuracy", scene, "--budgets", "1,8");
        assertThat(budget.exitCode()).isEqualTo(2);
        assertThat(budget.err()).contains("each budget must be a square").contains("got 8");
        CliRun tiny = CliRun.of("accuracy", scene, "--width", "8", "--height", "8");
        assertThat(tiny.exitCode()).isEqualTo(2);
        assertThat(tiny.err()).contains("at least 11×11");
    }

    @Test
    void theReferenceDrawsOtherSobolPointsThanTheStudy() throws IOException {
        dev.crt.scene.Scene scene = dev.crt.lang.CrtCompiler.compile(dev.crt.lang.ScriptFiles.read(script()),
                dev.crt.lang.CompileOptions.DEFAULT).scene();
        assertThat(AccuracyStudy.reference(scene, 64, 0.5).settings().seed()).isNotEqualTo(scene.settings().seed());
    }

    @Test
    void withALensTheBudgetGoesToTwoByTwoSubPixelsTimesLensSamples() {
        assertThat(AccuracyStudy.split(64, true)).containsExactly(2, 16);
        assertThat(AccuracyStudy.split(6, true)).containsExactly(1, 6);
        assertThat(AccuracyStudy.split(16, false)).containsExactly(4, 1);
    }
}
