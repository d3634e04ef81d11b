package dev.crt.live;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.MeshData;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

class MeshBvhTest {
    /** A closed mesh of many triangles: a UV sphere of {@code rings × segments} quads. */
    static MeshData sphere(int rings, int segments) {
        double[] p = new double[3 * (rings + 1) * segments];
        for (int r = 0; r <= rings; r++) {
            for (int s = 0; s < segments; s++) {
                double th = Math.PI * r / rings, ph = 2 * Math.PI * s / segments;
                int v = 3 * (r * segments + s);
                p[v] = Math.sin(th) * Math.cos(ph);
                p[v + 1] = Math.cos(th);
                p[v + 2] = Math.sin(th) * Math.sin(ph);
            }
        }
        int[] t = new int[6 * rings * segments];
        int k = 0;
        for (int r = 0; r < rings; r++) {
            for (int s = 0; s < segments; s++) {
                int a = r * segments + s, b = r * segments + (s + 1) % segments, c = a + segments, d = b + segments;
                t[k++] = a; t[k++] = c; t[k++] = b;
                t[k++] = b; t[k++] = c; t[k++] = d;
            }
        }
        return new MeshData("sphere", p, t, null, null, true);
    }

    @Test
    void everyTriangleLiesInExactlyOneLeafWhoseBoxesHoldIt() {
        MeshData m = sphere(24, 40);
        MeshBvh bvh = MeshBvh.of(m);
        int n = m.triangleCount();
        // The triangles are the same, reordered.
        assertThat(sorted(bvh.triangles)).isEqualTo(sorted(m.triangles()));
        int[] seen = new int[n];
        int nodes = bvh.nodes.length / 8;
        int[] stack = new int[64];
        int sp = 0, depth = 0;
        stack[sp++] = 0;
        int[] level = new int[nodes];
        level[0] = 1;
        while (sp > 0) {
            int i = stack[--sp];
            depth = Math.max(depth, level[i]);
            float[] node = Arrays.copyOfRange(bvh.nodes, 8 * i, 8 * i + 8);
            int first = (int) node[3], count = (int) node[7];
            if (count == 0) {
                for (int c = first; c < first + 2; c++) {
                    // A child's box lies in its parent's.
                    for (int a = 0; a < 3; a++) {
                        assertThat(bvh.nodes[8 * c + a]).isGreaterThanOrEqualTo(node[a]);
                        assertThat(bvh.nodes[8 * c + 4 + a]).isLessThanOrEqualTo(node[4 + a]);
                    }
                    level[c] = level[i] + 1;
                    stack[sp++] = c;
                }
                continue;
            }
            assertThat(count).isBetween(1, MeshBvh.LEAF_TRIANGLES);
            for (int f = first; f < first + count; f++) {
                seen[f]++;
                for (int corner = 0; corner < 3; corner++) {
                    int v = bvh.triangles[3 * f + corner];
                    for (int a = 0; a < 3; a++) {
                        float x = (float) m.positions()[3 * v + a];
                        assertThat(x).isBetween(node[a], node[4 + a]);
                    }
                }
            }
        }
        assertThat(seen).containsOnly(1);
        // Balanced: a median split gives about log2 of the leaves.
        assertThat(depth).isLessThanOrEqualTo(2 + (int) Math.ceil(Math.log(n) / Math.log(2)));
    }

    @Test
    void theSameTrianglesAreBuiltOnceAndOthersAgain() {
        MeshData m = sphere(20, 20);
        assertThat(MeshBvh.of(m)).isSameAs(MeshBvh.of(m));
        // A recompile reads the file into a new MeshData: the same content, the same hierarchy.
        assertThat(MeshBvh.of(sphere(20, 20))).isSameAs(MeshBvh.of(m));
        assertThat(MeshBvh.of(sphere(20, 21))).isNotSameAs(MeshBvh.of(m));
    }

    @Test
    void degenerateAndRepeatedTrianglesStillEndInLeaves() {
        // Every triangle the same: no axis separates them, the median split still halves the range.
        double[] p = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        int[] t = new int[3 * 1000];
        for (int i = 0; i < 1000; i++) { t[3 * i + 1] = 1; t[3 * i + 2] = 2; }
        MeshBvh bvh = MeshBvh.of(new MeshData("same", p, t, null, null, false));
        int leaves = 0, total = 0;
        for (int i = 0; i < bvh.nodes.length / 8; i++) {
            int count = (int) bvh.nodes[8 * i + 7];
            if (count > 0) { leaves++; total += count; }
        }
        assertThat(total).isEqualTo(1000);
        assertThat(leaves).isGreaterThanOrEqualTo(1000 / MeshBvh.LEAF_TRIANGLES);
    }

    private static long[] sorted(int[] triangles) {
        long[] keys = new long[triangles.length / 3];
        for (int i = 0; i < keys.length; i++) {
            keys[i] = ((long) triangles[3 * i] << 42) | ((long) triangles[3 * i + 1] << 21) | triangles[3 * i + 2];
        }
        Arrays.sort(keys);
        return keys;
    }
}
