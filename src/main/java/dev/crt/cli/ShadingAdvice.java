package dev.crt.cli;

import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Primitive;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import java.util.ArrayDeque;
import java.util.Deque;

/**
 * Recognises a script written for CRT 2015: in CRT's model, a material that sets
 * {@code reflectivity} without {@code diffuse} looks brighter than it did then (the 2015 program's
 * diffuse was 1 − reflectivity), so such a scene is better seen with {@code --shading original}.
 */
final class ShadingAdvice {
    private ShadingAdvice() {}

    /**
     * Whether {@code scene} looks like a 2015 scene rendered in CRT's model: no Settings extension
     * given (sampler, seed, shading), no material that gives {@code diffuse}, and some material with
     * reflectivity.
     */
    static boolean looksLike2015(Scene scene) {
        Settings s = scene.settings();
        if (s.shading() != Shading.CRT || s.gave("sampler") || s.gave("seed") || s.gave("shading")) return false;
        boolean reflective = false;
        Deque<Entity> todo = new ArrayDeque<>(scene.entities());
        while (!todo.isEmpty()) {
            Entity e = todo.pop();
            if (e instanceof Csg c) {
                todo.push(c.left());
                todo.push(c.right());
            } else {
                Material m = ((Primitive) e).material();
                if (m.diffuseGiven()) return false;
                reflective |= m.reflectivity() > 0;
            }
        }
        return reflective;
    }

    static String note(Object file) {
        return "crt: note: " + file + " looks like a CRT 2015 scene (reflective materials without 'diffuse'); "
                + "render it with --shading original to see it as it looked then";
    }
}
