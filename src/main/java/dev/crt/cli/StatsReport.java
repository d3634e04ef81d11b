package dev.crt.cli;

import dev.crt.animation.FrameJob;
import dev.crt.render.RenderStats;
import java.io.PrintWriter;
import java.util.Locale;

/** The {@code --stats} table: rays by kind, rays per second, and the time of each phase. */
final class StatsReport {
    private StatsReport() {}

    static void print(PrintWriter out, long compileNanos, FrameJob.Outcome outcome) {
        RenderStats s = outcome.stats();
        out.println("rays");
        row(out, "primary", s.primaryRays());
        row(out, "shadow", s.shadowRays());
        row(out, "reflected", s.reflectedRays());
        row(out, "refracted", s.refractedRays());
        row(out, "total", s.totalRays());
        out.printf(Locale.ROOT, "  %-10s %14.2f Mrays/s%n", "speed", s.megaRaysPerSecond());
        out.println("time");
        time(out, "compile", compileNanos);
        time(out, "bvh build", s.buildNanos());
        time(out, "render", s.renderNanos());
        time(out, "write", outcome.writeNanos());
        time(out, "total", compileNanos + s.buildNanos() + s.renderNanos() + outcome.writeNanos());
    }

    private static void row(PrintWriter out, String name, long n) {
        out.printf(Locale.ROOT, "  %-10s %,14d%n", name, n);
    }

    private static void time(PrintWriter out, String name, long nanos) {
        out.printf(Locale.ROOT, "  %-10s %14.3f s%n", name, nanos / 1e9);
    }
}
