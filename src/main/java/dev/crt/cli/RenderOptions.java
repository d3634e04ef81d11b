package dev.crt.cli;

import dev.crt.scene.Sampler;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

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

    @Option(names = "--sampler", paramLabel = "KIND",
            description = "Pixel samples: grid, jittered, sobol or adaptive (overrides Settings).")
    String sampler;

    @Option(names = "--noise", paramLabel = "LEVELS",
            description = "The adaptive sampler's target: standard error of a pixel's mean, in 8-bit levels (default: 0.5).")
    Double noise;

    @Option(names = "--shading", paramLabel = "MODEL",
            description = "crt (CRT's model) or original (the look of CRT 2015's scenes); overrides Settings.")
    String shading;

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
        if (sampler != null && Sampler.of(sampler).isEmpty()) {
            throw new ParameterException(spec.commandLine(),
                    "--sampler must be grid, jittered, sobol or adaptive, not '" + sampler + "'");
        }
        if (shading != null && Shading.of(shading).isEmpty()) {
            throw new ParameterException(spec.commandLine(), "--shading must be crt or original, not '" + shading + "'");
        }
        if (noise != null && !(noise > 0 && noise < Double.POSITIVE_INFINITY)) {
            throw new ParameterException(spec.commandLine(), "--noise must be a positive number of 8-bit levels, not " + noise);
        }
    }

    /** The scene with the command line's values in place of its Settings'. */
    Scene applyTo(Scene scene) {
        Settings s = scene.settings();
        s = s.withSize(width != null ? width : s.width(), height != null ? height : s.height());
        s = s.withSampling(supersampling != null ? supersampling : s.supersampling(),
                dofSamples != null ? dofSamples : s.dofSamples());
        if (sampler != null) s = s.withSampler(Sampler.of(sampler).orElseThrow(), noise != null ? noise : s.noise());
        else if (noise != null) s = s.withNoise(noise);
        if (shading != null) s = s.withShading(Shading.of(shading).orElseThrow());
        return scene.withSettings(s);
    }
}
