package dev.crt.cli;

import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/** Options shared by commands that render: image size, sampling, threads and reporting. */
final class RenderOptions {
    /** More threads than this only cost memory: each reserves a deep stack. */
    static final int MAX_THREADS = 256;

    @Option(names = "--width", paramLabel = "W", description = "Image width in pixels (overrides Settings).")
    Integer width;

    @Option(names = "--height", paramLabel = "H", description = "Image height in pixels (overrides Settings).")
    Integer height;

    @Option(names = "--supersampling", paramLabel = "N", description = "N×N samples per pixel (overrides Settings).")
    Integer supersampling;

    @Option(names = "--dof-samples", paramLabel = "N", description = "Lens samples per pixel sample (overrides Settings).")
    Integer dofSamples;

    @Option(names = "--threads", paramLabel = "N", description = "Render threads; 0 uses every core (default: ${DEFAULT-VALUE}).")
    int threads = 0;

    @Option(names = "--stats", description = "Print rays by kind, rays per second and the time of each phase.")
    boolean stats;

    @Option(names = {"-q", "--quiet"}, description = "Print no progress and no summary.")
    boolean quiet;

    /** Checks the values; a bad one is a usage error. */
    void validate(CommandSpec spec) {
        OptionChecks.requireAtLeast(spec, width, 1, "--width");
        OptionChecks.requireAtLeast(spec, height, 1, "--height");
        OptionChecks.requireBetween(spec, supersampling, 1, Settings.MAX_SUPERSAMPLING, "--supersampling");
        OptionChecks.requireBetween(spec, dofSamples, 1, Settings.MAX_DOF_SAMPLES, "--dof-samples");
        OptionChecks.requireBetween(spec, threads, 0, MAX_THREADS, "--threads");
    }

    /** The scene with the command line's values in place of its Settings'. */
    Scene applyTo(Scene scene) {
        Settings s = scene.settings();
        s = s.withSize(width != null ? width : s.width(), height != null ? height : s.height());
        s = s.withSampling(supersampling != null ? supersampling : s.supersampling(),
                dofSamples != null ? dofSamples : s.dofSamples());
        return scene.withSettings(s);
    }
}
