package dev.crt.cli;

import dev.crt.image.AtomicFile;
import dev.crt.image.FrameBuffer;
import dev.crt.image.ImageFiles;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.Source;
import dev.crt.render.RenderCancelledException;
import dev.crt.render.Renderer;
import dev.crt.scene.Sampler;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code crt accuracy}: error against time for each pixel sampler, charted. */
@Command(name = "accuracy", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {"Chart error against render time for the pixel samplers on a scene.",
                "Renders a converged reference (cached), then the scene with each method at each budget, and writes "
                        + "accuracy.csv, rmse.png/.svg and ssim.png/.svg (error against time, Pareto front marked) "
                        + "and reference.png into the output folder."},
        footer = {"", "Budgets are samples per pixel: n×n sub-pixel samples (squares) for a scene without depth of field;",
                "with a lens, 2×2 sub-pixel samples times spp/4 lens samples (or 1 × spp when 4 does not divide it).",
                "", "Exit codes: 0 done, 1 the script has errors, 2 bad usage, 3 a file could not be read or written,",
                "130 interrupted (Ctrl-C), 143 terminated."})
final class AccuracyCommand implements Callable<Integer> {
    /** The longest side the study renders at unless told otherwise: error curves need no more. */
    static final int DEFAULT_WIDTH = 320;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE", description = "The scene script (.crt).")
    Path sceneFile;

    @Option(names = {"-o", "--output"}, paramLabel = "DIR",
            description = "Folder for the CSV and charts (default: accuracy-NAME in the current folder).")
    Path output;

    @Option(names = "--methods", paramLabel = "LIST", split = ",",
            description = "Samplers to compare (default: grid,jittered,sobol,adaptive).")
    List<String> methods = List.of("grid", "jittered", "sobol", "adaptive");

    @Option(names = "--budgets", paramLabel = "LIST", split = ",",
            description = "Samples per pixel to try (default: 1,4,16,64).")
    List<Integer> budgets = List.of(1, 4, 16, 64);

    @Option(names = "--reference-spp", paramLabel = "N",
            description = "Samples per pixel of the reference, rendered with the Sobol sampler (default: ${DEFAULT-VALUE}).")
    int referenceSpp = 1024;

    @Option(names = "--width", paramLabel = "W",
            description = "Image width (default: the scene's, scaled down to " + DEFAULT_WIDTH + " keeping its shape).")
    Integer width;

    @Option(names = "--height", paramLabel = "H", description = "Image height (default: the scene's shape at the width).")
    Integer height;

    @Option(names = "--noise", paramLabel = "LEVELS",
            description = "The adaptive sampler's target, in 8-bit levels (default: ${DEFAULT-VALUE}).")
    double noise = Settings.DEFAULT_NOISE;

    @Option(names = "--threads", paramLabel = "N", description = "Render threads; 0 uses every core (default: ${DEFAULT-VALUE}).")
    int threads = 0;

    @Option(names = "--no-cache", description = "Render the reference again even when a cached one exists.")
    boolean noCache;

    @Option(names = "--replot", description = "Render nothing: draw the charts again from the output folder's accuracy.csv.")
    boolean replot;

    @Mixin
    ScriptOptions scriptOptions;

    @Mixin
    TimeOption timeOption;

