package dev.crt;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;
import org.junit.jupiter.api.io.TempDir;

/**
 * The build step that rewrites the jar's Java 5 class files as Java 8 ones
 * (src/build/UpgradeClassFiles.java), run as Maven runs it: a Java source file with ASM on its
 * class path, on a jar of the libraries that need it (picocli, DockingFrames). The rewritten
 * classes must link, the JVM's type-checking verifier reading their new frames, exactly as the
 * originals do; everything else in the jar stays byte for byte.
 */
class UpgradeClassFilesTest {
    private static final Path STEP = Path.of("src/build/UpgradeClassFiles.java");

    @TempDir
    Path dir;

    @Test
    void oldClassFilesBecomeJavaEightAndLinkAsBefore() throws Exception {
        Path original = dir.resolve("original.jar");
        merge(original, jarOf(picocli.CommandLine.class), jarOf(bibliothek.gui.DockController.class),
                jarOf(bibliothek.gui.dock.common.CControl.class));
        Path jar = Files.copy(original, dir.resolve("libraries.jar"));
        Map<String, byte[]> before = entries(original);
        long old = before.entrySet().stream().filter(e -> isClass(e.getKey()) && major(e.getValue()) < 50).count();
        assertThat(old).as("Java 5 class files in picocli and DockingFrames").isGreaterThan(2500);

        Run run = run(jar);
        assertThat(run.exit).as(run.output).isZero();
        assertThat(run.output).contains(String.format("%,d class files older than Java 6 rewritten", old))
                .doesNotContain("kept as");

        Map<String, byte[]> after = entries(jar);
        assertThat(after.keySet()).containsExactlyElementsOf(before.keySet());
        for (Map.Entry<String, byte[]> e : before.entrySet()) {
            byte[] now = after.get(e.getKey());
            if (isClass(e.getKey()) && major(e.getValue()) < 50) {
                assertThat(major(now)).as(e.getKey()).isEqualTo(52);
            } else {
                assertThat(now).as(e.getKey()).isEqualTo(e.getValue());
            }
        }
        assertThat(linkAll(jar)).isEqualTo(linkAll(original));

        // A second run finds nothing left to do and changes nothing.
        Run again = run(jar);
        assertThat(again.exit).as(again.output).isZero();
        assertThat(again.output).contains(": 0 class files older than Java 6 rewritten");
        Map<String, byte[]> third = entries(jar);
        for (String name : after.keySet()) assertThat(third.get(name)).as(name).isEqualTo(after.get(name));
    }

