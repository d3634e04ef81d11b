package dev.crt.render;

import dev.crt.geom.Vec3;
import dev.crt.scene.AreaLight;
import dev.crt.scene.Light;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.PointLight;
import dev.crt.scene.Rgb;
import dev.crt.scene.SpotLight;
import java.util.List;

/**
 * The lights of a scene as flat arrays with a kind tag each, and the one dispatch from a light
 * sample to its kind's class (PointLightSource, ParallelLightSource, SpotLightSource,
 * AreaLightSource). {@code x, y, z} is a point light's or spot's position, an area light's corner,
 * or, for a parallel light, the unit direction towards the light; {@code ax, ay, az} is a spot's
 * unit axis or an area light's unit normal. The ambient terms of all lights are summed once:
 * Σ aℓ·Cℓ.
 */
final class Lights {
    static final byte POINT = 0, PARALLEL = 1, SPOT = 2, AREA = 3;

    final int count;
    final byte[] kind;
    final double[] x, y, z, r, g, b, falloff;
    final double[] ax, ay, az, cosOuter, cosInner;
    final double[] e1x, e1y, e1z, e2x, e2y, e2z;
    /** An area light's n (n² samples); 1 for the other kinds. */
    final int[] samples;
    final double ambientR, ambientG, ambientB;
    /** Whether some light draws random numbers (an area light): only then is a pixel's light generator seeded. */
    final boolean random;

    Lights(List<Light> lights) {
        count = lights.size();
        kind = new byte[count];
        x = new double[count];
        y = new double[count];
        z = new double[count];
        r = new double[count];
        g = new double[count];
        b = new double[count];
        falloff = new double[count];
        ax = new double[count];
        ay = new double[count];
        az = new double[count];
        cosOuter = new double[count];
        cosInner = new double[count];
        e1x = new double[count];
        e1y = new double[count];
        e1z = new double[count];
        e2x = new double[count];
        e2y = new double[count];
        e2z = new double[count];
        samples = new int[count];
        double ar = 0, ag = 0, ab = 0;
        boolean anyRandom = false;
        for (int i = 0; i < count; i++) {
            Light l = lights.get(i);
            Vec3 p;
            samples[i] = 1;
            if (l instanceof PointLight pl) {
                kind[i] = POINT;
                p = pl.origin();
                falloff[i] = pl.falloff();
            } else if (l instanceof ParallelLight pl) {
                kind[i] = PARALLEL;
                p = pl.towardsLight();
            } else if (l instanceof SpotLight sl) {
                kind[i] = SPOT;
                p = sl.origin();
                falloff[i] = sl.falloff();
                axis(i, sl.pointing().minus(sl.origin()).normalize());
                cosOuter[i] = Math.cos(Math.toRadians(sl.angle()));
                cosInner[i] = Math.cos(Math.toRadians(sl.innerAngle()));
            } else {
                AreaLight al = (AreaLight) l;
                kind[i] = AREA;
                p = al.corner();
                falloff[i] = al.falloff();
                samples[i] = al.samples();
                Vec3 e1 = al.edge1(), e2 = al.edge2();
                e1x[i] = e1.x();
                e1y[i] = e1.y();
                e1z[i] = e1.z();
                e2x[i] = e2.x();
                e2y[i] = e2.y();
                e2z[i] = e2.z();
                axis(i, e1.cross(e2).normalize());
                anyRandom = true;
            }
            x[i] = p.x();
            y[i] = p.y();
            z[i] = p.z();
            Rgb c = l.color();
            r[i] = c.r();
            g[i] = c.g();
            b[i] = c.b();
            ar += l.ambient() * c.r();
            ag += l.ambient() * c.g();
            ab += l.ambient() * c.b();
        }
        ambientR = ar;
        ambientG = ag;
        ambientB = ab;
        random = anyRandom;
    }

    /** Whether no light takes light away: every colour and ambient sum non-negative (falloffs, cones and areas weigh by factors ≥ 0). */
    boolean nonNegative() {
        for (int i = 0; i < count; i++) {
            if (!(r[i] >= 0 && g[i] >= 0 && b[i] >= 0)) return false;
        }
        return ambientR >= 0 && ambientG >= 0 && ambientB >= 0;
    }

    private void axis(int i, Vec3 a) {
        ax[i] = a.x();
        ay[i] = a.y();
        az[i] = a.z();
    }

    /** How many samples light i takes per shading point: n² for an area light, else 1. */
    int sampleCount(int i) {
        if (!Features.LIGHTS) return 1;
        int n = samples[i];
        return n * n;
    }

    /** Sample k of light i as seen from (px, py, pz), into {@code s}; area lights draw their jitter from {@code random}. */
    void sample(int i, int k, double px, double py, double pz, PixelRandom random, LightSample s) {
        byte which = kind[i];
        // With spot and area lights switched off (Features), what is not a point light is a parallel one.
        if (which == POINT) PointLightSource.sample(this, i, px, py, pz, s);
        else if (which == PARALLEL || !Features.LIGHTS) ParallelLightSource.sample(this, i, s);
        else if (which == SPOT) SpotLightSource.sample(this, i, px, py, pz, s);
        else AreaLightSource.sample(this, i, k, px, py, pz, random, s);
    }
}
