package dev.crt.render;

import dev.crt.geom.Vec3;
import dev.crt.scene.Box;
import dev.crt.scene.Camera;
import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.Plane;
import dev.crt.scene.PointLight;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.Sphere;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes a benchmark scene as POV-Ray 3.7 source, for side-by-side timing. Only what the benchmark
 * scenes use: untransformed spheres, boxes, planes and difference CSG, point and parallel lights,
 * a gradient sky. Run:
 * <pre>java -cp target/classes:target/test-classes dev.crt.render.PovExport bench.pov</pre>
 * then {@code povray +Ibench.pov +Obench-pov.png +W1280 +H720 -A -D +WT2}.
 */
public final class PovExport {
    private PovExport() {}

    private static String v(Vec3 p) { return String.format(Locale.ROOT, "<%.9g, %.9g, %.9g>", p.x(), p.y(), p.z()); }

    private static String texture(Material m) {
        return String.format(Locale.ROOT,
                "texture { pigment { color rgbf <%.6g, %.6g, %.6g, %.6g> } finish { ambient 0.0 diffuse %.6g phong %.6g "
                        + "phong_size %.6g reflection %.6g } }%s",
                m.color().r(), m.color().g(), m.color().b(), m.transparency(), m.diffuse(), m.specular(), m.shininess(),
                m.reflectivity(), m.transparency() > 0 ? String.format(Locale.ROOT, " interior { ior %.6g }", m.ior()) : "");
    }

    private static String entity(Entity e) {
        if (e instanceof Sphere s) return "sphere { " + v(s.center()) + ", " + s.radius() + " " + texture(s.material()) + " }";
        if (e instanceof Box b) return "box { " + v(b.min()) + ", " + v(b.max()) + " " + texture(b.material()) + " }";
        if (e instanceof Plane p) {
            return "plane { " + v(p.normal()) + ", " + p.normal().dot(p.position()) + " " + texture(p.material()) + " }";
        }
        Csg c = (Csg) e;
        String op = switch (c.operation()) {
            case UNION -> "union";
            case INTERSECTION -> "intersection";
            case DIFFERENCE -> "difference";
        };
        return op + " { " + entity(c.left()) + "\n  " + entity(c.right()) + " }";
    }

    static String toPov(Scene scene) {
        Settings s = scene.settings();
        StringBuilder b = new StringBuilder();
        b.append("#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level ").append(s.recursionDepth() + 1)
                .append(" ambient_light rgb <1,1,1> }\n");
        Camera c = s.camera();
        double aspect = (double) s.width() / s.height();
        double hfov = Math.toDegrees(2 * Math.atan(Math.tan(Math.toRadians(c.fov() / 2)) * aspect));
        b.append("camera { perspective location ").append(v(c.position())).append(" right x*").append(aspect)
                .append(" up y look_at ").append(v(c.pointing())).append(" angle ").append(hfov).append(" }\n");
        if (s.background() instanceof GradientBackground g) {
            b.append(String.format(Locale.ROOT, "sky_sphere { pigment { gradient y color_map { [0 rgb <%g,%g,%g>] [1 rgb <%g,%g,%g>] } } }\n",
                    g.horizon().r(), g.horizon().g(), g.horizon().b(), g.sky().r(), g.sky().g(), g.sky().b()));
        }
        for (Light l : s.lights()) {
            String color = String.format(Locale.ROOT, "color rgb <%g, %g, %g>", l.color().r(), l.color().g(), l.color().b());
            if (l instanceof PointLight p) b.append("light_source { ").append(v(p.origin())).append(" ").append(color).append(" }\n");
            else {
                ParallelLight p = (ParallelLight) l;
                b.append("light_source { ").append(v(p.from().times(1000))).append(" ").append(color)
                        .append(" parallel point_at ").append(v(p.pointing())).append(" }\n");
            }
        }
        for (Entity e : scene.entities()) b.append(entity(e)).append('\n');
        return b.toString();
    }

    public static void main(String[] args) throws IOException {
        Path out = Path.of(args.length > 0 ? args[0] : "bench.pov");
        Files.writeString(out, toPov(RenderBench.boxes(1280, 720)));
        System.out.println("wrote " + out);
    }
}
