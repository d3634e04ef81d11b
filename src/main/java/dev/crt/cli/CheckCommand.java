package dev.crt.cli;

import dev.crt.lang.CompileResult;
import dev.crt.lang.Source;
import dev.crt.scene.Scene;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code crt check}: compiles scripts and reports their diagnostics without rendering. */
@Command(name = "check", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {"Compile scene scripts and report errors and warnings without rendering.",
                "Diagnostics go to stderr, one summary line per file to stdout."},
        footer = {"", ExitCode.HELP_LINE})
final class CheckCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(arity = "1..*", paramLabel = "SCENE", description = "Scene scripts (.crt) to check; - reads the standard input.")
    List<Path> scenes;

    @Mixin
    ScriptOptions scriptOptions;

    @Mixin
    TimeOption timeOption;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        var options = OptionChecks.compileOptions(spec, scriptOptions, timeOption.time);
        int exit = ExitCode.OK;
        for (Path file : scenes) {
            Source source;
            try {
                source = ScriptCompilation.read(file);
            } catch (CliFailure f) {
                err.println("crt: " + f.getMessage());
                err.flush();
                out.println(file + ": not read");
                exit = Math.max(exit, f.exitCode());
                continue;
            }
            CompileResult result = ScriptCompilation.compile(source, options, err);
            out.println(summary(file, result));
            if (!result.hasErrors() && ShadingAdvice.looksLike2015(result.scene())) {
                err.println(ShadingAdvice.note(file));
                err.flush();
            }
            if (result.hasErrors()) exit = Math.max(exit, ExitCode.ofErrors(result));
        }
        out.flush();
        return exit;
    }

    static String summary(Path file, CompileResult result) {
        String warnings = count(result.warningCount(), "warning");
        if (result.hasErrors()) {
            return file + ": " + count(result.errorCount(), "error") + ", " + warnings;
        }
        Scene scene = result.scene();
        return file + ": ok, " + count(scene.entities().size(), "entity", "entities") + ", "
                + count(scene.settings().lights().size(), "light") + ", " + warnings;
    }

    static String count(long n, String one) { return count(n, one, one + "s"); }

    static String count(long n, String one, String many) { return n + " " + (n == 1 ? one : many); }
}
