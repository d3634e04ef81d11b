package dev.crt.cli;

import dev.crt.image.AtomicFile;
import dev.crt.image.FrameBuffer;
import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/**
 * Converged reference pictures kept between runs of {@code crt accuracy}, under
 * {@code $XDG_CACHE_HOME/crt/accuracy/} (default {@code ~/.cache/crt/accuracy/}), named by a
 * SHA-256 of everything that decides them; a damaged or foreign file is treated as missing.
 * {@code -Dcrt.cache=DIR} puts them elsewhere.
 */
final class ReferenceCache {
    private static final String MAGIC = "CRT reference 1";

    private final Path folder;

    ReferenceCache(Path folder) {
        this.folder = folder;
    }

    /** The cache folder the XDG base directory rules give, or the one {@code -Dcrt.cache} names. */
    static Path defaultFolder() {
        String named = System.getProperty("crt.cache");
        if (named != null && !named.isBlank()) return Path.of(named);
        String xdg = System.getenv("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute() ? Path.of(xdg)
                : Path.of(System.getProperty("user.home"), ".cache");
        return base.resolve("crt").resolve("accuracy");
    }

    /** The key of a reference: a digest of the parts that decide it, each length-prefixed. */
    static String key(String... parts) {
        try {
            MessageDigest d = MessageDigest.getInstance("SHA-256");
            for (String p : parts) {
                byte[] b = p.getBytes(StandardCharsets.UTF_8);
                d.update((b.length + ":").getBytes(StandardCharsets.UTF_8));
                d.update(b);
            }
            return HexFormat.of().formatHex(d.digest());
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }

    Path file(String key) {
        return folder.resolve(key + ".ref");
    }

    /** The cached picture, or null when there is none (or it cannot be read as one). */
    FrameBuffer load(String key) {
        try (InputStream raw = Files.newInputStream(file(key));
             DataInputStream in = new DataInputStream(new BufferedInputStream(raw))) {
            if (!MAGIC.equals(in.readUTF())) return null;
            int w = in.readInt(), h = in.readInt();
            if (w < 1 || h < 1 || (long) w * h > FrameBuffer.MAX_PIXELS) return null;
            FrameBuffer fb = new FrameBuffer(w, h);
            float[] data = fb.data();
            for (int k = 0; k < data.length; k++) data[k] = in.readFloat();
            if (in.read() != -1) return null;
            return fb;
        } catch (NoSuchFileException e) {
            return null;
        } catch (IOException e) {
            return null;
        }
    }

    /** Stores {@code image} under {@code key}, atomically: a crash leaves the old file or none. */
    void store(String key, FrameBuffer image) throws IOException {
        Files.createDirectories(folder);
        AtomicFile.write(file(key), raw -> {
            DataOutputStream out = new DataOutputStream(raw);
            out.writeUTF(MAGIC);
            out.writeInt(image.width());
            out.writeInt(image.height());
            for (float f : image.data()) out.writeFloat(f);
            out.flush();
        });
    }
}
