package dev.crt.render;

import static dev.crt.render.Scenes.*;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.AreaLight;
import dev.crt.scene.Background;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;

/**
 * Area light accuracy and cost, not a unit test: the RMS relative error of a wall's diffuse value
 * under a parallelogram light against the closed-form polygon irradiance, and the shadow rays per
 * second, for n = 1 … 64 (n² samples), with a log-log chart. Run:
 * <pre>mvn -B -q -o test-compile && java -cp target/classes:target/test-classes:$(cat cp.txt) dev.crt.render.AreaLightConvergence docs/images/area-light-convergence.png</pre>
 * (cp.txt from {@code mvn -q -o dependency:build-classpath -Dmdep.outputFile=cp.txt}).
 */
public final class AreaLightConvergence {
    private AreaLightConvergence() {}

    public static void main(String[] args) throws Exception {
        int[] ns = {1, 2, 4, 8, 16, 32, 64};
        List<Double> xs = new ArrayList<>(), errors = new ArrayList<>(), reference = new ArrayList<>();
        System.out.println("| n | samples | RMS relative error | rays | Mrays/s (1 thread) |");
        System.out.println("|---|---|---|---|---|");
        double first = 0;
        for (int n : ns) {
            Vec3 corner = v(-0.5, -0.4, -1.5), e1 = v(1.2, 0, 0), e2 = v(0, 0.3, -0.8);
            AreaLight light = new AreaLight(corner, e1, e2, n, Rgb.WHITE, 2, 0, SourceSpan.NONE);
            Settings s = settings(camera(v(0, 0, -4), Vec3.ZERO, 90), List.of(light), Background.BLACK, 96, 96);
            Scene scene = scene(s, plane(v(0, 0, -1), Vec3.ZERO, matte(Rgb.WHITE)));
            Renderer r = Renderer.prepare(scene);
            r.render(1, RenderMonitor.NONE);
            long t0 = System.nanoTime();
            FrameBuffer fb = r.render(1, RenderMonitor.NONE);
            double seconds = (System.nanoTime() - t0) / 1e9;
            long rays = r.stats().totalRays();
            double area = e1.cross(e2).length(), sum = 0;
            Vec3[] poly = {corner, corner.plus(e1), corner.plus(e1).plus(e2), corner.plus(e2)};
            for (int j = 0; j < s.height(); j++) {
                for (int i = 0; i < s.width(); i++) {
                    Vec3 d = Reference.center(s, i, j);
                    Vec3 x = v(0, 0, -4).plus(d.times(4 / d.z()));
                    double exact = 2 * LightKindsTest.polygonIrradiance(x, v(0, 0, -1), poly) / area;
                    double rel = (fb.get(i, j, 0) - exact) / exact;
                    sum += rel * rel;
                }
            }
            double error = Math.sqrt(sum / (s.width() * s.height()));
            if (n == 1) first = error;
            xs.add((double) n * n);
            errors.add(error);
            reference.add(first * Math.pow(n, -2));
            System.out.printf(Locale.ROOT, "| %d | %d | %.3g | %,d | %.2f |%n", n, n * n, error, rays, rays / seconds / 1e6);
        }
        XYChart chart = new XYChartBuilder().width(760).height(520).title("Area light: error against samples per shading point")
                .xAxisTitle("samples per shading point (n²)").yAxisTitle("RMS relative error of the diffuse term").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        chart.addSeries("CRT, n×n jittered", xs, errors);
        chart.addSeries("slope 1/N (jittered, smooth integrand)", xs, reference);
        BitmapEncoder.saveBitmap(chart, Path.of(args[0]).toString(), BitmapEncoder.BitmapFormat.PNG);
    }
}
