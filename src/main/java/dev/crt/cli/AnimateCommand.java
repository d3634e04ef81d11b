package dev.crt.cli;

import dev.crt.animation.AnimationRun;
import dev.crt.animation.AnimationTotals;
import dev.crt.animation.FrameFailure;
import dev.crt.animation.FrameRange;
import dev.crt.animation.FramePattern;
import dev.crt.animation.GifAssembly;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.Source;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code crt animate}: renders a range of frames of a script that uses t, each frame an independent, restartable unit. */
@Command(name = "animate", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {"Render the frames of an animation. t is the frame number and the script is compiled afresh for "
                + "each frame. Every frame is written atomically, so a killed run can be finished with --resume, and "
                + "--shard I/N splits the frames among N runs on any machines (see docs/animation.md)."},
        footer = {"", "Examples:",
                "  crt animate orbit.crt --frames 0..47 -o frames/orbit_%%04d.png --gif orbit.gif",
                "  crt animate orbit.crt --frames 0..999 -o /farm/%%04d.png --shard 3/10 --resume",
                "",
                "Frame files that exist already are a file error (3) without --resume or --force.",
                ExitCode.HELP_LINE})
final class AnimateCommand implements Callable<Integer> {
    /** The exit code of a run stopped by Ctrl-C, as shells report a SIGINT. */
    static final int CANCELLED = ExitCode.CANCELLED;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE", description = "The scene script (.crt), or - for the standard input; t is the frame number.")
    Path sceneFile;

