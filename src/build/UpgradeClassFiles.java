import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import java.util.zip.ZipOutputStream;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.Opcodes;

/**
 * A build step (run by Maven after the jar is shaded, see pom.xml): rewrites the class files of a
 * jar that are older than Java 6 (major version below 50) as Java 8 class files (52), with the
 * stack map frames the JVM's type-checking verifier reads; the code itself is unchanged.
 *
 * <p>Why: picocli and DockingFrames ship Java 5 class files. The JVM verifies those with its old
 * inferring verifier on every run, and its start-up caches (class-data sharing, Java 25's
 * ahead-of-time cache) cannot hold them, nor any class that depends on them: the command line's
 * classes were read from the jar and verified on every run of {@code crt}, and their lambdas were
 * spun anew (docs/benchmarks.md, section 41).
 *
 * <pre>java -cp asm.jar src/build/UpgradeClassFiles.java JAR</pre>
 *
 * The jar is rewritten through a temporary file and a rename, so a failure leaves it as it was.
 * A class file ASM cannot give frames to is kept as it is (and named): it runs as before.
 * Exit status: 0 done, 2 wrong arguments, 3 the jar could not be read or written.
 */
public final class UpgradeClassFiles {
    /** Java 6: from here on class files carry stack map frames (required from 51 on). */
    private static final int FRAMES_FROM = 50;

    public static void main(String[] args) {
        if (args.length != 1) {
            System.err.println("usage: java -cp asm.jar UpgradeClassFiles.java JAR");
            System.exit(2);
        }
        Path jar = Path.of(args[0]);
        try {
            Result r = upgrade(jar);
            System.out.printf("%s: %,d %s older than Java 6 rewritten as Java 8 class files%n",
                    jar.getFileName(), r.upgraded, r.upgraded == 1 ? "class file" : "class files");
            if (!r.kept.isEmpty()) {
                System.out.printf("%s: %,d kept as %s (no frames could be computed): %s%n",
                        jar.getFileName(), r.kept.size(), r.kept.size() == 1 ? "it was" : "they were", String.join(", ", r.kept));
            }
        } catch (NoSuchFileException e) {
            System.err.println("UpgradeClassFiles: no such jar: " + jar);
            System.exit(3);
        } catch (IOException e) {
            System.err.println("UpgradeClassFiles: could not rewrite " + jar + ": " + e);
            System.exit(3);
        }
    }

    private record Result(int upgraded, List<String> kept) {}

    private static Result upgrade(Path jar) throws IOException {
        Path tmp = jar.resolveSibling(jar.getFileName() + ".upgrading");
        int upgraded = 0;
        List<String> kept = new ArrayList<>();
        // Frames name the common superclass where two types meet; ASM finds it by loading the
        // classes (without initialising them) from the jar itself and the platform.
        try (URLClassLoader loader = new URLClassLoader(new URL[] {jar.toUri().toURL()}, ClassLoader.getPlatformClassLoader());
                InputStream raw = Files.newInputStream(jar);
                ZipInputStream in = new ZipInputStream(raw);
                OutputStream out = Files.newOutputStream(tmp);
                ZipOutputStream zip = new ZipOutputStream(out)) {
            ZipEntry e;
            while ((e = in.getNextEntry()) != null) {
                byte[] bytes = in.readAllBytes();
                String name = e.getName();
                if (name.endsWith(".class") && !name.startsWith("META-INF/") && major(bytes) < FRAMES_FROM) {
                    try {
                        bytes = withFrames(bytes, loader);
                        upgraded++;
                    } catch (RuntimeException | LinkageError failed) {
                        kept.add(name);
                    }
                }
                ZipEntry copy = new ZipEntry(name);
                copy.setTime(e.getTime());
                zip.putNextEntry(copy);
                zip.write(bytes);
                zip.closeEntry();
            }
        } catch (IOException | RuntimeException failed) {
            Files.deleteIfExists(tmp);
            throw failed;
        }
        Files.move(tmp, jar, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        return new Result(upgraded, kept);
    }

    private static int major(byte[] classFile) {
        return classFile.length < 8 ? Integer.MAX_VALUE : (classFile[6] & 0xff) << 8 | (classFile[7] & 0xff);
    }

    private static byte[] withFrames(byte[] classFile, ClassLoader loader) {
        ClassReader reader = new ClassReader(classFile);
        ClassWriter writer = new ClassWriter(ClassWriter.COMPUTE_FRAMES) {
            @Override
            protected ClassLoader getClassLoader() {
                return loader;
            }
        };
        reader.accept(new ClassVisitor(Opcodes.ASM9, writer) {
            @Override
            public void visit(int version, int access, String name, String signature, String superName, String[] interfaces) {
                // From Java 6 on an interface must also say it is abstract, which old compilers
                // left out of package-info files.
                if ((access & Opcodes.ACC_INTERFACE) != 0) access |= Opcodes.ACC_ABSTRACT;
                super.visit(Opcodes.V1_8, access, name, signature, superName, interfaces);
            }
        }, ClassReader.SKIP_FRAMES);
        return writer.toByteArray();
    }
}
