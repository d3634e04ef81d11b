package dev.crt.lang.eval;

import dev.crt.image.PictureFiles;
import dev.crt.scene.MeshData;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.Picture;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Finds and decodes the files a script names (section 11): an existing absolute path as given,
 * else relative to the script's folder, else for a leading '/' under each --assets folder and
 * the assets CRT ships (the folder named by the system property {@code crt.assets}, when set).
 */
final class Assets {
    /** A file that is missing or cannot be decoded, said in a sentence for the diagnostic. */
    static final class AssetProblem extends Exception {
        AssetProblem(String message) { super(message, null, false, false); }
    }

    private final Path scriptFolder;
    private final List<Path> assetFolders;
    private final Map<Path, Picture> decoded = new HashMap<>();
    /** Meshes by file: every instance of one file shares its triangles. */
    private final Map<Path, MeshData> meshes = new HashMap<>();

    Assets(Path scriptFolder, List<Path> assetDirs) {
        this.scriptFolder = scriptFolder != null ? scriptFolder : Path.of("").toAbsolutePath();
        Set<Path> folders = new LinkedHashSet<>();
        for (Path dir : assetDirs) folders.add(dir.toAbsolutePath().normalize());
        String shipped = System.getProperty("crt.assets");
        if (shipped != null && !shipped.isBlank()) folders.add(Path.of(shipped).toAbsolutePath().normalize());
        this.assetFolders = List.copyOf(folders);
    }

    PanoramaBackground panorama(String name, double angle) throws AssetProblem {
        Path file = find(name, "panorama");
        return new PanoramaBackground(file.toString(), picture(file, name, "panorama"), angle);
    }

    /** The picture of an image texture, and the file it was found in. */
    record Image(Path file, Picture picture) {}

    Image image(String name) throws AssetProblem {
        Path file = find(name, "image");
        return new Image(file, picture(file, name, "image"));
    }

    private Picture picture(Path file, String name, String what) throws AssetProblem {
        Picture picture = decoded.get(file);
        if (picture == null) {
            try {
                picture = PictureFiles.read(file);
            } catch (IOException e) {
                throw new AssetProblem("cannot use " + what + " '" + name + "': " + e.getMessage());
            }
            decoded.put(file, picture);
        }
        return picture;
    }

    MeshData mesh(String name) throws AssetProblem {
        Path file = find(name, "mesh");
        MeshData mesh = meshes.get(file);
        if (mesh == null) {
            try {
                mesh = MeshFiles.read(file);
            } catch (MeshBuilder.MeshProblem e) {
                throw new AssetProblem("cannot use mesh '" + name + "': " + e.getMessage());
            }
            meshes.put(file, mesh);
        }
        return mesh;
    }

    private Path find(String name, String what) throws AssetProblem {
        if (name.isEmpty()) throw new AssetProblem("the " + what + " file name is empty");
        // A set: the script's folder may also be an asset folder, and each place is named once.
        Set<Path> searched = new LinkedHashSet<>();
        try {
            Path given = Path.of(name);
            if (given.isAbsolute()) {
                if (Files.isRegularFile(given)) return given;
                searched.add(given);
            }
            String relative = name.startsWith("/") ? name.replaceFirst("^/+", "") : name;
            Path inScriptFolder = scriptFolder.resolve(relative).normalize();
            if (Files.isRegularFile(inScriptFolder)) return inScriptFolder;
            searched.add(inScriptFolder);
            if (name.startsWith("/")) {
                for (Path folder : assetFolders) {
                    Path candidate = folder.resolve(relative).normalize();
                    if (Files.isRegularFile(candidate)) return candidate;
                    searched.add(candidate);
                }
            }
        } catch (InvalidPathException e) {
            throw new AssetProblem(what + " file name '" + name + "' is not a valid path");
        }
        List<String> places = new ArrayList<>();
        for (Path p : searched) places.add(p.toString());
        throw new AssetProblem(what + " file '" + name + "' not found; looked for " + String.join(", ", places));
    }
}
