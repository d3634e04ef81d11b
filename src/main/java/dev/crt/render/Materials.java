package dev.crt.render;

import dev.crt.scene.Material;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/** The distinct materials of a scene as one flat array, twelve doubles each. */
final class Materials {
    static final int STRIDE = 12;
    static final int R = 0, G = 1, B = 2, DIFFUSE = 3, SPECULAR = 4, SHININESS = 5, REFLECTIVITY = 6,
            TRANSPARENCY = 7, IOR = 8, ER = 9, EG = 10, EB = 11;

    private final Map<Material, Integer> index = new HashMap<>();
    double[] data = new double[STRIDE * 8];
    private int count;

    /** The index of {@code m}, adding it on first use. */
    int indexOf(Material m) {
        Integer i = index.get(m);
        if (i != null) return i;
        int k = count++;
        if (k * STRIDE == data.length) data = Arrays.copyOf(data, data.length * 2);
        double[] v = {m.color().r(), m.color().g(), m.color().b(), m.diffuse(), m.specular(), m.shininess(),
                m.reflectivity(), m.transparency(), m.ior(), m.emission().r(), m.emission().g(), m.emission().b()};
        System.arraycopy(v, 0, data, k * STRIDE, STRIDE);
        index.put(m, k);
        return k;
    }

    double transparency(int m) { return data[m * STRIDE + TRANSPARENCY]; }
}