    @Override
    public Integer call() throws CliFailure {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (replot) return replot(err);
        List<Sampler> samplers = samplers();
        if (budgets.isEmpty()) throw new ParameterException(spec.commandLine(), "--budgets needs at least one budget");
        OptionChecks.requireAtLeast(spec, width, 1, "--width");
        OptionChecks.requireAtLeast(spec, height, 1, "--height");
        OptionChecks.requireAtLeast(spec, threads, 0, "--threads");
        if (!(noise > 0 && noise < Double.POSITIVE_INFINITY)) {
            throw new ParameterException(spec.commandLine(), "--noise must be a positive number of 8-bit levels, not " + noise);
        }
        CompileOptions options = OptionChecks.compileOptions(spec, scriptOptions, timeOption.time);
        Source source = ScriptCompilation.read(sceneFile);
        CompileResult result = ScriptCompilation.compile(source, options, err);
        if (result.hasErrors()) return ExitCode.ofErrors(result);
        Scene scene = sized(result.scene());
        boolean lens = AccuracyStudy.hasLens(scene);
        try {
            for (int b : budgets) AccuracyStudy.split(b, lens);
            AccuracyStudy.split(referenceSpp, lens);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        Path dir = output != null ? output : Path.of("accuracy-" + stem(sceneFile));
        prepareFolder(dir);

        Settings s = scene.settings();
        err.printf(Locale.ROOT, "crt: %s at %d×%d%s; methods %s; budgets %s spp%n", sceneFile, s.width(), s.height(),
                lens ? " (with depth of field)" : "", String.join(", ", samplers.stream().map(Sampler::word).toList()),
                budgets);
        err.flush();
        List<AccuracyStudy.Point> points;
        FrameBuffer reference;
        try (Cancellation cancel = Cancellation.install()) {
            reference = reference(source, scene, cancel, err);
            points = AccuracyStudy.run(scene, reference, samplers, budgets, noise, threads,
                    cancel.monitor(Progress.NONE), new AccuracyStudy.Listener() {
                        @Override
                        public void rendering(String what) {
                            err.println("crt: rendering " + what);
                            err.flush();
                        }

                        @Override
                        public void measured(AccuracyStudy.Point p) {
                            out.printf(Locale.ROOT, "%-9s %5d spp  %8.3f s  RMSE %7.3f  SSIM %.5f%n", p.sampler().word(),
                                    p.samplesPerPixel(), p.seconds(), p.rmse(), p.ssim());
                            out.flush();
                        }
                    });
        } catch (RenderCancelledException e) {
            err.println("crt: cancelled; the cached reference and earlier results are kept, no chart was written");
            err.flush();
            return 130;
        }
        try {
            writeCsv(points, dir.resolve("accuracy.csv"));
            charts(points, stem(sceneFile) + ", " + s.width() + "×" + s.height(), dir);
            ImageFiles.write(reference, dir.resolve("reference.png"), s.outputGamma(), Map.of("Software", "CRT accuracy reference"));
        } catch (IOException e) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot write into " + dir + ": " + ScriptCompilation.plain(e));
        }
        err.println("crt: wrote " + dir.resolve("accuracy.csv") + ", rmse.png/.svg, ssim.png/.svg and reference.png");
        err.flush();
        return ExitCode.OK;
    }

    private static void charts(List<AccuracyStudy.Point> points, String title, Path dir) throws IOException {
        AccuracyChart.write(points, title + ": RMSE against time", "RMSE (8-bit levels)", AccuracyStudy.Point::rmse,
                AccuracyStudy.Point::paretoRmse, dir.resolve("rmse"));
        AccuracyChart.write(points, title + ": 1 − SSIM against time", "1 − SSIM", p -> 1 - p.ssim(),
                AccuracyStudy.Point::paretoSsim, dir.resolve("ssim"));
    }

