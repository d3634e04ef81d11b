package dev.crt.cli;

import dev.crt.image.FrameBuffer;
import dev.crt.image.IdColors;
import dev.crt.image.ImageFiles;
import dev.crt.render.FeatureSwitchedOffException;
import dev.crt.render.Renderer;
import dev.crt.scene.Scene;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;

/** Writes the id and depth passes of {@code crt render} and {@code crt preview}, atomically. */
final class PassFiles {
    private PassFiles() {}

    /** The ray tracer's id or depth pass of {@code scene} through its camera, at pixel centres. */
    static int renderPass(Scene scene, PassOption.Pass pass, Path target, boolean quiet, PrintWriter err)
            throws CliFailure {
        int w = scene.settings().width(), h = scene.settings().height();
        if ((long) w * h > FrameBuffer.MAX_PIXELS) {
            throw new CliFailure(ExitCode.USAGE, String.format(Locale.ROOT,
                    "an image of %d×%d pixels is too large to render (at most %,d pixels)", w, h, FrameBuffer.MAX_PIXELS));
        }
        long start = System.nanoTime();
        Renderer renderer;
        try {
            renderer = Renderer.prepare(scene);
        } catch (FeatureSwitchedOffException e) {
            throw new CliFailure(ExitCode.USAGE, e.getMessage());
        }
        if (pass == PassOption.Pass.ID) {
            writeIds(renderer.idPass(), w, h, target);
        } else {
            double[] depth = renderer.depthPass();
            float[] values = new float[depth.length];
            for (int i = 0; i < depth.length; i++) values[i] = (float) depth[i];
            writeDepth(values, w, h, target);
        }
        if (!quiet) {
            err.printf(Locale.ROOT, "crt: wrote the %s pass %s (%d×%d) in %s%n", pass.name().toLowerCase(Locale.ROOT),
                    target, w, h, RenderCommand.seconds(System.nanoTime() - start));
            err.flush();
        }
        return ExitCode.OK;
    }

    static void writeIds(int[] ids, int w, int h, Path target) throws CliFailure {
        try {
            ImageFiles.write(IdColors.image(ids, w, h), target, 1, Map.of());
        } catch (IOException e) {
            throw new CliFailure(ExitCode.FILE_ERROR, ScriptCompilation.plain(e));
        }
    }

    static void writeDepth(float[] depth, int w, int h, Path target) throws CliFailure {
        try {
            ImageFiles.writeGreyPfm(depth, w, h, target);
        } catch (IOException e) {
            throw new CliFailure(ExitCode.FILE_ERROR, ScriptCompilation.plain(e));
        }
    }
}
