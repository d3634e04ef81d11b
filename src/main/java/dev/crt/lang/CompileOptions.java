package dev.crt.lang;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

/**
 * What a compile may depend on besides the script: the time {@code t}, the asset folders given with
 * {@code --assets}, the evaluation budget (loop iterations in total, wall-clock time), and whether
 * to record a {@link SourceMap} (tools that edit the script ask for it; rendering does not).
 */
public record CompileOptions(double time, List<Path> assetDirs, long loopBudget, Duration timeBudget, boolean sourceMap) {
    public static final long DEFAULT_LOOP_BUDGET = 10_000_000L;
    public static final Duration DEFAULT_TIME_BUDGET = Duration.ofSeconds(10);
    public static final CompileOptions DEFAULT =
            new CompileOptions(0, List.of(), DEFAULT_LOOP_BUDGET, DEFAULT_TIME_BUDGET);

    public CompileOptions {
        assetDirs = List.copyOf(assetDirs);
    }

    /** Options that record no source map. */
    public CompileOptions(double time, List<Path> assetDirs, long loopBudget, Duration timeBudget) {
        this(time, assetDirs, loopBudget, timeBudget, false);
    }

    public CompileOptions withTime(double t) { return new CompileOptions(t, assetDirs, loopBudget, timeBudget, sourceMap); }

    /** The same options, recording a {@link SourceMap}. */
    public CompileOptions withSourceMap() { return new CompileOptions(time, assetDirs, loopBudget, timeBudget, true); }
}