    /** Draws the charts again from the CSV an earlier study wrote into the output folder. */
    private int replot(PrintWriter err) throws CliFailure {
        Path dir = output != null ? output : Path.of("accuracy-" + stem(sceneFile));
        Path csv = dir.resolve("accuracy.csv");
        List<AccuracyStudy.Point> points = new ArrayList<>();
        try {
            List<String> rows = Files.readAllLines(csv, StandardCharsets.UTF_8);
            for (String row : rows.subList(1, rows.size())) {
                String[] f = row.split(",");
                Sampler m = Sampler.of(f[0]).orElseThrow(() -> new IllegalArgumentException("unknown method " + f[0]));
                points.add(new AccuracyStudy.Point(m, Integer.parseInt(f[1]), Integer.parseInt(f[2]), Integer.parseInt(f[3]),
                        Double.parseDouble(f[4]), Long.parseLong(f[5]), Long.parseLong(f[6]), Double.parseDouble(f[7]),
                        Double.parseDouble(f[8]), false, false));
            }
            charts(AccuracyStudy.markPareto(points), stem(sceneFile), dir);
        } catch (IOException e) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot replot from " + csv + ": " + ScriptCompilation.plain(e));
        } catch (RuntimeException e) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot replot from " + csv + ": it is not a CSV crt accuracy wrote ("
                    + e.getMessage() + ")");
        }
        err.println("crt: drew " + dir.resolve("rmse.png") + " and ssim.png again from " + csv);
        err.flush();
        return ExitCode.OK;
    }

    private static String stem(Path script) {
        String name = script.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(0, dot) : name;
    }

    private List<Sampler> samplers() {
        List<Sampler> list = new ArrayList<>();
        for (String m : methods) {
            Sampler k = Sampler.of(m.trim()).orElseThrow(() -> new ParameterException(spec.commandLine(),
                    "--methods takes grid, jittered, sobol and adaptive, not '" + m + "'"));
            if (!list.contains(k)) list.add(k);
        }
        if (list.isEmpty()) throw new ParameterException(spec.commandLine(), "--methods needs at least one method");
        return list;
    }

    /** The scene at the study's size: the options', or the scene's scaled to the default width. */
    private Scene sized(Scene scene) {
        Settings s = scene.settings();
        int w = width != null ? width : Math.min(s.width(), DEFAULT_WIDTH);
        int h = height != null ? height : Math.max(1, (int) Math.round((double) w * s.height() / s.width()));
        if (w < 11 || h < 11) {
            throw new ParameterException(spec.commandLine(), "the study needs pictures of at least 11×11 pixels (SSIM's window), got "
                    + w + "×" + h);
        }
        return scene.withSettings(s.withSize(w, h));
    }

    private FrameBuffer reference(Source source, Scene scene, Cancellation cancel, PrintWriter err) throws CliFailure {
        Settings s = scene.settings();
        ReferenceCache cache = new ReferenceCache(ReferenceCache.defaultFolder());
        String version = Main.class.getPackage().getImplementationVersion();
        String key = ReferenceCache.key(source.text(), Double.toString(timeOption.time), s.width() + "×" + s.height(),
                Integer.toString(referenceSpp), String.valueOf(scriptOptions.assetDirs), version == null ? "dev" : version,
                "reference seed " + AccuracyStudy.REFERENCE_SEED);
        if (!noCache) {
            FrameBuffer cached = cache.load(key);
            if (cached != null && cached.width() == s.width() && cached.height() == s.height()) {
                err.println("crt: using the cached reference " + cache.file(key));
                err.flush();
                return cached;
            }
        }
        Scene ref = AccuracyStudy.reference(scene, referenceSpp, noise);
        long total = (long) s.width() * s.height();
        FrameBuffer image;
        try (Progress progress = Progress.start("Reference (" + referenceSpp + " spp)", total, "px", false)) {
            image = Renderer.prepare(ref).render(threads, cancel.monitor(progress));
        }
        try {
            cache.store(key, image);
        } catch (IOException e) {
            err.println("crt: warning: could not cache the reference (" + ScriptCompilation.plain(e) + "); it will be rendered again next time");
            err.flush();
        }
        return image;
    }

    private static void prepareFolder(Path dir) throws CliFailure {
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot write into " + dir + ": it is a file, not a folder");
        }
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot create the folder " + dir + ": " + ScriptCompilation.plain(e));
        }
    }

    private static void writeCsv(List<AccuracyStudy.Point> points, Path file) throws IOException {
        StringBuilder b = new StringBuilder(
                "method,spp,supersampling,dofsamples,seconds,primary_rays,total_rays,rmse,ssim,pareto_rmse,pareto_ssim\n");
        for (AccuracyStudy.Point p : points) {
            b.append(String.format(Locale.ROOT, "%s,%d,%d,%d,%.6f,%d,%d,%.6f,%.8f,%b,%b%n", p.sampler().word(),
                    p.samplesPerPixel(), p.supersampling(), p.dofSamples(), p.seconds(), p.primaryRays(), p.totalRays(),
                    p.rmse(), p.ssim(), p.paretoRmse(), p.paretoSsim()));
        }
        byte[] bytes = b.toString().getBytes(StandardCharsets.UTF_8);
        AtomicFile.write(file, out -> out.write(bytes));
    }
}
