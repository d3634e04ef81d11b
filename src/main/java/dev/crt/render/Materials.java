package dev.crt.render;

import dev.crt.scene.Material;
import java.util.Arrays;

/**
 * The distinct materials of a scene as one flat array, thirteen doubles each. Materials are told
 * apart by their values, as Material's equals does, through a hash table of indices into the
 * array itself: a scene with a million materials costs no object per material.
 */
final class Materials {
    static final int STRIDE = 13;
    static final int R = 0, G = 1, B = 2, DIFFUSE = 3, SPECULAR = 4, SHININESS = 5, REFLECTIVITY = 6,
            TRANSPARENCY = 7, IOR = 8, ER = 9, EG = 10, EB = 11, ORIGINAL_DIFFUSE = 12;

    double[] data = new double[STRIDE * 8];
    private int count;
    /** Open addressing: index + 1 of the material in each slot, 0 when the slot is free. */
    private int[] table = new int[16];
    private final double[] values = new double[STRIDE];
    /** Scenes often give many objects one Material object: the last answer is kept. */
    private Material last;
    private int lastIndex;

    /** The index of {@code m}, adding it on first use. */
    int indexOf(Material m) {
        if (m == last) return lastIndex;
        double[] v = values;
        v[R] = m.color().r();
        v[G] = m.color().g();
        v[B] = m.color().b();
        v[DIFFUSE] = m.diffuse();
        v[SPECULAR] = m.specular();
        v[SHININESS] = m.shininess();
        v[REFLECTIVITY] = m.reflectivity();
        v[TRANSPARENCY] = m.transparency();
        v[IOR] = m.ior();
        v[ER] = m.emission().r();
        v[EG] = m.emission().g();
        v[EB] = m.emission().b();
        v[ORIGINAL_DIFFUSE] = m.originalDiffuse();
        int mask = table.length - 1;
        int slot = hash(v, 0) & mask;
        int k;
        while (true) {
            int entry = table[slot];
            if (entry == 0) {
                k = add(v, slot);
                break;
            }
            if (equal(entry - 1, v)) {
                k = entry - 1;
                break;
            }
            slot = (slot + 1) & mask;
        }
        last = m;
        lastIndex = k;
        return k;
    }

    private int add(double[] v, int slot) {
        int k = count++;
        if (k * STRIDE == data.length) data = Arrays.copyOf(data, data.length * 2);
        System.arraycopy(v, 0, data, k * STRIDE, STRIDE);
        table[slot] = k + 1;
        if (2 * count > table.length) {
            int[] bigger = new int[2 * table.length];
            int mask = bigger.length - 1;
            for (int i = 0; i < count; i++) {
                int s = hash(data, i * STRIDE) & mask;
                while (bigger[s] != 0) s = (s + 1) & mask;
                bigger[s] = i + 1;
            }
            table = bigger;
        }
        return k;
    }

    /** Equal as Material's equals compares doubles (Double.compare, so NaN equals NaN and 0.0 differs from −0.0). */
    private boolean equal(int k, double[] v) {
        for (int i = 0; i < STRIDE; i++) {
            if (Double.doubleToLongBits(data[k * STRIDE + i]) != Double.doubleToLongBits(v[i])) return false;
        }
        return true;
    }

    private static int hash(double[] a, int at) {
        long h = 0;
        for (int i = 0; i < STRIDE; i++) h = (h + Double.doubleToLongBits(a[at + i])) * 0x9E3779B97F4A7C15L;
        return (int) (h ^ (h >>> 32));
    }

    double transparency(int m) { return data[m * STRIDE + TRANSPARENCY]; }
}
