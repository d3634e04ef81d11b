package dev.crt;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.ZipFile;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The ./crt launcher on a fresh clone: two runs started together build the jar once (the second
 * waits on the first's lock, then runs) and compile no test or benchmark code. One build of the
 * main code with Maven: about 25 s on the shared 2-core machine.
 */
class LauncherTest {
    @TempDir
    Path clone;

    private static void copy(Path from, Path to) throws IOException {
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Path target = to.resolve(from.relativize(f).toString());
                if (Files.isDirectory(f)) Files.createDirectories(target);
                else Files.copy(f, target);
            }
        }
    }

    @Test
    void twoFirstRunsAtOnceBuildOnceAndBothRun() throws Exception {
        Path repo = Path.of("").toAbsolutePath();
        for (String part : List.of("pom.xml", "crt", "grammar", "src/main", "src/build")) copy(repo.resolve(part), clone.resolve(part));
        clone.resolve("crt").toFile().setExecutable(true);
        Path script = Files.writeString(clone.resolve("a.crt"), "Scene { Sphere { } }\n");
        Process first = start(script, "1");
        Thread.sleep(500);
        Process second = start(script, "2");
        assertThat(first.waitFor(240, TimeUnit.SECONDS)).isTrue();
        assertThat(second.waitFor(240, TimeUnit.SECONDS)).isTrue();
        String err = Files.readString(clone.resolve("err1")) + Files.readString(clone.resolve("err2"));
        assertThat(first.exitValue()).as(err).isZero();
        assertThat(second.exitValue()).as(err).isZero();
        assertThat(err.split("crt: building target/crt.jar", -1)).as(err).hasSize(2);
        assertThat(Files.readString(clone.resolve("out1"))).contains("a.crt: ok");
        assertThat(Files.readString(clone.resolve("out2"))).contains("a.crt: ok");
        assertThat(clone.resolve("target/crt.jar")).isRegularFile();
        assertThat(clone.resolve("target/test-classes")).doesNotExist();
        // The build's last step rewrote picocli's Java 5 class files as Java 8 ones, which the
        // start-up cache can hold (src/build/UpgradeClassFiles.java).
        try (ZipFile jar = new ZipFile(clone.resolve("target/crt.jar").toFile())) {
            byte[] head = jar.getInputStream(jar.getEntry("picocli/CommandLine.class")).readNBytes(8);
            assertThat((head[6] & 0xff) << 8 | (head[7] & 0xff)).as("picocli's class file version in the jar").isEqualTo(52);
        }
        // The training render made a start-up cache: one that fails (a training scene the compiler
        // refuses) leaves none, and nothing else says so.
        try (Stream<Path> made = Files.list(clone.resolve("target"))) {
            assertThat(made.map(p -> p.getFileName().toString()))
                    .anyMatch(name -> name.startsWith("crt-") && (name.endsWith(".aot") || name.endsWith(".jsa")));
        }
        // It compiled a written-out scene large enough for the lexer and the number reader to reach
        // the JIT's top tier in training (docs/benchmarks.md, section 36): 4,000 objects, each with
        // its own material.
        // It comes after the scene made by a loop (a large written-out scene before it slowed later
        // compiles of loops).
        String training = Files.readString(clone.resolve("target/cds-train/train.crt"));
        assertThat(training.split("material -> Material \\{", -1)).hasSizeGreaterThan(4000);
        assertThat(training.indexOf("while (i < n)")).isPositive().isLessThan(training.indexOf("material -> Material {"));

        // The start-up cache the first run made is the one later runs can use: the JVM refuses a
        // cache made with other options (it did, silently, for every render on Java 25), and says
        // so only when its log asks for warnings.
        ProcessBuilder third = new ProcessBuilder("bash", clone.resolve("crt").toString(), "--version")
                .directory(clone.toFile())
                .redirectErrorStream(true)
                .redirectOutput(clone.resolve("out3").toFile());
        third.environment().put("CRT_JAVA_OPTS", "-Xss16m -Xlog:aot=warning -Xlog:cds=warning");
        Process run = third.start();
        assertThat(run.waitFor(120, TimeUnit.SECONDS)).isTrue();
        String out = Files.readString(clone.resolve("out3"));
        assertThat(run.exitValue()).as(out).isZero();
        assertThat(out).as("the JVM's word on the start-up cache").contains("crt ").doesNotContainIgnoringCase("error")
                .doesNotContain("Unable to map").doesNotContain("mismatch");

        // Batch commands run with the throughput collector, tenuring at once, and transparent huge
        // pages where the kernel gives them on request (docs/benchmarks.md, section 40); a
        // collector or page setting in CRT_JAVA_OPTS is left alone.
        Path setting = Path.of("/sys/kernel/mm/transparent_hugepage/enabled");
        boolean onRequest = Files.isReadable(setting) && Files.readString(setting).contains("[madvise]");
        String flags = flags(script, "-Xss16m -XX:+PrintCommandLineFlags");
        assertThat(flags).contains("-XX:+UseParallelGC", "-XX:MaxTenuringThreshold=0");
        if (onRequest) assertThat(flags).contains("-XX:+UseTransparentHugePages");
        else assertThat(flags).doesNotContain("UseTransparentHugePages");
        assertThat(flags(script, "-Xss16m -XX:+UseG1GC -XX:-UseTransparentHugePages -XX:+PrintCommandLineFlags"))
                .contains("-XX:+UseG1GC", "-XX:-UseTransparentHugePages")
                .doesNotContain("UseParallelGC", "MaxTenuringThreshold=0", "+UseTransparentHugePages");
    }

    /** What {@code crt check} prints with CRT_JAVA_OPTS set to {@code options}. */
    private String flags(Path script, String options) throws Exception {
        ProcessBuilder check = new ProcessBuilder("bash", clone.resolve("crt").toString(), "check", script.toString())
                .directory(clone.toFile())
                .redirectErrorStream(true)
                .redirectOutput(clone.resolve("flags").toFile());
        check.environment().put("CRT_JAVA_OPTS", options);
        Process run = check.start();
        assertThat(run.waitFor(120, TimeUnit.SECONDS)).isTrue();
        String out = Files.readString(clone.resolve("flags"));
        assertThat(run.exitValue()).as(out).isZero();
        assertThat(out).contains("a.crt: ok");
        return out;
    }

    private Process start(Path script, String n) throws IOException {
        return new ProcessBuilder("bash", clone.resolve("crt").toString(), "check", script.toString())
                .directory(clone.toFile())
                .redirectOutput(clone.resolve("out" + n).toFile())
                .redirectError(clone.resolve("err" + n).toFile())
                .start();
    }
}
