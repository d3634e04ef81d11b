package dev.crt.cli;

import java.io.PrintWriter;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code crt} command: compiles and renders CRT scene scripts. */
@Command(name = "crt",
        mixinStandardHelpOptions = true,
        versionProvider = Main.Version.class,
        description = "CRT, the Cathode Ray Tracer: compile and render .crt scene scripts.",
        subcommands = {CheckCommand.class, RenderCommand.class, AnimateCommand.class, AccuracyCommand.class,
                CommandLine.HelpCommand.class},
        footer = {"", "Exit codes: 0 success, 1 the script has errors, 2 bad usage, 3 a file could not be read or written."})
public final class Main implements Runnable {
    /** A bug in CRT rather than a problem with the user's input (EX_SOFTWARE). */
    static final int INTERNAL_ERROR = 70;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a command is needed: check, render, animate or accuracy");
    }

    public static void main(String[] args) {
        useShippedAssets();
        System.exit(run(args));
    }

    /**
     * Points the compiler at the assets CRT ships (the {@code assets} folder beside
     * {@code target/}), unless {@code -Dcrt.assets} already names a folder.
     */
    static void useShippedAssets() {
        if (System.getProperty("crt.assets") != null) return;
        try {
            Path code = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            Path root = code.getParent() == null ? null : code.getParent().getParent();
            if (root != null && Files.isDirectory(root.resolve("assets"))) {
                System.setProperty("crt.assets", root.resolve("assets").toString());
            }
        } catch (URISyntaxException | SecurityException | IllegalArgumentException e) {
            // Without a known location the shipped assets are simply not searched.
        }
    }

    /** Runs crt with {@code args} on the process's stdout and stderr; returns the exit code. */
    public static int run(String... args) {
        return run(new PrintWriter(System.out, true), new PrintWriter(System.err, true), args);
    }

    /** Runs crt with {@code args}, printing results to {@code out} and diagnostics to {@code err}. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        CommandLine cl = new CommandLine(new Main());
        cl.setOut(out);
        cl.setErr(err);
        cl.setExecutionExceptionHandler((ex, line, parsed) -> {
            if (ex instanceof CliFailure f) {
                line.getErr().println("crt: " + f.getMessage());
                return f.exitCode();
            }
            line.getErr().println("crt: internal error (a bug in CRT, please report it): " + ex);
            ex.printStackTrace(line.getErr());
            return INTERNAL_ERROR;
        });
        return cl.execute(args);
    }

    /** The version from the jar's manifest, or "development" when run from classes. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"crt " + (v == null ? "development build" : v),
                    "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vm.name") + ")"};
        }
    }
}