    @Option(names = "--frames", required = true, paramLabel = "A..B[:STEP]",
            description = "The frames to render: A to B inclusive, every STEP-th (default 1), such as 0..99 or 0..98:2.")
    String frames;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "PATTERN",
            description = "Frame file names with the frame number as %%d or %%04d (frames/f_%%04d.png); .png, .ppm or .pfm. Folders are created.")
    String output;

    @Option(names = "--gif", paramLabel = "FILE",
            description = "Also write a looping animated GIF of every frame of the range that exists after the run.")
    Path gif;

    @Option(names = "--fps", paramLabel = "N", description = "GIF frames per second, up to 50 (default: 25).")
    Double fps;

    @Option(names = "--shard", paramLabel = "I/N",
            description = "Render only shard I of N (I from 0 to N-1): the frames whose position in the range is I modulo N.")
    String shard;

    @ArgGroup(exclusive = true)
    Existing existing = new Existing();

    /** What to do with frames whose files exist already. */
    static final class Existing {
        @Option(names = "--resume", description = "Skip frames whose files exist: finish a run that was killed or failed.")
        boolean resume;

        @Option(names = "--force", description = "Render every frame again, replacing files that exist.")
        boolean force;
    }

    @Option(names = "--keep-going", description = "After a frame fails, render the remaining frames and report every failure at the end.")
    boolean keepGoing;

    @Option(names = "--jobs", paramLabel = "J",
            description = "Frames rendered at once (default: ${DEFAULT-VALUE}); each gets max(1, threads/J) render threads.")
    int jobs = 1;

    @Mixin
    ScriptOptions scriptOptions;

    /** Not an option of animate (t is the frame number); accepted only to say so plainly. */
    @Option(names = "--time", hidden = true)
    Double time;

    @Mixin
    RenderOptions renderOptions;

    @Override
    public Integer call() throws CliFailure {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Plan plan = checkUsage();
        CompileOptions options = OptionChecks.compileOptions(spec, scriptOptions, 0);
        Source source = ScriptCompilation.read(sceneFile);

        List<AnimationRun.Frame> owned = plan.ownedFrames();
        List<Path> ownedFiles = owned.stream().map(AnimationRun.Frame::file).toList();
        List<Path> touched = new ArrayList<>(ownedFiles);
        if (gif != null) touched.add(gif);
        FrameFiles.prepareFolders(touched);
        List<Path> found = FrameFiles.existing(ownedFiles);
        if (!existing.resume && !existing.force) refuseToOverwrite(found, owned.size());
        int leftovers = FrameFiles.removeLeftovers(touched);
        if (leftovers > 0 && !renderOptions.quiet) {
            err.println("crt: removed " + CheckCommand.count(leftovers, "temporary file") + " that an interrupted run left");
        }
        Set<Path> kept = existing.resume ? new HashSet<>(found) : Set.of();
        List<AnimationRun.Frame> todo = owned.stream().filter(f -> !kept.contains(f.file())).toList();
        int skipped = owned.size() - todo.size();

        int threads = renderOptions.threads > 0 ? renderOptions.threads : Runtime.getRuntime().availableProcessors();
        AnimationRun run = new AnimationRun(source, options, renderOptions::applyTo, jobs, Math.max(1, threads / jobs),
                keepGoing, text -> {
                    synchronized (err) {
                        err.print(text);
                        err.flush();
                    }
                });
        AnimationRun.Outcome outcome;
        int exit;
        // Ctrl-C waits for the summary too, so a cancelled run still says what it left.
        try (Cancellation cancel = Cancellation.install()) {
            try (AnimationProgress progress = AnimationProgress.start(todo.size(), renderOptions.quiet, err)) {
                outcome = run.run(todo, cancel::isCancelled, progress);
            }
            exit = report(plan, outcome, skipped, err);
            err.flush();
        }
        if (gif != null && exit != CANCELLED && (exit == ExitCode.OK || keepGoing)) {
            List<Path> frameFiles = FrameFiles.existing(plan.allFiles());
            if (frameFiles.isEmpty()) {
                err.println("crt: no GIF written: none of the frames exists");
                exit = Math.max(exit, ExitCode.FILE_ERROR);
            } else {
                try {
                    GifAssembly.write(gif, frameFiles, plan.fps());
                } catch (IOException e) {
                    throw new CliFailure(ExitCode.FILE_ERROR, "cannot write " + gif + ": " + ScriptCompilation.plain(e));
                }
                if (!renderOptions.quiet) {
                    err.printf(Locale.ROOT, "crt: wrote %s (%d frames at %s fps)%n", gif, frameFiles.size(), plan.fps());
                }
            }
        }
        if (renderOptions.stats) {
            printTotals(out, outcome.totals(), skipped, outcome.failures().size(), outcome.wallNanos());
        }
        out.flush();
        err.flush();
        return exit;
    }

    /** The checked command line: which frames, which of them are this run's, where they go. */
    private record Plan(FrameRange range, Shard shard, FramePattern pattern, double fps) {
        /** This run's frames: the shard's share of the range. */
        List<AnimationRun.Frame> ownedFrames() {
            List<AnimationRun.Frame> frames = new ArrayList<>();
            for (int k = 0; k < range.size(); k++) {
                if (shard.owns(k)) frames.add(new AnimationRun.Frame(range.frame(k), pattern.path(range.frame(k))));
            }
            return frames;
        }

        /** Every frame file of the range, in frame order, whichever shard renders it. */
        List<Path> allFiles() {
            List<Path> files = new ArrayList<>();
            for (int k = 0; k < range.size(); k++) files.add(pattern.path(range.frame(k)));
            return files;
        }
    }

    /** Every check that needs no file: a bad value is a usage error (exit code 2) before any work. */
    private Plan checkUsage() {
        renderOptions.validate(spec);
        if (time != null) {
            throw usage("--time does not apply to crt animate: t is the frame number (use crt render --time T for one frame)");
        }
        OptionChecks.requireBetween(spec, jobs, 1, RenderOptions.MAX_THREADS, "--jobs");
        FrameRange range;
        Shard share;
        FramePattern pattern;
        try {
            range = FrameRange.parse(frames);
            share = shard == null ? Shard.WHOLE : Shard.parse(shard);
            pattern = FramePattern.parse(output);
        } catch (IllegalArgumentException e) {
            throw usage(e.getMessage());
        }
        if (!OutputFiles.IMAGE_TYPES.contains(pattern.extension())) {
            throw usage("-o " + output + ": unsupported image type '" + (pattern.extension().isEmpty() ? "(none)" : "." + pattern.extension())
                    + "' (use .png, .ppm or .pfm)");
        }
        if (fps != null && gif == null) throw usage("--fps sets the speed of the GIF: give --gif FILE too");
        double rate = fps == null ? 25 : fps;
        if (gif != null) {
            if (!OutputFiles.extension(gif).equals("gif")) throw usage("--gif " + gif + ": the file name must end in .gif");
            if (pattern.extension().equals("pfm")) {
                throw usage("--gif needs frames in .png or .ppm: .pfm frames hold linear light, not display colours");
            }
            if (!(rate > 0 && rate <= 50)) {
                throw usage("--fps must be above 0 and at most 50 (GIF delays are whole hundredths of a second), got " + fps);
            }
            if (share.count() > 1) {
                throw usage("--gif with --shard would make each shard write a GIF of whatever frames exist; "
                        + "make the GIF after all shards finish: crt animate … --resume --gif FILE");
            }
        }
        return new Plan(range, share, pattern, rate);
    }

    private void refuseToOverwrite(List<Path> found, int owned) throws CliFailure {
        if (!found.isEmpty()) {
            throw new CliFailure(ExitCode.FILE_ERROR, found.size() + " of the " + owned + " frame files exist already ("
                    + found.get(0) + (found.size() > 1 ? ", …" : "") + "): use --resume to keep them and render the rest, "
                    + "or --force to render them again");
        }
        if (gif != null && Files.exists(gif)) {
            throw new CliFailure(ExitCode.FILE_ERROR, gif + " exists already: use --resume or --force to replace it");
        }
    }

    /** Prints the summary and failures to stderr and returns the run's exit code. */
    private int report(Plan plan, AnimationRun.Outcome outcome, int skipped, PrintWriter err) {
        long rendered = outcome.totals().frames();
        List<AnimationRun.Failure> failures = outcome.failures();
        // -q: no summary, even on a cancel; the one line below still says what was left.
        if (!renderOptions.quiet || !failures.isEmpty()) {
            err.printf(Locale.ROOT, "crt: frames %s%s: %d rendered, %d skipped, %d failed in %s (%.2f frames/s)%n",
                    plan.range(), plan.shard().count() > 1 ? " shard " + plan.shard() : "", rendered, skipped,
                    failures.size(), RenderCommand.seconds(outcome.wallNanos()),
                    AnimationTotals.framesPerSecond(rendered, outcome.wallNanos()));
        }
        if (outcome.cancelled()) {
            err.println("crt: cancelled; the frames written are complete: rerun with --resume to render the rest");
            return CANCELLED;
        }
        if (failures.isEmpty()) return ExitCode.OK;
        int exit = ExitCode.OK;
        for (AnimationRun.Failure f : failures) {
            err.printf("crt: frame %d failed: %s%n", f.frame(), f.reason());
            exit = Math.max(exit, exitCode(f.kind()));
        }
        if (!keepGoing) {
            err.println("crt: stopped at the first failure; the frames written are complete: "
                    + "rerun with --resume once it is fixed, or use --keep-going to render the other frames anyway");
        }
        return exit;
    }

    /** The exit code a frame failure calls for. */
    static int exitCode(FrameFailure.Kind kind) {
        return switch (kind) {
            case SCRIPT -> ExitCode.SCRIPT_ERROR;
            case MEMORY -> ExitCode.INTERNAL_ERROR;
            case SETTINGS -> ExitCode.USAGE;
            case FILE -> ExitCode.FILE_ERROR;
        };
    }

    /**
     * The {@code --stats} table: the render command's table over all frames, then frame counts,
     * the wall-clock time and the share of frame time spent outside tracing (compile, BVH, write).
     */
    private static void printTotals(PrintWriter out, AnimationTotals totals, int skipped, int failed, long wallNanos) {
        long frames = totals.frames();
        long compileNanos = totals.compileNanos();
        dev.crt.animation.FrameJob.Outcome sum = totals.sum();
        out.println("times and rays summed over " + frames + (frames == 1 ? " frame" : " frames"));
        StatsReport.print(out, compileNanos, sum);
        long renderNanos = sum.stats().renderNanos();
        long frameNanos = compileNanos + sum.stats().buildNanos() + renderNanos + sum.writeNanos();
        out.println("frames");
        out.printf(Locale.ROOT, "  %-10s %14d%n", "rendered", frames);
        out.printf(Locale.ROOT, "  %-10s %14d%n", "skipped", skipped);
        out.printf(Locale.ROOT, "  %-10s %14d%n", "failed", failed);
        out.printf(Locale.ROOT, "  %-10s %14.3f s%n", "wall clock", wallNanos / 1e9);
        out.printf(Locale.ROOT, "  %-10s %14.2f frames/s%n", "speed", AnimationTotals.framesPerSecond(frames, wallNanos));
        out.printf(Locale.ROOT, "  %-10s %14.1f %% (compile, bvh build and write of frame time)%n", "overhead",
                frameNanos == 0 ? 0 : 100.0 * (frameNanos - renderNanos) / frameNanos);
    }

    private ParameterException usage(String message) { return new ParameterException(spec.commandLine(), message); }
}
