package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ProgressTest {
    @TempDir
    Path dir;

    @Test
    void aDescriptorIsATerminalWhenItLeadsToATerminalDevice() throws IOException {
        assumeTrue(Files.isDirectory(Path.of("/proc/self/fd")));
        assertThat(Progress.isTerminal(Files.createSymbolicLink(dir.resolve("pts"), Path.of("/dev/pts/3")))).isTrue();
        assertThat(Progress.isTerminal(Files.createSymbolicLink(dir.resolve("tty"), Path.of("/dev/tty1")))).isTrue();
        Path log = Files.writeString(dir.resolve("log.txt"), "");
        assertThat(Progress.isTerminal(Files.createSymbolicLink(dir.resolve("file"), log))).isFalse();
        assertThat(Progress.isTerminal(Files.createSymbolicLink(dir.resolve("pipe"), Path.of("pipe:[4242]")))).isFalse();
    }

    /**
     * Runs {@code crt render} on a small scene under {@code script}, so that it has a pseudo-terminal,
     * with {@code shellRedirect} appended to the command line; what the terminal showed goes to
     * {@code typescript}. Skips the test where no pseudo-terminal can be had.
     */
    private void renderOnATerminal(String shellRedirect, Path typescript) throws IOException, InterruptedException {
        assumeTrue(Files.isDirectory(Path.of("/proc/self/fd")) && Files.isExecutable(Path.of("/usr/bin/script")));
        Path scene = Files.writeString(dir.resolve("s.crt"), """
                Settings { camera -> Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) } width -> 200 height -> 150 }
                Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }
                """);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String command = "'" + java + "' -cp '" + System.getProperty("java.class.path") + "' dev.crt.cli.Main render '"
                + scene + "' -o '" + dir.resolve("s.png") + "' --threads 1" + shellRedirect;
        Process p = new ProcessBuilder("/usr/bin/script", "-qec", command, typescript.toString())
                .redirectInput(ProcessBuilder.Redirect.PIPE)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .redirectError(ProcessBuilder.Redirect.DISCARD)
                .start();
        p.getOutputStream().close();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assumeTrue(p.exitValue() == 0, "script could not run the command on a pseudo-terminal");
    }

    /** stdin and stdout on a terminal (so System.console() is there) but stderr into a file: no bar in the file. */
    @Test
    void noBarGoesToStderrRedirectedToAFileFromATerminal() throws IOException, InterruptedException {
        Path err = dir.resolve("err.txt");
        renderOnATerminal(" 2>'" + err + "'", Path.of("/dev/null"));
        assertThat(Files.readString(err)).doesNotContain("Rendering").doesNotContain("\r").startsWith("crt: wrote ");
    }

    /** On a terminal the bar says what it waits for while the scene is prepared, then counts pixels. */
    @Test
    void onATerminalTheBarShowsThePreparationThenThePixels() throws IOException, InterruptedException {
        Path typescript = dir.resolve("typescript.txt");
        renderOnATerminal("", typescript);
        String shown = Files.readString(typescript);
        assertThat(shown).contains("preparing the scene").contains("30000/30000").contains("crt: wrote ");
        // The message goes once the pixels are counted: the last state of the bar is without it.
        String last = shown.substring(shown.lastIndexOf("Rendering"));
        assertThat(last).doesNotContain("preparing").contains("100%");
    }
}
