package dev.crt.render;

import dev.crt.scene.Checker;
import dev.crt.scene.Material;
import java.util.Arrays;

/**
 * The distinct materials of a scene as one flat array, {@link #STRIDE} doubles each. Materials are told
 * apart by their values, as Material's equals does, through a hash table of indices into the
 * array itself: a scene with a million materials costs no object per material.
 */
final class Materials {
    static final int STRIDE = 25;
    static final int R = 0, G = 1, B = 2, DIFFUSE = 3, SPECULAR = 4, SHININESS = 5, REFLECTIVITY = 6,
            TRANSPARENCY = 7, IOR = 8, ER = 9, EG = 10, EB = 11, ORIGINAL_DIFFUSE = 12, FRESNEL = 13,
            AR = 14, AG = 15, AB = 16, TEXTURE = 17, T1R = 18, T1G = 19, T1B = 20, T2R = 21, T2G = 22, T2B = 23,
            TSCALE = 24;
    /** {@link #TEXTURE} values: a plain colour, or a checkerboard of T1 and T2 with cells TSCALE wide. */
    static final double PLAIN = 0, CHECKER = 1;

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
        v[FRESNEL] = m.fresnel() ? 1 : 0;
        v[AR] = m.absorption().r();
        v[AG] = m.absorption().g();
        v[AB] = m.absorption().b();
        for (int k = TEXTURE; k < STRIDE; k++) v[k] = 0;
        if (m.texture() instanceof Checker c) {
            v[TEXTURE] = CHECKER;
            v[T1R] = c.color1().r();
            v[T1G] = c.color1().g();
            v[T1B] = c.color1().b();
            v[T2R] = c.color2().r();
            v[T2G] = c.color2().g();
            v[T2B] = c.color2().b();
            v[TSCALE] = c.scale();
        }
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

    /** Whether some material absorbs light inside its solid (Beer's law). */
    boolean absorbing() {
        for (int k = 0; k < count; k++) {
            if (data[k * STRIDE + AR] != 0 || data[k * STRIDE + AG] != 0 || data[k * STRIDE + AB] != 0) return true;
        }
        return false;
    }
}
