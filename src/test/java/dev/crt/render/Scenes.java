package dev.crt.render;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Background;
import dev.crt.scene.Box;
import dev.crt.scene.Camera;
import dev.crt.scene.Csg;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.Plane;
import dev.crt.scene.PointLight;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Sphere;
import java.util.List;

/** Builds scenes in code for render tests, the way the compiler would. */
final class Scenes {
    private Scenes() {}

    static Vec3 v(double x, double y, double z) { return new Vec3(x, y, z); }

    /** A uniformly random unit vector (rejection sampling in the unit ball, away from its centre). */
    static Vec3 unit(java.util.SplittableRandom r) {
        while (true) {
            Vec3 v = new Vec3(r.nextDouble() * 2 - 1, r.nextDouble() * 2 - 1, r.nextDouble() * 2 - 1);
            double l = v.length();
            if (l > 0.1 && l <= 1) return v.div(l);
        }
    }

    static Rgb rgb(double r, double g, double b) { return new Rgb(r, g, b); }

    static Material matte(Rgb c) { return new Material(c, 1, 0, 30, 0, 0, 1, Rgb.BLACK); }

    static Material material(Rgb c, double kd, double ks, double n, double kr, double kt, double ior) {
        return new Material(c, kd, ks, n, kr, kt, ior, Rgb.BLACK);
    }

    static Sphere sphere(Vec3 c, double r, Material m) { return new Sphere(c, r, m, Transform.IDENTITY, SourceSpan.NONE); }

    static Box box(Vec3 a, Vec3 b, Material m) { return Box.ofCorners(a, b, m, Transform.IDENTITY, SourceSpan.NONE); }

    static Plane plane(Vec3 n, Vec3 p, Material m) {
        return new Plane(n.normalize(), p, m, Transform.IDENTITY, SourceSpan.NONE);
    }

    static Csg csg(CsgOperation op, Entity a, Entity b) { return new Csg(op, a, b, Transform.IDENTITY, SourceSpan.NONE); }

    static PointLight point(Vec3 p, Rgb c, double falloff, double ambient) {
        return new PointLight(p, c, falloff, ambient, SourceSpan.NONE);
    }

    static ParallelLight parallel(Vec3 from, Vec3 to, Rgb c, double ambient) {
        return new ParallelLight(from, to, c, ambient, SourceSpan.NONE);
    }

    static Camera camera(Vec3 p, Vec3 at, double fov) {
        return new Camera(p, at, fov, 0, 0, at.minus(p).length(), ApertureShape.CIRCLE, SourceSpan.NONE);
    }

    static Settings settings(Camera cam, List<Light> lights, Background bg, int w, int h) {
        return new Settings("test", "", "", "", lights, cam, bg, 1, 1, 5, 1, w, h);
    }

    static Scene scene(Settings s, Entity... entities) { return new Scene("test", s, List.of(entities)); }
}
