package dev.crt.cli;

import dev.crt.studio.Studio;
import dev.crt.studio.StudioPaths;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code crt studio}: opens the desktop studio, where scripts are written and rendered. */
@Command(name = "studio", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {"Open the CRT studio: a docked editor for .crt scripts with live diagnostics,",
                "completion and a progressive render view (F5 renders, Esc cancels).",
                "Settings and layout: $XDG_CONFIG_HOME/crt (default ~/.config/crt).",
                "Unsaved text is kept in $XDG_STATE_HOME/crt/recovery (default ~/.local/state/crt/recovery)."},
        footer = {"", "Exit codes: 0 closed normally, 2 no graphical display (or bad usage)."})
final class StudioCommand implements Callable<Integer> {
    @Parameters(arity = "0..*", paramLabel = "SCENE", description = "Scene scripts (.crt) to open.")
    List<Path> scenes = List.of();

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws CliFailure {
        try {
            return Studio.run(scenes, StudioPaths.ofUser());
        } catch (Studio.NoDisplayException e) {
            // Not a mistake in the command line, so one sentence and no pointer to --help.
            spec.commandLine().getErr().println("crt: " + e.getMessage());
            spec.commandLine().getErr().flush();
            return ExitCode.USAGE;
        }
    }
}
