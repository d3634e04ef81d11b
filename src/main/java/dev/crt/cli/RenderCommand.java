package dev.crt.cli;

import dev.crt.animation.FrameFailure;
import dev.crt.animation.FrameJob;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.Source;
import dev.crt.render.RenderCancelledException;
import dev.crt.scene.Scene;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code crt render}: compiles a script and renders it to an image file. */
@Command(name = "render", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {"Render a scene script to an image (.png, .ppm or .pfm by extension).",
                "Command-line values override the script's Settings. Ctrl-C cancels and writes nothing."},
        footer = {"", ExitCode.HELP_LINE})
final class RenderCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE", description = "The scene script (.crt), or - for the standard input.")
    Path sceneFile;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT",
            description = "The image to write (default: the script's name with .png, in the current folder); missing folders are created.")
    Path output;

    @Mixin
    ScriptOptions scriptOptions;

    @Mixin
    TimeOption timeOption;

    @Mixin
    RenderOptions renderOptions;

    @Mixin
    PassOption passOption;

    @Override
    public Integer call() throws CliFailure {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        renderOptions.validate(spec);
        CompileOptions options = OptionChecks.compileOptions(spec, scriptOptions, timeOption.time);
        if (output == null && ScriptCompilation.isStandardInput(sceneFile)) {
            throw new CliFailure(ExitCode.USAGE, "a script read from the standard input (-) needs -o OUT for the image");
        }
        Path target = output != null ? output : passOption.defaultOutput(sceneFile);
        PassOption.Pass pass = passOption.pass(spec, target);
        OutputFiles.checkWritableImage(target);

        long compileStart = System.nanoTime();
        Source source = ScriptCompilation.read(sceneFile);
        CompileResult result = ScriptCompilation.compile(source, options, err);
        long compileNanos = System.nanoTime() - compileStart;
        if (result.hasErrors()) return ExitCode.ofErrors(result);
        Scene scene = renderOptions.applyTo(result.scene());
        if (pass != PassOption.Pass.COLOR) return PassFiles.renderPass(scene, pass, target, renderOptions.quiet, err);

        long total = (long) scene.settings().width() * scene.settings().height();
        FrameJob.Outcome outcome;
        try (Cancellation cancel = Cancellation.install();
             Progress progress = Progress.start("Rendering", total, "px", renderOptions.quiet)) {
            progress.preparing("preparing the scene");
            outcome = FrameJob.run(scene, target, renderOptions.threads, cancel.monitor(progress));
        } catch (FrameFailure f) {
            throw new CliFailure(AnimateCommand.exitCode(f.kind()), f.getMessage());
        } catch (RenderCancelledException e) {
            err.println("crt: render cancelled; nothing was written");
            err.flush();
            return ExitCode.CANCELLED;
        }
        if (!renderOptions.quiet) {
            err.printf(Locale.ROOT, "crt: wrote %s (%d×%d) in %s%n", target, scene.settings().width(),
                    scene.settings().height(), seconds(compileNanos + outcome.stats().buildNanos()
                            + outcome.stats().renderNanos() + outcome.writeNanos()));
            err.flush();
        }
        if (renderOptions.stats) {
            StatsReport.print(out, compileNanos, outcome);
        }
        out.flush();
        return ExitCode.OK;
    }

    static Path defaultOutput(Path script) {
        String name = script.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return Path.of((dot > 0 ? name.substring(0, dot) : name) + ".png");
    }

    static String seconds(long nanos) { return String.format(Locale.ROOT, "%.3f s", nanos / 1e9); }
}
