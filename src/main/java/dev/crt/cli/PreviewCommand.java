package dev.crt.cli;

import dev.crt.image.ImageFiles;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.Source;
import dev.crt.live.GlUnavailableException;
import dev.crt.live.Preview;
import dev.crt.live.UnsupportedSceneException;
import dev.crt.scene.Scene;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code crt preview}: draws a scene with the OpenGL live view's renderer, headless, to an image file. */
@Command(name = "preview", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {"Draw a scene script with the live view's OpenGL renderer (headless, no display needed)",
                "to an image (.png or .ppm; .pfm for --pass depth): exact shapes and CSG, lights and shadows,",
                "no reflections or refractions. Command-line values override the script's Settings."},
        footer = {"", "Exit codes: 0 drawn, 1 the script has errors, 2 bad usage, 3 a file could not be read or written,",
                "4 OpenGL is not available here or the scene holds something the live view cannot draw."})
final class PreviewCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE", description = "The scene script (.crt).")
    Path sceneFile;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT",
            description = "The image to write (default: the script's name with .png, or .pfm for depth, in the current folder).")
    Path output;

    @Option(names = "--width", paramLabel = "W", description = "Image width in pixels (overrides Settings).")
    Integer width;

    @Option(names = "--height", paramLabel = "H", description = "Image height in pixels (overrides Settings).")
    Integer height;

    @Option(names = {"-q", "--quiet"}, description = "Print no summary.")
    boolean quiet;

    @Mixin
    ScriptOptions scriptOptions;

    @Mixin
    TimeOption timeOption;

    @Mixin
    PassOption passOption;

    @Override
    public Integer call() throws CliFailure {
        PrintWriter err = spec.commandLine().getErr();
        OptionChecks.requireAtLeast(spec, width, 1, "--width");
        OptionChecks.requireAtLeast(spec, height, 1, "--height");
        CompileOptions options = OptionChecks.compileOptions(spec, scriptOptions, timeOption.time);
        Path target = output != null ? output : passOption.defaultOutput(sceneFile);
        PassOption.Pass pass = passOption.pass(spec, target);
        OutputFiles.checkWritableImage(target);
        if (pass == PassOption.Pass.COLOR && OutputFiles.extension(target).equals("pfm")) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "crt preview writes its picture as .png or .ppm (8-bit, as drawn), not " + target);
        }

        long start = System.nanoTime();
        Source source = ScriptCompilation.read(sceneFile);
        CompileResult result = ScriptCompilation.compile(source, options, err);
        if (result.hasErrors()) return ExitCode.ofErrors(result);
        Scene scene = result.scene();
        var s = scene.settings();
        scene = scene.withSettings(s.withSize(width != null ? width : s.width(), height != null ? height : s.height()));
        int w = scene.settings().width(), h = scene.settings().height();
        if ((long) w * h > MAX_PIXELS) {
            throw new CliFailure(ExitCode.USAGE, String.format(Locale.ROOT,
                    "an image of %d×%d pixels is too large to preview (at most %,d pixels)", w, h, MAX_PIXELS));
        }
        try (Preview preview = Preview.open()) {
            preview.draw(scene);
            switch (pass) {
                case ID -> PassFiles.writeIds(preview.ids(), w, h, target);
                case DEPTH -> PassFiles.writeDepth(preview.depth(), w, h, target);
                default -> {
                    try {
                        ImageFiles.write(preview.colourImage(s.gamma()), target, s.gamma(),
                                dev.crt.animation.FrameJob.textChunks(s));
                    } catch (IOException e) {
                        throw new CliFailure(ExitCode.FILE_ERROR, ScriptCompilation.plain(e));
                    }
                }
            }
        } catch (GlUnavailableException e) {
            throw new CliFailure(ExitCode.NO_OPENGL, e.getMessage());
        } catch (UnsupportedSceneException e) {
            throw new CliFailure(ExitCode.NO_OPENGL, "cannot preview " + sceneFile + ": " + e.getMessage());
        }
        if (!quiet) {
            err.printf(Locale.ROOT, "crt: wrote %s (%d×%d, %s pass) in %s%n", target, w, h,
                    pass.name().toLowerCase(Locale.ROOT), RenderCommand.seconds(System.nanoTime() - start));
            err.flush();
        }
        return ExitCode.OK;
    }

    /** The largest framebuffer drawn: 8192 × 8192, within every OpenGL 3.3 implementation's usual limit. */
    static final long MAX_PIXELS = 8192L * 8192;
}
