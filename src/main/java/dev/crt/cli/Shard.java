package dev.crt.cli;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Shard {@code index} of {@code count}: the frames whose index in the range leaves {@code index}
 * when divided by {@code count}. The shares are disjoint and cover the range, and each depends on
 * nothing but I, N and the range, so shards may run in any order on any machines.
 */
record Shard(int index, int count) {
    static final Shard WHOLE = new Shard(0, 1);

    private static final Pattern SYNTAX = Pattern.compile("(\\d+)/(\\d+)");

    Shard {
        if (count < 1) throw new IllegalArgumentException("the shard count must be at least 1, got " + count);
        if (index < 0 || index >= count) {
            throw new IllegalArgumentException("the shard index must be from 0 to " + (count - 1) + ", got " + index);
        }
    }

    /** Parses {@code I/N}; a bad value is an IllegalArgumentException. */
    static Shard parse(String text) {
        Matcher m = SYNTAX.matcher(text.strip());
        if (!m.matches()) {
            throw new IllegalArgumentException("--shard takes I/N with I from 0 to N-1 (such as 0/4), got '" + text + "'");
        }
        try {
            return new Shard(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--shard " + text + ": the numbers are too large");
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--shard " + text + ": " + e.getMessage());
        }
    }

    /** Whether the frame at {@code frameIndex} in the range is this shard's to render. */
    boolean owns(int frameIndex) { return frameIndex % count == index; }

    @Override
    public String toString() { return index + "/" + count; }
}
