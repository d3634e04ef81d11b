package dev.crt.cli;

import dev.crt.lang.CompileOptions;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Option;

/** Options that change how a script compiles: asset folders and the evaluation budget. */
final class ScriptOptions {
    @Option(names = "--assets", paramLabel = "DIR",
            description = "Folder to look up assets such as panorama images in (repeatable).")
    List<Path> assetDirs = new ArrayList<>();

    @Option(names = "--time-budget", paramLabel = "SECONDS",
            description = "Stop evaluating a script after this long (default: ${DEFAULT-VALUE}).")
    double timeBudget = CompileOptions.DEFAULT_TIME_BUDGET.toSeconds();

    /** The compile options for the time {@code t}. */
    CompileOptions toCompileOptions(double time) {
        if (!Double.isFinite(time)) {
            throw new IllegalArgumentException("--time must be a finite number, got " + time);
        }
        for (Path dir : assetDirs) {
            if (!Files.isDirectory(dir)) {
                throw new IllegalArgumentException("--assets " + dir + ": " + (Files.exists(dir) ? "not a folder" : "no such folder"));
            }
        }
        if (!(timeBudget > 0)) {
            throw new IllegalArgumentException("--time-budget must be a positive number of seconds");
        }
        return new CompileOptions(time, assetDirs, CompileOptions.DEFAULT_LOOP_BUDGET,
                Duration.ofNanos((long) Math.min(timeBudget * 1e9, Long.MAX_VALUE)));
    }
}
