package dev.crt.render;

/**
 * Where a line o + t·d is inside one primitive solid: from {@code tIn} to {@code tOut} (infinite
 * for half-spaces), with the face crossed at each end. Per-thread scratch.
 */
final class LineSpan {
    double tIn, tOut;
    int faceIn, faceOut;
}
