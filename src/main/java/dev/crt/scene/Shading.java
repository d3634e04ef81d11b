package dev.crt.scene;

import java.util.Locale;
import java.util.Optional;

/** Which shading model renders a scene: Settings' {@code shading}. */
public enum Shading {
    /** CRT's own model (docs/rendering.md). */
    CRT,
    /** What the 2015 program computed, so its scenes look as they did (docs/rendering.md, "Scenes from CRT 2015"). */
    ORIGINAL;

    /** The word scripts and the command line use. */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The model a script or option names, if any. */
    public static Optional<Shading> of(String word) {
        for (Shading s : values()) {
            if (s.word().equals(word)) return Optional.of(s);
        }
        return Optional.empty();
    }
}
