package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The two start-up modes the launcher uses, each in a studio process of its own: the ready report
 * ({@code crt.studio.quitWhenReady}, for the start-up benchmark) and the training run that makes the
 * studio's class-data archive without showing a window ({@code crt.studio.train}); then a studio
 * started from that archive.
 */
@Tag("gui")
class StudioStartGuiTest {
    @TempDir
    Path temp;

    @BeforeAll
    static void display() {
        GuiTestSupport.requireDisplay();
    }

    @Test
    void theStudioReportsWhenItIsPaintedAndQuitsWhenAskedTo() throws Exception {
        Path script = temp.resolve("ball.crt");
        Files.writeString(script, "Scene { Sphere { radius -> 1 } }\n");
        Run run = studio(testClassPath(), List.of("-Dcrt.studio.quitWhenReady=true"), script);
        assertThat(run.exit).as("exit code; it said:\n%s", run.output).isZero();
        assertThat(run.output).containsPattern("studio ready in \\d+ ms \\(\\d+ ms since the JVM started, \\d+ ms of CPU\\)");
    }

    @Test
    void aTrainingRunMakesAnArchiveTheStudioThenStartsFrom() throws Exception {
        // Class-data archives hold classes from jar files only: the compiled classes go into one.
        List<String> path = new ArrayList<>();
        path.add(jarOf(Path.of("target", "classes"), temp.resolve("crt.jar")).toString());
        for (String p : testClassPath()) if (Files.isRegularFile(Path.of(p))) path.add(p);
        Path script = temp.resolve("train.crt");
        Files.writeString(script, """
                Settings { camera -> Camera { position -> vec3(0, 2, -6) pointing -> vec3(0, 0, 0) } width -> 32 height -> 24 }
                Scene { Sphere { } - Box { cornerA -> vec3(0, 0, -2) cornerB -> vec3(2, 2, 2) } }
                """);
        Path archive = temp.resolve("studio.jsa");

        Run train = studio(path, List.of("-XX:ArchiveClassesAtExit=" + archive, "-Dcrt.studio.train=true"), script);
        assertThat(train.exit).as("training exit code; it said:\n%s", train.output).isZero();
        assertThat(archive).exists();
        assertThat(Files.size(archive)).as("archive size").isGreaterThan(1_000_000);
        byte[] bytes = Files.readAllBytes(archive);
        assertThat(contains(bytes, "dev/crt/studio/StudioWindow")).as("the studio's window class is archived").isTrue();
        assertThat(contains(bytes, "org/fife/ui/rsyntaxtextarea/RSyntaxTextArea")).as("the editor is archived").isTrue();

        Run start = studio(path, List.of("-XX:SharedArchiveFile=" + archive, "-Xshare:on", "-Dcrt.studio.quitWhenReady=true"), script);
        assertThat(start.exit).as("exit code of a start from the archive; it said:\n%s", start.output).isZero();
        assertThat(start.output).contains("studio ready in");
    }

    private record Run(int exit, String output) {}

    private Run studio(List<String> classPath, List<String> options, Path script) throws Exception {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.add("-Xss16m");
        command.add("-Djava.util.prefs.userRoot=" + temp.resolve("prefs"));
        command.addAll(options);
        command.add("-cp");
        command.add(String.join(java.io.File.pathSeparator, classPath));
        command.add("dev.crt.cli.Main");
        command.add("studio");
        command.add(script.toString());
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        Path output = Files.createTempFile(temp, "studio", ".txt");
        pb.redirectOutput(output.toFile());
        // Settings, recent files and recovery of a home of its own.
        pb.environment().put("XDG_CONFIG_HOME", temp.resolve("config").toString());
        pb.environment().put("XDG_STATE_HOME", temp.resolve("state").toString());
        Process p = pb.start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("the studio did not end in 120 s; it said:\n" + Files.readString(output));
        }
        return new Run(p.exitValue(), Files.readString(output, StandardCharsets.UTF_8));
    }

    private static List<String> testClassPath() {
        return List.of(System.getProperty("java.class.path").split(java.io.File.pathSeparator));
    }

    private static Path jarOf(Path classes, Path jar) throws IOException {
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out);
             Stream<Path> files = Files.walk(classes)) {
            for (Path f : (Iterable<Path>) files.filter(Files::isRegularFile)::iterator) {
                j.putNextEntry(new JarEntry(classes.relativize(f).toString().replace('\\', '/')));
                Files.copy(f, j);
                j.closeEntry();
            }
        }
        return jar;
    }

    private static boolean contains(byte[] haystack, String needle) {
        byte[] n = needle.getBytes(StandardCharsets.US_ASCII);
        outer:
        for (int i = 0; i + n.length <= haystack.length; i++) {
            for (int k = 0; k < n.length; k++) if (haystack[i + k] != n[k]) continue outer;
            return true;
        }
        return false;
    }
}
