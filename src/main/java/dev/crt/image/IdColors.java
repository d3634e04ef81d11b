package dev.crt.image;

/**
 * The id pass's encoding, shared by the ray tracer ({@code crt render --pass id}) and the live
 * view ({@code crt preview --pass id}): entity index {@code i} (0-based, in scene order) is the
 * 1-based {@code k = i + 1} written as 8-bit RGB {@code (k mod 256, (k div 256) mod 256, k div
 * 65536)}; background is k = 0, black.
 */
public final class IdColors {
    private IdColors() {}

    /** The 1-based code of entity index {@code index}, 0 for background (index −1). */
    public static int code(int index) { return index + 1; }

    /** The entity index of a 1-based code, −1 for background. */
    public static int entityIndex(int code) { return code - 1; }

    /** The 0xRRGGBB colour of entity index {@code index} (−1 for background: black). */
    public static int rgb(int index) {
        int k = code(index);
        return (k & 255) << 16 | ((k >> 8) & 255) << 8 | ((k >> 16) & 255);
    }

    /** The entity index a colour encodes, −1 for black. */
    public static int index(int rgb) {
        int k = ((rgb >> 16) & 255) | ((rgb >> 8) & 255) << 8 | (rgb & 255) << 16;
        return entityIndex(k);
    }

    /** An id pass as a linear float image (gamma 1) whose 8-bit encoding is exactly the colours above. */
    public static FrameBuffer image(int[] indices, int width, int height) {
        FrameBuffer image = new FrameBuffer(width, height);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int c = rgb(indices[y * width + x]);
                image.set(x, y, ((c >> 16) & 255) / 255.0, ((c >> 8) & 255) / 255.0, (c & 255) / 255.0);
            }
        }
        return image;
    }
}
