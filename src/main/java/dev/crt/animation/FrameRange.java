package dev.crt.animation;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The frames of an animation, {@code first..last:step}: first, first + step, … up to last. A frame's
 * index is its position in the range (0 for the first frame), which is what shards divide.
 */
public record FrameRange(int first, int last, int step) {
    /** More frames than this in one range is surely a typo, and their file names alone would fill memory. */
    public static final int MAX_FRAMES = 1_000_000;

    private static final Pattern SYNTAX = Pattern.compile("(-?\\d+)(?:\\.\\.(-?\\d+)(?::(\\d+))?)?");

    public FrameRange {
        if (last < first) throw new IllegalArgumentException("the last frame " + last + " comes before the first " + first);
        if (step < 1) throw new IllegalArgumentException("the step must be at least 1, got " + step);
        if (((long) last - first) / step >= MAX_FRAMES) {
            throw new IllegalArgumentException("that is more than " + MAX_FRAMES + " frames; split it into several ranges");
        }
    }

    /** Parses {@code A..B}, {@code A..B:STEP} or a single frame {@code A}; a bad value is an IllegalArgumentException. */
    public static FrameRange parse(String text) {
        Matcher m = SYNTAX.matcher(text.strip());
        if (!m.matches()) {
            throw new IllegalArgumentException("--frames takes FIRST..LAST or FIRST..LAST:STEP (such as 1..100 or 0..48:2), got '" + text + "'");
        }
        try {
            int first = Integer.parseInt(m.group(1));
            int last = m.group(2) == null ? first : Integer.parseInt(m.group(2));
            int step = m.group(3) == null ? 1 : Integer.parseInt(m.group(3));
            return new FrameRange(first, last, step);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--frames " + text + ": frame numbers must lie between "
                    + Integer.MIN_VALUE + " and " + Integer.MAX_VALUE);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--frames " + text + ": " + e.getMessage());
        }
    }

    /** How many frames the range holds. */
    public int size() { return (int) (((long) last - first) / step + 1); }

    /** The frame number at {@code index} (0 ≤ index < size()). */
    public int frame(int index) { return (int) (first + (long) index * step); }

    @Override
    public String toString() { return first + ".." + last + (step == 1 ? "" : ":" + step); }
}