    @Test
    void aClassWithoutComputableFramesIsKeptAndNamed() throws Exception {
        // A Java 5 class whose method calls a subroutine (jsr/ret, which javac stopped writing
        // long ago but old compilers wrote): frames cannot describe it, so it stays as it was.
        ClassWriter old = new ClassWriter(0);
        old.visit(Opcodes.V1_5, Opcodes.ACC_PUBLIC | Opcodes.ACC_SUPER, "legacy/Subroutine", null, "java/lang/Object", null);
        MethodVisitor m = old.visitMethod(Opcodes.ACC_PUBLIC | Opcodes.ACC_STATIC, "run", "()I", null, null);
        m.visitCode();
        Label sub = new Label();
        m.visitJumpInsn(Opcodes.JSR, sub);
        m.visitInsn(Opcodes.ICONST_1);
        m.visitInsn(Opcodes.IRETURN);
        m.visitLabel(sub);
        m.visitVarInsn(Opcodes.ASTORE, 0);
        m.visitVarInsn(Opcodes.RET, 0);
        m.visitMaxs(1, 1);
        m.visitEnd();
        old.visitEnd();
        byte[] legacy = old.toByteArray();
        Path jar = dir.resolve("mixed.jar");
        try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(jar))) {
            out.putNextEntry(new ZipEntry("legacy/Subroutine.class"));
            out.write(legacy);
            out.closeEntry();
            out.putNextEntry(new ZipEntry("picocli/CommandLine$Range.class"));
            try (InputStream in = picocli.CommandLine.class.getResourceAsStream("CommandLine$Range.class")) {
                in.transferTo(out);
            }
            out.closeEntry();
        }
        Run run = run(jar);
        assertThat(run.exit).as(run.output).isZero();
        assertThat(run.output).contains(": 1 class file older than Java 6 rewritten")
                .contains("1 kept as it was").contains("legacy/Subroutine.class");
        Map<String, byte[]> after = entries(jar);
        assertThat(after.get("legacy/Subroutine.class")).isEqualTo(legacy);
        assertThat(major(after.get("picocli/CommandLine$Range.class"))).isEqualTo(52);
    }

    @Test
    void aMissingJarIsSaidPlainly() throws Exception {
        Run run = run(dir.resolve("absent.jar"));
        assertThat(run.exit).isEqualTo(3);
        assertThat(run.output).contains("no such jar").contains("absent.jar");
        assertThat(dir.resolve("absent.jar.upgrading")).doesNotExist();
    }

    private record Run(int exit, String output) {}

    private Run run(Path jar) throws IOException, InterruptedException, URISyntaxException {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Path asm = jarOf(org.objectweb.asm.ClassWriter.class);
        Path log = dir.resolve("log");
        Process p = new ProcessBuilder(java.toString(), "-cp", asm.toString(), STEP.toString(), jar.toString())
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        return new Run(p.exitValue(), Files.readString(log));
    }

    /**
     * Loads and initialises every class of the jar in a loader of its own; per class, "ok" or the
     * error it gave. A class whose frames were wrong fails to link with a VerifyError, one whose
     * flags were wrong with a ClassFormatError; classes that need a library not in the jar, or a
     * display, fail alike before and after.
     */
    private static Map<String, String> linkAll(Path jar) throws IOException {
        Map<String, String> outcome = new LinkedHashMap<>();
        try (URLClassLoader loader = new URLClassLoader(new URL[] {jar.toUri().toURL()}, ClassLoader.getPlatformClassLoader());
                ZipFile zip = new ZipFile(jar.toFile())) {
            for (ZipEntry e : Collections.list(zip.entries())) {
                if (!isClass(e.getName())) continue;
                String name = e.getName().substring(0, e.getName().length() - ".class".length()).replace('/', '.');
                try {
                    Class.forName(name, true, loader);
                    outcome.put(name, "ok");
                } catch (Throwable t) {
                    outcome.put(name, t.getClass().getName());
                }
            }
        }
        assertThat(outcome.values()).doesNotContain(VerifyError.class.getName(), ClassFormatError.class.getName());
        return outcome;
    }

    private static boolean isClass(String name) {
        return name.endsWith(".class") && !name.startsWith("META-INF/") && !name.equals("module-info.class");
    }

    private static int major(byte[] classFile) {
        return (classFile[6] & 0xff) << 8 | (classFile[7] & 0xff);
    }

    private static Path jarOf(Class<?> c) throws URISyntaxException {
        return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    /** The entries of the jars in one jar, the first of a name kept (their manifests, licences). */
    private static void merge(Path to, Path... jars) throws IOException {
        Set<String> seen = new HashSet<>();
        try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(to))) {
            for (Path jar : jars) {
                try (ZipFile zip = new ZipFile(jar.toFile())) {
                    for (ZipEntry e : Collections.list(zip.entries())) {
                        if (!seen.add(e.getName())) continue;
                        out.putNextEntry(new ZipEntry(e.getName()));
                        try (InputStream in = zip.getInputStream(e)) {
                            in.transferTo(out);
                        }
                        out.closeEntry();
                    }
                }
            }
        }
    }

    private static Map<String, byte[]> entries(Path jar) throws IOException {
        Map<String, byte[]> all = new LinkedHashMap<>();
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            List<ZipEntry> list = new ArrayList<>(Collections.list(zip.entries()));
            for (ZipEntry e : list) {
                try (InputStream in = zip.getInputStream(e)) {
                    all.put(e.getName(), in.readAllBytes());
                }
            }
        }
        return all;
    }
}
