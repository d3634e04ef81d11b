package dev.crt.render;

import dev.crt.scene.MeshData;

/** Meshes built in code for tests: a closed triangulated torus and an open grid of unit squares. */
final class Meshes {
    private Meshes() {}

    /** A closed torus about the origin, axis z, of nu × nv quads split into triangles, wound outward. */
    static MeshData torus(double big, double small, int nu, int nv) {
        double[] p = new double[3 * nu * nv];
        for (int i = 0; i < nu; i++) {
            for (int j = 0; j < nv; j++) {
                double a = 2 * Math.PI * i / nu, b = 2 * Math.PI * j / nv;
                double rho = big + small * Math.cos(b);
                int k = 3 * (i * nv + j);
                p[k] = rho * Math.cos(a);
                p[k + 1] = rho * Math.sin(a);
                p[k + 2] = small * Math.sin(b);
            }
        }
        int[] t = new int[6 * nu * nv];
        int n = 0;
        for (int i = 0; i < nu; i++) {
            for (int j = 0; j < nv; j++) {
                int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
                t[n++] = a;
                t[n++] = b;
                t[n++] = c;
                t[n++] = a;
                t[n++] = c;
                t[n++] = d;
            }
        }
        return new MeshData("torus", p, t, null, null, true);
    }

    /** The open grid of n × n unit squares in the plane z = 0 from (0, 0), each split along a diagonal. */
    static MeshData grid(int n) {
        double[] p = new double[3 * (n + 1) * (n + 1)];
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                int k = 3 * (i * (n + 1) + j);
                p[k] = i;
                p[k + 1] = j;
            }
        }
        int[] t = new int[6 * n * n];
        int m = 0;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                int a = i * (n + 1) + j, b = (i + 1) * (n + 1) + j, c = (i + 1) * (n + 1) + j + 1, d = i * (n + 1) + j + 1;
                // Alternate diagonals, so both directions of shared diagonal edges occur.
                if ((i + j) % 2 == 0) {
                    t[m++] = a; t[m++] = b; t[m++] = c;
                    t[m++] = a; t[m++] = c; t[m++] = d;
                } else {
                    t[m++] = a; t[m++] = b; t[m++] = d;
                    t[m++] = b; t[m++] = c; t[m++] = d;
                }
            }
        }
        return new MeshData("grid", p, t, null, null, false);
    }
}
