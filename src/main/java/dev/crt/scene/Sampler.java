package dev.crt.scene;

import java.util.Locale;
import java.util.Optional;

/** How a pixel's samples (sub-pixel positions and lens points) are placed: Settings' {@code sampler}. */
public enum Sampler {
    /** The n×n grid of sub-pixel centres, lens points from the pixel's random generator (wave 1). */
    GRID,
    /** One random point in each cell of the n×n grid; lens points Latin-hypercube stratified. */
    JITTERED,
    /** A Sobol sequence, Owen-scrambled per pixel from the scene seed. */
    SOBOL,
    /** The Sobol samples in order, stopping once the pixel's mean is known to within the noise target. */
    ADAPTIVE;

    /** The word scripts and the command line use. */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The sampler a script or option names, if any. */
    public static Optional<Sampler> of(String word) {
        for (Sampler s : values()) {
            if (s.word().equals(word)) return Optional.of(s);
        }
        return Optional.empty();
    }

    /** The words, for messages: "grid", "jittered", "sobol" or "adaptive". */
    public static String words() {
        StringBuilder b = new StringBuilder();
        Sampler[] all = values();
        for (int k = 0; k < all.length; k++) {
            if (k > 0) b.append(k == all.length - 1 ? " or " : ", ");
            b.append('"').append(all[k].word()).append('"');
        }
        return b.toString();
    }
}
