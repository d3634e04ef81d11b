package dev.crt.render;

import dev.crt.image.FrameBuffer;

/**
 * The outlines of Gooch materials (docs/rendering.md, "Gooch shading"), found from the geometry
 * seen through the pixel centres: between two side-by-side pixels lies an edge when they show
 * different entities (or one shows the background: a silhouette) or surface normals more than
 * {@value #CREASE_DEGREES}° apart (a crease), and at least one of them is a Gooch material. The
 * edge is drawn on the Gooch pixel (the nearer one when both are) and the next pixels away from
 * the edge, {@code outline} pixels in all (the larger of the two materials' widths), in black.
 */
final class Outlines {
    static final double CREASE_DEGREES = 60;
    private static final double CREASE_COS = Math.cos(Math.toRadians(CREASE_DEGREES));

    private Outlines() {}

    static void draw(FrameBuffer image, SceneGeometry geometry, CameraRays camera, int[] shape, int[] face, double[] t,
            boolean[] flip) {
        int w = image.width(), h = image.height(), n = w * h;
        Shapes shapes = geometry.shapes;
        double[] mat = geometry.materials.data;
        int[] owner = new int[n];
        double[] width = new double[n];
        float[] normal = new float[3 * n];
        Ray ray = new Ray();
        SurfacePoint sp = new SurfacePoint();
        double[] d = new double[3];
        for (int i = 0; i < n; i++) {
            int s = shape[i];
            if (s < 0) {
                owner[i] = -1;
                t[i] = Double.POSITIVE_INFINITY;
                continue;
            }
            owner[i] = geometry.owner[s];
            int m = shapes.material[s] * Materials.STRIDE;
            width[i] = mat[m + Materials.MODEL] == Materials.GOOCH ? mat[m + Materials.OUTLINE] : 0;
            camera.direction(i % w, i / w, 0.5, 0.5, d);
            ray.set(camera.px, camera.py, camera.pz, d[0], d[1], d[2]);
            shapes.surface(s, face[i], t[i], ray, sp);
            double sign = flip[i] ? -1 : 1;
            normal[3 * i] = (float) (sign * sp.nx);
            normal[3 * i + 1] = (float) (sign * sp.ny);
            normal[3 * i + 2] = (float) (sign * sp.nz);
        }
        boolean[] black = new boolean[n];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int p = y * w + x;
                if (x + 1 < w) edge(x, y, 1, 0, w, h, owner, normal, t, width, black);
                if (y + 1 < h) edge(x, y, 0, 1, w, h, owner, normal, t, width, black);
            }
        }
        for (int p = 0; p < n; p++) {
            if (black[p]) image.set(p % w, p / w, 0, 0, 0);
        }
    }

    /**
     * If pixel (x, y) and its neighbour (x + sx, y + sy) are split by an outline, blackens the
     * line: the drawn side's pixel and the next ones away from the other side, {@code outline} in
     * all (stopping at the image's border).
     */
    private static void edge(int x, int y, int sx, int sy, int w, int h, int[] owner, float[] normal, double[] t,
            double[] width, boolean[] black) {
        int p = y * w + x, q = (y + sy) * w + x + sx;
        double wide = Math.max(width[p], width[q]);
        if (wide < 1) return;
        boolean split = owner[p] != owner[q];
        if (!split && owner[p] >= 0) {
            double c = normal[3 * p] * normal[3 * q] + normal[3 * p + 1] * normal[3 * q + 1] + normal[3 * p + 2] * normal[3 * q + 2];
            split = c < CREASE_COS;
        }
        if (!split) return;
        // On the Gooch side when only one is (a contact edge has nearly equal depths on both sides), else the nearer.
        boolean onP = width[p] != 0 && (width[q] == 0 || t[p] <= t[q]);
        int cx = onP ? x : x + sx, cy = onP ? y : y + sy, dx = onP ? -sx : sx, dy = onP ? -sy : sy;
        for (int k = 0, n = (int) Math.round(wide); k < n; k++, cx += dx, cy += dy) {
            if (cx < 0 || cy < 0 || cx >= w || cy >= h) break;
            black[cy * w + cx] = true;
        }
    }
}
