import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Draws the charts of docs/benchmarks.md from the CSV files that bench/povray-compare.sh and
 * bench/scaling.sh write. Run it with bench/charts.sh, which puts XChart on the class path.
 *
 * <pre>
 *   java -cp XCHART_CLASSPATH bench/charts/BenchCharts.java RESULTS_DIR IMAGES_DIR
 * </pre>
 * Writes bench-povray.png, bench-scaling.png, bench-mrays.png, bench-csg.png, bench-torus-roots.png
 * and bench-mesh-render.png into IMAGES_DIR.
 */
public final class BenchCharts {
    private static final Color CRT = new Color(0x2b, 0x6c, 0xb0);
    private static final Color POVRAY = new Color(0xd0, 0x6b, 0x2a);
    private static final Color GREY = new Color(0x70, 0x70, 0x70);

    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: BenchCharts RESULTS_DIR IMAGES_DIR");
            System.exit(2);
        }
        Path results = Path.of(args[0]);
        Path images = Path.of(args[1]);
        Files.createDirectories(images);
        Path compare = results.resolve("povray-compare.csv");
        if (Files.exists(compare)) {
            povray(read(compare), images.resolve("bench-povray.png"));
        } else {
            System.err.println("no " + compare + ": run bench/povray-compare.sh first");
        }
        Path scaling = results.resolve("scaling.csv");
        if (Files.exists(scaling)) {
            List<String[]> rows = read(scaling);
            scaling(rows, images.resolve("bench-scaling.png"));
            mrays(rows, images.resolve("bench-mrays.png"));
        } else {
            System.err.println("no " + scaling + ": run bench/scaling.sh first");
        }
        Path torus = results.resolve("torus-roots.csv");
        if (Files.exists(torus)) {
            torus(read(torus), images.resolve("bench-torus-roots.png"));
        } else {
            System.err.println("no " + torus + ": run TorusRootsBench (docs/benchmarks.md, torus roots)");
        }
        Path meshes = results.resolve("mesh-render-cpu.csv");
        if (Files.exists(meshes)) {
            meshRender(read(meshes), images.resolve("bench-mesh-render.png"));
        } else {
            System.err.println("no " + meshes + ": run bench/mesh-render-cpu.sh first");
        }
        Path csg = results.resolve("csg-scaling.csv");
        Path before = results.resolve("csg-scaling-before.csv");
        if (Files.exists(csg) && Files.exists(before)) {
            csg(read(csg), read(before), images.resolve("bench-csg.png"));
        } else {
            System.err.println("no " + csg + " or " + before + ": see docs/benchmarks.md, section 4");
        }
    }

    /** Render time of the dimpled plate against the number of balls, before and after the CSG rework. */
    private static void csg(List<String[]> rows, List<String[]> before, Path file) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(450)
                .title("Plate minus a union of n balls, 640x360: render time")
                .xAxisTitle("balls in the union (log scale)").yAxisTitle("seconds (log scale)").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setXAxisDecimalPattern("#,###");
        series(chart, "every operand tested (before)", column(before, 0), column(before, 3), POVRAY);
        series(chart, "n-ary nodes and a BVH over the operands", column(rows, 0), column(rows, 3), CRT);
        save(chart, file);
    }

    /**
     * Failure rate against cost per ray of each quartic method, one point per family of rays.
     * A rate of 0 cannot sit on a log axis: it is drawn at half of one failure in the rays tried.
     */
    private static void torus(List<String[]> rows, Path file) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(450)
                .title("Torus roots: failure rate against cost (one point per family of rays)")
                .xAxisTitle("nanoseconds per ray").yAxisTitle("rays with a missed or wrong root (log; 0 drawn at 1/(2n))").build();
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setMarkerSize(10);
        Color[] colors = {POVRAY, CRT, GREY, Color.BLACK};
        List<String> methods = new ArrayList<>();
        for (String[] r : rows) if (!methods.contains(r[0])) methods.add(r[0]);
        for (int m = 0; m < methods.size(); m++) {
            List<Double> x = new ArrayList<>(), y = new ArrayList<>();
            for (String[] r : rows) {
                if (!r[0].equals(methods.get(m))) continue;
                double rays = Double.parseDouble(r[2]), failed = Double.parseDouble(r[3]);
                x.add(Double.parseDouble(r[7]));
                y.add(failed > 0 ? failed / rays : 0.5 / rays);
            }
            XYSeries series = chart.addSeries(methods.get(m), x, y);
            series.setMarker(SeriesMarkers.CIRCLE);
            series.setMarkerColor(colors[m % colors.length]);
        }
        save(chart, file);
    }

    /** Whole-process time of each run and the median, CRT beside POV-Ray. */
    private static void povray(List<String[]> rows, Path file) throws IOException {
        List<String> labels = new ArrayList<>();
        List<Double> crt = new ArrayList<>();
        List<Double> pov = new ArrayList<>();
        double ratio = 0;
        for (String[] row : rows) {
            labels.add(row[0].equals("median") ? "median" : "run " + row[0]);
            crt.add(Double.parseDouble(row[1]));
            pov.add(Double.parseDouble(row[2]));
            if (row[0].equals("median")) {
                ratio = Double.parseDouble(row[1]) / Double.parseDouble(row[2]);
            }
        }
        String[] median = rows.get(rows.size() - 1);
        if (median[0].equals("median") && median.length >= 6 && !median[4].isEmpty() && !median[5].isEmpty()) {
            // CRT's render phase beside POV-Ray's trace phase: the tracing alone, without start-up and output
            labels.add("render phase (median)");
            crt.add(Double.parseDouble(median[4]));
            pov.add(Double.parseDouble(median[5]));
        }
        CategoryChart chart = new CategoryChartBuilder().width(800).height(450)
                .title(String.format(Locale.ROOT, "Box field, 1280x720: whole-process time, CRT / POV-Ray = %.2f", ratio))
                .xAxisTitle("").yAxisTitle("seconds (lower is better)").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        chart.getStyler().setSeriesColors(new Color[] {CRT, POVRAY});
        chart.getStyler().setLabelsVisible(true);
        chart.getStyler().setDecimalPattern("0.00");
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.addSeries("CRT", labels, crt);
        chart.addSeries("POV-Ray 3.7", labels, pov);
        save(chart, file);
    }

    /** Compile, BVH build and render time against n on a logarithmic n axis. */
    private static void scaling(List<String[]> rows, Path file) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(450)
                .title("Random spheres, 640x360: time against the number of spheres")
                .xAxisTitle("spheres (log scale)").yAxisTitle("seconds").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setXAxisDecimalPattern("#,###");
        double[] n = column(rows, 0);
        series(chart, "render", n, column(rows, 3), CRT);
        series(chart, "BVH build", n, column(rows, 2), POVRAY);
        series(chart, "compile (script evaluation)", n, column(rows, 1), GREY);
        save(chart, file);
    }

    /**
     * Render CPU time of the mesh ball against its triangle count on a log axis, where growth like
     * log n is a straight line.
     */
    private static void meshRender(List<String[]> rows, Path file) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(450)
                .title("Mesh ball, 1280x720, one render thread: CPU time against triangles")
                .xAxisTitle("triangles (log scale)").yAxisTitle("CPU seconds").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setXAxisDecimalPattern("#,###");
        chart.getStyler().setYAxisMin(0.0);
        series(chart, "render (median of the renders in a warm JVM)", column(rows, 0), column(rows, 3), CRT);
        save(chart, file);
    }

    /** Rays per second against n. */
    private static void mrays(List<String[]> rows, Path file) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(450)
                .title("Random spheres, 640x360: rays per second (primary and shadow)")
                .xAxisTitle("spheres (log scale)").yAxisTitle("Mrays/s").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setLegendVisible(false);
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setXAxisDecimalPattern("#,###");
        chart.getStyler().setYAxisMin(0.0);
        series(chart, "Mrays/s", column(rows, 0), column(rows, 4), CRT);
        save(chart, file);
    }

    private static void series(XYChart chart, String name, double[] x, double[] y, Color color) {
        XYSeries s = chart.addSeries(name, x, y);
        s.setMarker(SeriesMarkers.CIRCLE);
        s.setLineColor(color);
        s.setMarkerColor(color);
        s.setLineStyle(new BasicStroke(2f));
    }

    private static double[] column(List<String[]> rows, int index) {
        return rows.stream().mapToDouble(r -> Double.parseDouble(r[index])).toArray();
    }

    /** The rows of a CSV file with a header line, split on commas. */
    private static List<String[]> read(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file);
        List<String[]> rows = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            if (!line.isBlank()) {
                rows.add(line.split(",", -1));
            }
        }
        return rows;
    }

    private static void save(org.knowm.xchart.internal.chartpart.Chart<?, ?> chart, Path file) throws IOException {
        BitmapEncoder.saveBitmap(chart, file.toString(), BitmapEncoder.BitmapFormat.PNG);
        System.out.println("wrote " + file);
    }
}
