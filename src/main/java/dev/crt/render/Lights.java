package dev.crt.render;

import dev.crt.geom.Vec3;
import dev.crt.scene.Light;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.PointLight;
import dev.crt.scene.Rgb;
import java.util.List;

/**
 * The lights of a scene as flat arrays. For a point light {@code x, y, z} is its position; for a
 * parallel light it is the unit direction towards the light. The ambient terms of all lights are
 * summed once: Σ aℓ·Cℓ.
 */
final class Lights {
    final int count;
    final boolean[] parallel;
    final double[] x, y, z, r, g, b, falloff;
    final double ambientR, ambientG, ambientB;

    Lights(List<Light> lights) {
        count = lights.size();
        parallel = new boolean[count];
        x = new double[count];
        y = new double[count];
        z = new double[count];
        r = new double[count];
        g = new double[count];
        b = new double[count];
        falloff = new double[count];
        double ar = 0, ag = 0, ab = 0;
        for (int i = 0; i < count; i++) {
            Light l = lights.get(i);
            Vec3 p;
            if (l instanceof PointLight pl) {
                p = pl.origin();
                falloff[i] = pl.falloff();
            } else {
                p = ((ParallelLight) l).towardsLight();
                parallel[i] = true;
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
    }
}
