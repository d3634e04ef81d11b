package dev.crt.cli;

import dev.crt.image.AtomicFile;
import dev.crt.scene.Sampler;
import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.function.Predicate;
import java.util.function.ToDoubleFunction;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.VectorGraphicsEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.XYStyler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** Error against render time, one series per sampler and the Pareto front, as PNG and SVG. */
final class AccuracyChart {
    /** Errors of exactly 0 (a method that hit the reference) still need a place on a log axis. */
    private static final double FLOOR = 1e-4;

    private AccuracyChart() {}

    /**
     * Writes {@code base}.png and {@code base}.svg (each atomically) of the error {@code error}
     * against time, the points where {@code front} holds joined as the Pareto front.
     */
    static void write(List<AccuracyStudy.Point> points, String title, String errorName,
            ToDoubleFunction<AccuracyStudy.Point> error, Predicate<AccuracyStudy.Point> front, Path base)
            throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(560).title(title)
                .xAxisTitle("render time (s)").yAxisTitle(errorName).build();
        XYStyler s = chart.getStyler();
        s.setXAxisLogarithmic(true);
        s.setYAxisLogarithmic(true);
        // Whole decades on both axes, so each shows at least two labelled powers of ten.
        double[] t = seconds(points), e = values(points, error);
        s.setXAxisMin(decadeBelow(min(t)));
        s.setXAxisMax(decadeAbove(max(t)));
        s.setYAxisMin(decadeBelow(min(e)));
        s.setYAxisMax(decadeAbove(max(e)));
        s.setLegendPosition(Styler.LegendPosition.InsideNE);
        s.setChartBackgroundColor(Color.WHITE);
        s.setXAxisDecimalPattern("0.###");
        s.setYAxisDecimalPattern("0.####");
        for (Sampler m : Sampler.values()) {
            List<AccuracyStudy.Point> mine = points.stream().filter(p -> p.sampler() == m).toList();
            if (mine.isEmpty()) continue;
            XYSeries series = chart.addSeries(m.word(), seconds(mine), values(mine, error));
            series.setMarker(SeriesMarkers.CIRCLE);
        }
        List<AccuracyStudy.Point> pareto = new ArrayList<>(points.stream().filter(front).toList());
        pareto.sort(Comparator.comparingDouble(AccuracyStudy.Point::seconds));
        if (!pareto.isEmpty()) {
            XYSeries f = chart.addSeries("Pareto front", seconds(pareto), values(pareto, error));
            f.setMarker(SeriesMarkers.NONE);
            f.setLineColor(new Color(0, 0, 0, 140));
            f.setLineStyle(new BasicStroke(2.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 1, new float[] {6, 6}, 0));
        }
        Path dir = base.toAbsolutePath().getParent();
        String name = base.getFileName().toString();
        byte[] png = BitmapEncoder.getBitmapBytes(chart, BitmapEncoder.BitmapFormat.PNG);
        AtomicFile.write(dir.resolve(name + ".png"), out -> out.write(png));
        AtomicFile.write(dir.resolve(name + ".svg"),
                out -> VectorGraphicsEncoder.saveVectorGraphic(chart, out, VectorGraphicsEncoder.VectorGraphicsFormat.SVG));
    }

    private static double decadeBelow(double v) { return Math.pow(10, Math.floor(Math.log10(v))); }

    /** The power of ten above v, and never the same as the one below (a decade at least). */
    private static double decadeAbove(double v) {
        double d = Math.pow(10, Math.ceil(Math.log10(v)));
        return d == decadeBelow(v) ? d * 10 : d;
    }

    private static double min(double[] v) { return Arrays.stream(v).min().orElse(1); }

    private static double max(double[] v) { return Arrays.stream(v).max().orElse(1); }

    private static double[] seconds(List<AccuracyStudy.Point> ps) {
        return ps.stream().mapToDouble(AccuracyStudy.Point::seconds).toArray();
    }

    private static double[] values(List<AccuracyStudy.Point> ps, ToDoubleFunction<AccuracyStudy.Point> error) {
        return ps.stream().mapToDouble(p -> Math.max(FLOOR, error.applyAsDouble(p))).toArray();
    }
}
