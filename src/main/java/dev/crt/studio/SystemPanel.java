package dev.crt.studio;

import java.awt.Color;
import java.awt.GridLayout;
import java.awt.event.HierarchyEvent;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.swing.JPanel;
import javax.swing.Timer;
import javax.swing.UIManager;
import org.knowm.xchart.XChartPanel;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;

/**
 * The System panel: charts of the last {@value #WINDOW_SECONDS} seconds of CPU load (the machine's
 * and CRT's), memory (the machine's in use, the JVM heap used and committed) and the studio's render
 * throughput, sampled once a second while the panel is showing and not at all while it is hidden.
 */
final class SystemPanel extends JPanel {
    /** How far back the charts reach. */
    static final int WINDOW_SECONDS = 300;

    static final String CPU_SYSTEM = "machine";
    static final String CPU_CRT = "CRT";
    static final String MEMORY_SYSTEM = "machine in use";
    static final String HEAP_USED = "JVM heap used";
    static final String HEAP_COMMITTED = "JVM heap committed";
    static final String THROUGHPUT = "renders";

    private static final Path MEMINFO = Path.of("/proc/meminfo");

    private final Throughput throughput;
    private final com.sun.management.OperatingSystemMXBean os =
            (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
    private final XYChart cpu = chart("CPU load (%)");
    private final XYChart memory = chart("Memory (MiB)");
    private final XYChart rays = chart("Render throughput (Mrays/s)");
    private final List<XChartPanel<XYChart>> panels;
    private final Timer sampler = new Timer(1000, e -> sample());

    /** The samples, oldest first, at most WINDOW_SECONDS + 1 of them: the second of each and the values by series. */
    private final long[] seconds = new long[WINDOW_SECONDS + 1];
    private final Map<String, double[]> values = new LinkedHashMap<>();
    private int count;

    SystemPanel(Throughput throughput) {
        super(new GridLayout(1, 3, 4, 0));
        this.throughput = throughput;
        setName("systemPanel");
        getAccessibleContext().setAccessibleName("System");
        for (String s : List.of(CPU_SYSTEM, CPU_CRT, MEMORY_SYSTEM, HEAP_USED, HEAP_COMMITTED, THROUGHPUT)) {
            values.put(s, new double[WINDOW_SECONDS + 1]);
        }
        cpu.getStyler().setYAxisMax(100.0);
        panels = List.of(new XChartPanel<>(cpu), new XChartPanel<>(memory), new XChartPanel<>(rays));
        String[] names = {"systemCpu", "systemMemory", "systemThroughput"};
        for (int i = 0; i < panels.size(); i++) {
            panels.get(i).setName(names[i]);
            add(panels.get(i));
        }
        applyTheme();
        // Sample only while someone can see the charts: a hidden panel costs nothing.
        addHierarchyListener(e -> {
            if ((e.getChangeFlags() & HierarchyEvent.SHOWING_CHANGED) == 0) return;
            if (isShowing()) {
                sample();
                sampler.start();
            } else {
                sampler.stop();
            }
        });
    }

    private static XYChart chart(String title) {
        XYChart c = new XYChartBuilder().width(400).height(200).title(title).build();
        c.getStyler().setYAxisDecimalPattern("#,##0.##");
        c.getStyler().setXAxisTitleVisible(false);
        c.getStyler().setYAxisTitleVisible(false);
        c.getStyler().setChartTitleFont(new java.awt.Font(java.awt.Font.SANS_SERIF, java.awt.Font.BOLD, 11));
        c.getStyler().setAxisTickLabelsFont(new java.awt.Font(java.awt.Font.SANS_SERIF, java.awt.Font.PLAIN, 10));
        c.getStyler().setLegendFont(new java.awt.Font(java.awt.Font.SANS_SERIF, java.awt.Font.PLAIN, 10));
        c.getStyler().setChartPadding(4);
        c.getStyler().setDefaultSeriesRenderStyle(org.knowm.xchart.XYSeries.XYSeriesRenderStyle.Line);
        c.getStyler().setMarkerSize(0);
        c.getStyler().setLegendPosition(Styler.LegendPosition.OutsideS);
        c.getStyler().setLegendLayout(Styler.LegendLayout.Horizontal);
        c.getStyler().setXAxisMin((double) -WINDOW_SECONDS);
        c.getStyler().setXAxisMax(0.0);
        c.getStyler().setYAxisMin(0.0);
        c.getStyler().setPlotGridVerticalLinesVisible(false);
        return c;
    }

    boolean isSampling() { return sampler.isRunning(); }

    /** Takes one sample of every series and redraws the charts. */
    void sample() {
        long nowNanos = System.nanoTime();
        long now = Math.floorDiv(nowNanos, 1_000_000_000L);
        if (count > 0 && seconds[count - 1] == now) return;
        if (count == seconds.length) {
            System.arraycopy(seconds, 1, seconds, 0, count - 1);
            for (double[] v : values.values()) System.arraycopy(v, 1, v, 0, count - 1);
            count--;
        }
        Runtime rt = Runtime.getRuntime();
        seconds[count] = now;
        values.get(CPU_SYSTEM)[count] = 100 * Math.max(0, os.getCpuLoad());
        values.get(CPU_CRT)[count] = 100 * Math.max(0, os.getProcessCpuLoad());
        values.get(MEMORY_SYSTEM)[count] = machineMemoryInUse() / (double) (1 << 20);
        values.get(HEAP_USED)[count] = (rt.totalMemory() - rt.freeMemory()) / (double) (1 << 20);
        values.get(HEAP_COMMITTED)[count] = rt.totalMemory() / (double) (1 << 20);
        count++;
        // Each past second is read again whole (a sample comes at any moment of its second); the
        // newest point is the rate over the last whole second, which a running render keeps filling.
        double[] mrays = values.get(THROUGHPUT);
        for (int i = 0; i < count - 1; i++) mrays[i] = throughput.megaRays(seconds[i]);
        mrays[count - 1] = throughput.recentMegaRaysPerSecond(nowNanos);
        double[] x = new double[count];
        for (int i = 0; i < count; i++) x[i] = seconds[i] - now;
        show(cpu, x, CPU_SYSTEM, CPU_CRT);
        show(memory, x, MEMORY_SYSTEM, HEAP_USED, HEAP_COMMITTED);
        show(rays, x, THROUGHPUT);
        panels.forEach(JPanel::repaint);
    }

    private void show(XYChart chart, double[] x, String... series) {
        for (String s : series) {
            double[] y = Arrays.copyOf(values.get(s), count);
            if (chart.getSeriesMap().containsKey(s)) chart.updateXYSeries(s, x, y, null);
            else chart.addSeries(s, x, y);
        }
    }

    /** The machine's memory in use: total less what Linux says is available (caches count as free), else less the free memory. */
    private long machineMemoryInUse() {
        long total = os.getTotalMemorySize();
        if (Files.isReadable(MEMINFO)) {
            try {
                for (String line : Files.readAllLines(MEMINFO)) {
                    if (line.startsWith("MemAvailable:")) {
                        long kib = Long.parseLong(line.replaceAll("[^0-9]", ""));
                        return Math.max(0, total - kib * 1024);
                    }
                }
            } catch (IOException | NumberFormatException e) {
                // Fall through to the JVM's figure.
            }
        }
        return Math.max(0, total - os.getFreeMemorySize());
    }

    /** How many points series {@code name} holds now. */
    int points(String name) {
        for (XYChart c : List.of(cpu, memory, rays)) {
            XYSeries s = c.getSeriesMap().get(name);
            if (s != null) return s.getXData().length;
        }
        return 0;
    }

    /** The latest value of series {@code name}, or NaN before the first sample. */
    double latest(String name) { return count == 0 ? Double.NaN : values.get(name)[count - 1]; }

    /** The largest value series {@code name} holds. */
    double highest(String name) {
        double max = Double.NaN;
        for (int i = 0; i < count; i++) max = Double.isNaN(max) ? values.get(name)[i] : Math.max(max, values.get(name)[i]);
        return max;
    }

    @Override
    public void updateUI() {
        super.updateUI();
        if (cpu != null) applyTheme();
    }

    /** Chart colours from the look and feel, so the charts follow the light and dark themes. */
    private void applyTheme() {
        Color back = UIManager.getColor("Panel.background");
        Color text = UIManager.getColor("Label.foreground");
        Color plot = UIManager.getColor("TextArea.background");
        if (back == null || text == null || plot == null) return;
        for (XYChart c : List.of(cpu, memory, rays)) {
            c.getStyler().setChartBackgroundColor(back);
            c.getStyler().setChartFontColor(text);
            c.getStyler().setAxisTickLabelsColor(text);
            c.getStyler().setPlotBackgroundColor(plot);
            c.getStyler().setLegendBackgroundColor(plot);
            c.getStyler().setPlotBorderVisible(false);
        }
        if (panels != null) panels.forEach(JPanel::repaint);
    }
}
