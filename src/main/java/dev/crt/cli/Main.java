package dev.crt.cli;

import java.io.PrintWriter;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code crt} command: compiles and renders CRT scene scripts. */
@Command(name = "crt",
        mixinStandardHelpOptions = true,
        versionProvider = Main.Version.class,
        description = "CRT, the Cathode Ray Tracer: compile and render .crt scene scripts.",
        footer = {"", ExitCode.HELP_LINE})
public final class Main implements Runnable {
    /** A bug in CRT rather than a problem with the user's input (EX_SOFTWARE). */
    static final int INTERNAL_ERROR = ExitCode.INTERNAL_ERROR;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /** The commands, in the order help lists them (picocli's own {@code help} last). */
    private static final List<Class<?>> COMMANDS = List.of(CheckCommand.class, RenderCommand.class, AnimateCommand.class,
            AccuracyCommand.class, PreviewCommand.class, StudioCommand.class, CommandLine.HelpCommand.class);

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(),
                "a command is needed: check, render, animate, accuracy, preview or studio");
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
        CommandLine cl = commandLine(args);
        cl.setOut(out);
        cl.setErr(err);
        // As git and cargo do: the error, then where help is, not 40 lines of help burying the error.
        cl.setParameterExceptionHandler((ex, params) -> usageError(ex.getCommandLine(), describe(ex)));
        cl.setExecutionExceptionHandler((ex, line, parsed) -> {
            if (ex instanceof CliFailure f) {
                if (f.exitCode() == ExitCode.USAGE) return usageError(line, f.getMessage());
                line.getErr().println("crt: " + f.getMessage());
                return f.exitCode();
            }
            line.getErr().println("crt: internal error (a bug in CRT, please report it): " + ex);
            ex.printStackTrace(line.getErr());
            return INTERNAL_ERROR;
        });
        try {
            return cl.execute(args);
        } catch (OutOfMemoryError e) {
            return outOfMemory(err);
        }
    }

    /**
     * The command line for {@code args}: when they start with the name of a command other than
     * help, that command alone is registered, else all of them (help lists them all, and a
     * mistyped name is told from the list). picocli reads every option of every registered command
     * by reflection when the command line is made, and its classes cannot go in the JVM's start-up
     * cache (Java 5 class files): with every command registered, each run through the launcher
     * took about 0.08 s longer and 0.2 s more CPU (docs/benchmarks.md, section 40).
     */
    static CommandLine commandLine(String... args) {
        CommandLine cl = new CommandLine(new Main());
        String first = args.length > 0 ? args[0] : "";
        // The version alone needs no command (scripts and the launcher's callers ask for it to
        // see that crt runs): reading every command's options took half of its time.
        if (args.length == 1 && (first.equals("--version") || first.equals("-V"))) return cl;
        for (Class<?> command : COMMANDS) {
            String name = command.getAnnotation(Command.class).name();
            if (!name.equals(first) || name.equals("help")) continue;
            cl.addSubcommand(name, command);
            return cl;
        }
        for (Class<?> command : COMMANDS) cl.addSubcommand(command);
        return cl;
    }

    /** picocli's message, except for a mistyped command, which is named as one. */
    private static String describe(CommandLine.ParameterException ex) {
        if (ex instanceof CommandLine.UnmatchedArgumentException unmatched && ex.getCommandLine().getParent() == null
                && !unmatched.getUnmatched().isEmpty() && !unmatched.getUnmatched().get(0).startsWith("-")) {
            return "unknown command '" + unmatched.getUnmatched().get(0) + "' (the commands are check, render, animate and help)";
        }
        // Some of picocli's messages start with their own "Error: ", which would follow ours.
        String message = ex.getMessage();
        return message.startsWith("Error: ") ? message.substring("Error: ".length()) : message;
    }

    /** Prints "crt: error: …" and a pointer to the command's --help; the exit code of bad usage. */
    static int usageError(CommandLine line, String message) {
        PrintWriter err = line.getErr();
        err.println("crt: error: " + message);
        err.println("Try '" + line.getCommandSpec().qualifiedName() + " --help' for more information.");
        err.flush();
        return ExitCode.USAGE;
    }

    /**
     * The heap ran out although the render was estimated to fit (the estimate cannot see
     * everything): one sentence and the internal-error code, never a trace, never 1.
     */
    static int outOfMemory(PrintWriter err) {
        long max = Runtime.getRuntime().maxMemory();
        long suggest = Math.max(1, (2 * max + (1L << 30) - 1) >> 30);
        err.println("crt: error: out of memory: the Java heap of " + dev.crt.animation.MemoryCheck.gib(max) + " is too small for this"
                + " scene; give Java more (CRT_JAVA_OPTS=-Xmx" + suggest + "g ./crt …) or render a smaller image or scene");
        err.flush();
        return INTERNAL_ERROR;
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
