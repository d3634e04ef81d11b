package dev.crt.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;

/** {@code crt animate}: renders a range of frames of a script that uses t. */
@Command(name = "animate", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "Render animation frames (not available yet: issue 4).")
final class AnimateCommand implements Callable<Integer> {
    @Override
    public Integer call() throws CliFailure {
        throw new CliFailure(ExitCode.USAGE, "crt animate is not available yet");
    }
}
