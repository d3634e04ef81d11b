package dev.crt.render;

import dev.crt.scene.Finish;
import dev.crt.scene.Material;
import dev.crt.scene.ShadingModel;
import dev.crt.scene.Texture;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The distinct materials of a scene as one flat array, {@link #STRIDE} doubles each. Materials are told
 * apart by their values, as Material's equals does, through a hash table of indices into the
 * array itself: a scene with a million materials costs no object per material.
 */
final class Materials {
    static final int STRIDE = 36;
    static final int R = 0, G = 1, B = 2, DIFFUSE = 3, SPECULAR = 4, SHININESS = 5, REFLECTIVITY = 6,
            TRANSPARENCY = 7, IOR = 8, ER = 9, EG = 10, EB = 11, ORIGINAL_DIFFUSE = 12, FRESNEL = 13,
            AR = 14, AG = 15, AB = 16;
    /**
     * Per channel, 0 for plain or 1 + the index of its texture in {@link #textures}; TEXTURED is 1
     * when any of them (or the bump map) is set, the one test a plain material pays for.
     */
    static final int TEX_COLOR = 17, TEXTURED = 18, TEX_EMISSION = 19, TEX_SPECULAR = 20, TEX_REFLECTIVITY = 21,
            TEX_TRANSPARENCY = 22, TEX_BUMP = 23, BUMPSCALE = 24, ROUGHNESS = 25, GLOSSY_SAMPLES = 26, MODEL = 27,
            COOL = 28, WARM = 31, OUTLINE = 34, NEEDS_UV = 35;
    /** {@link #MODEL} values. */
    static final double PHONG = 0, GOOCH = 1;

    /** The distinct textures the materials use (equal textures share one index). */
    final List<Texture> textures = new ArrayList<>();
    private final Map<Texture, Integer> textureIndex = new HashMap<>();

    double[] data = new double[STRIDE * 8];
    private int count;
    /** Open addressing: index + 1 of the material in each slot, 0 when the slot is free. */
    private int[] table = new int[16];
    private final double[] values = new double[STRIDE];
    /**
     * Scenes often give many objects a few Material objects (one, or a palette taken in turn): the
     * answers for recent objects are kept by identity, so such a scene hashes each object's
     * values once, not once per primitive.
     */
    private final Material[] recent = new Material[RECENT];
    private final int[] recentIndex = new int[RECENT];
    private static final int RECENT = 64;

    /** The index of {@code m}, adding it on first use. */
    int indexOf(Material m) {
        int r = System.identityHashCode(m) & (RECENT - 1);
        if (recent[r] == m) return recentIndex[r];
        int k = search(m);
        recent[r] = m;
        recentIndex[r] = k;
        return k;
    }

    private int search(Material m) {
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
        Finish f = m.finish();
        v[TEX_COLOR] = texture(m.texture());
        v[TEX_EMISSION] = texture(f.emission());
        v[TEX_SPECULAR] = texture(f.specular());
        v[TEX_REFLECTIVITY] = texture(f.reflectivity());
        v[TEX_TRANSPARENCY] = texture(f.transparency());
        v[TEX_BUMP] = texture(f.bump());
        boolean uv = needsUv(m.texture()) || needsUv(f.emission()) || needsUv(f.specular()) || needsUv(f.reflectivity())
                || needsUv(f.transparency()) || needsUv(f.bump());
        v[TEXTURED] = m.texture() != null || f.textured() ? 1 : 0;
        v[NEEDS_UV] = uv ? 1 : 0;
        v[BUMPSCALE] = f.bumpScale();
        v[ROUGHNESS] = f.roughness();
        v[GLOSSY_SAMPLES] = f.glossySamples();
        v[MODEL] = f.model() == ShadingModel.GOOCH ? GOOCH : PHONG;
        v[COOL] = f.cool().r();
        v[COOL + 1] = f.cool().g();
        v[COOL + 2] = f.cool().b();
        v[WARM] = f.warm().r();
        v[WARM + 1] = f.warm().g();
        v[WARM + 2] = f.warm().b();
        v[OUTLINE] = f.outline();
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
        return k;
    }

    private static boolean needsUv(Texture t) { return t != null && t.needsUv(); }

    private double texture(Texture t) {
        if (t == null) return 0;
        Integer k = textureIndex.get(t);
        if (k == null) {
            k = textures.size();
            textures.add(t);
            textureIndex.put(t, k);
        }
        return k + 1;
    }

    private Texture[] prepared;

    /**
     * Makes the textures ready for pictures of output gamma {@code gamma} (image textures decode
     * to linear light and build their mipmaps): once per prepared scene, before tracing.
     */
    void prepare(double gamma) {
        Texture[] ready = new Texture[textures.size() + 1];
        for (int k = 0; k < textures.size(); k++) ready[k + 1] = textures.get(k).prepared(gamma);
        prepared = ready;
    }

    /** The prepared textures, texture k at index k + 1 (as the channel slots hold them); as stored when not prepared. */
    Texture[] prepared() {
        if (prepared == null) prepare(1);
        return prepared;
    }

    /** Whether some material asks for glossy reflection and refraction. */
    boolean glossy() {
        for (int k = 0; k < count; k++) {
            if (data[k * STRIDE + ROUGHNESS] > 0) return true;
        }
        return false;
    }

    /** Whether some material has a value other than 0 in {@code slot} (a flag or a texture index). */
    boolean any(int slot) {
        for (int k = 0; k < count; k++) {
            if (data[k * STRIDE + slot] != 0) return true;
        }
        return false;
    }

    /** The slots {@link #nonNegative} asks to be at least 0. */
    private static final int[] ADDING = {R, G, B, DIFFUSE, SPECULAR, REFLECTIVITY, ER, EG, EB};

    /**
     * Whether every material only adds light: colour, diffuse, specular, reflectivity and emission
     * non-negative and transparency in [0, 1], so that every term of a pixel's sum is non-negative
     * (its textures, which may compute their values, are not looked at: ask only without them).
     */
    boolean nonNegative() {
        for (int k = 0; k < count; k++) {
            int m = k * STRIDE;
            for (int slot : ADDING) {
                if (!(data[m + slot] >= 0)) return false;
            }
            if (!(data[m + TRANSPARENCY] >= 0 && data[m + TRANSPARENCY] <= 1)) return false;
        }
        return true;
    }

    /** Whether some material shades with the Gooch model. */
    boolean gooch() {
        for (int k = 0; k < count; k++) {
            if (data[k * STRIDE + MODEL] == GOOCH) return true;
        }
        return false;
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
