package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The command line registers only the command its arguments name (picocli reads every option of
 * every registered command when the command line is made), none for the version alone, and every
 * command otherwise: for help, for no command, and for a mistyped one.
 */
class CommandRegistrationTest {
    private static final List<String> ALL = List.of("check", "render", "animate", "accuracy", "preview", "studio", "help");

    @Test
    void aNamedCommandIsTheOnlyOneRegisteredAndHelpsAsBefore() {
        for (String name : ALL) {
            if (name.equals("help")) continue;
            assertThat(Main.commandLine(name, "scene.crt").getSubcommands().keySet()).as(name).containsExactly(name);
            StringWriter out = new StringWriter(), err = new StringWriter();
            int code = Main.run(new PrintWriter(out, true), new PrintWriter(err, true), name, "--help");
            assertThat(code).as(err.toString()).isZero();
            assertThat(out.toString()).startsWith("Usage: crt " + name + " ");
        }
    }

    @Test
    void withoutACommandNameEveryCommandIsRegisteredInHelpsOrder() {
        for (String[] args : List.of(new String[0], new String[] {"help"}, new String[] {"help", "render"},
                new String[] {"--help"}, new String[] {"-V", "render"}, new String[] {"rendr", "x.crt"})) {
            assertThat(Main.commandLine(args).getSubcommands().keySet()).as(String.join(" ", args)).containsExactlyElementsOf(ALL);
        }
        StringWriter out = new StringWriter(), err = new StringWriter();
        assertThat(Main.run(new PrintWriter(out, true), new PrintWriter(err, true), "--help")).isZero();
        assertThat(out.toString()).contains("Commands:", "  check ", "  render ", "  animate ", "  accuracy ", "  preview ",
                "  studio ", "  help ");
        // The version alone registers no command and prints what it printed.
        for (String flag : List.of("--version", "-V")) {
            assertThat(Main.commandLine(flag).getSubcommands()).as(flag).isEmpty();
            StringWriter version = new StringWriter();
            assertThat(Main.run(new PrintWriter(version, true), new PrintWriter(err, true), flag)).isZero();
            assertThat(version.toString()).startsWith("crt ").contains("Java ");
        }
        StringWriter helpOut = new StringWriter();
        assertThat(Main.run(new PrintWriter(helpOut, true), new PrintWriter(err, true), "help", "animate")).isZero();
        assertThat(helpOut.toString()).startsWith("Usage: crt animate ");
    }
}
