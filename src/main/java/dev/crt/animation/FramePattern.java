package dev.crt.animation;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A printf-style output name such as {@code frames/f_%04d.png}: exactly one integer conversion
 * ({@code %d}, {@code %4d}, {@code %04d}) that the frame number replaces, and {@code %%} for a
 * literal percent sign. Anything else is refused, because a name without the frame number would
 * make every frame overwrite the same file.
 */
public record FramePattern(String text, String before, String conversion, String after) {
    private static final Pattern CONVERSION = Pattern.compile("%(0?[1-9]\\d{0,2})?d");

    /** Parses and checks {@code text}; a bad pattern is an IllegalArgumentException. */
    public static FramePattern parse(String text) {
        StringBuilder before = new StringBuilder();
        StringBuilder after = new StringBuilder();
        String conversion = null;
        int i = 0;
        while (i < text.length()) {
            char c = text.charAt(i);
            StringBuilder literal = conversion == null ? before : after;
            if (c != '%') {
                literal.append(c);
                i++;
            } else if (text.startsWith("%%", i)) {
                literal.append('%');
                i += 2;
            } else {
                Matcher m = CONVERSION.matcher(text).region(i, text.length());
                if (!m.lookingAt()) {
                    throw new IllegalArgumentException("-o " + text + ": unsupported conversion at '" + text.substring(i)
                            + "' (use %d or %04d for the frame number, %% for a percent sign)");
                }
                if (conversion != null) {
                    throw new IllegalArgumentException("-o " + text + ": the pattern has more than one frame number conversion");
                }
                conversion = m.group();
                i = m.end();
            }
        }
        if (conversion == null) {
            throw new IllegalArgumentException("-o " + text + ": the pattern needs the frame number, such as frames/f_%04d.png"
                    + " (without it every frame would overwrite the same file)");
        }
        FramePattern pattern = new FramePattern(text, before.toString(), conversion, after.toString());
        try {
            pattern.path(0);
        } catch (InvalidPathException e) {
            throw new IllegalArgumentException("-o " + text + ": not a valid file name: " + e.getReason());
        }
        return pattern;
    }

    /** The file of frame {@code frame}; a width pads with zeros ({@code %5d} as {@code %05d}), never with spaces. */
    public Path path(int frame) {
        String padded = conversion.length() > 2 && conversion.charAt(1) != '0' ? "%0" + conversion.substring(1) : conversion;
        return Path.of(before + String.format(Locale.ROOT, padded, frame) + after);
    }

    /** The image type, from the pattern's extension ("png", "ppm", "pfm", or anything the user typed). */
    public String extension() {
        String name = path(0).getFileName() == null ? "" : path(0).getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot < 0 ? "" : name.substring(dot + 1).toLowerCase(Locale.ROOT);
    }

    @Override
    public String toString() { return text; }
}
