package dev.crt.studio;

import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import java.util.HashSet;
import java.util.Set;
import java.util.function.UnaryOperator;

/**
 * Render settings the user chose for this session only (Render → Settings…): each one, when set,
 * replaces the script's value in the studio's renders and animations without touching the script.
 * Threads are only ever here: they are a property of the machine, not of the scene.
 */
final class SessionSettings implements UnaryOperator<Scene> {
    Integer width;
    Integer height;
    Integer supersampling;
    Integer dofSamples;
    Integer recursionDepth;
    Double gamma;
    /** Render threads; 0 means all cores. */
    int threads;

    boolean isEmpty() {
        return width == null && height == null && supersampling == null && dofSamples == null && recursionDepth == null
                && gamma == null;
    }

    /** The render threads in force: the session's count, or every core. */
    int threadCount() { return threads > 0 ? threads : Runtime.getRuntime().availableProcessors(); }

    /** {@code scene} with this session's settings in place of the script's. */
    @Override
    public Scene apply(Scene scene) {
        return isEmpty() ? scene : scene.withSettings(apply(scene.settings()));
    }

    /** {@code s} with this session's settings in place of the script's. */
    Settings apply(Settings s) {
        if (isEmpty()) return s;
        Set<String> given = new HashSet<>(s.given());
        if (recursionDepth != null) given.add("recursiondepth");
        return new Settings(s.title(), s.author(), s.date(), s.notes(), s.lights(), s.camera(),
                s.background(), or(supersampling, s.supersampling()), or(dofSamples, s.dofSamples()),
                or(recursionDepth, s.recursionDepth()), gamma != null ? gamma : s.gamma(), or(width, s.width()),
                or(height, s.height()), s.sampler(), s.seed(), s.noise(), s.shading(), given);
    }

    private static int or(Integer session, int script) { return session != null ? session : script; }
}
