package dev.crt.studio;

import java.nio.file.Path;
import java.util.Map;

/**
 * Where the studio keeps its files: settings and layout under {@code $XDG_CONFIG_HOME/crt}
 * (default {@code ~/.config/crt}), recovery copies of unsaved scripts under
 * {@code $XDG_STATE_HOME/crt/recovery} (default {@code ~/.local/state/crt/recovery}).
 */
public record StudioPaths(Path config, Path recovery) {
    /** The folders the XDG variables of {@code env} name, with the XDG defaults under {@code home}. */
    public static StudioPaths from(Map<String, String> env, Path home) {
        Path configHome = absolute(env.get("XDG_CONFIG_HOME"), home.resolve(".config"));
        Path stateHome = absolute(env.get("XDG_STATE_HOME"), home.resolve(".local").resolve("state"));
        return new StudioPaths(configHome.resolve("crt"), stateHome.resolve("crt").resolve("recovery"));
    }

    /** For this process: its environment and the user's home. */
    public static StudioPaths ofUser() {
        return from(System.getenv(), Path.of(System.getProperty("user.home")));
    }

    private static Path absolute(String value, Path fallback) {
        // The XDG specification says relative values are invalid and are to be ignored.
        if (value == null || value.isBlank()) return fallback;
        Path p = Path.of(value);
        return p.isAbsolute() ? p : fallback;
    }

    Path settingsFile() { return config.resolve("studio.properties"); }

    Path layoutFile() { return config.resolve("studio-layout.xml"); }
}
