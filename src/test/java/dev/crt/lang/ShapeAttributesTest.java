package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static dev.crt.lang.Scripts.error;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.scene.Cone;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Scene;
import org.junit.jupiter.api.Test;

/** The second wave's shapes in scripts: attributes, defaults and each diagnostic with its position. */
class ShapeAttributesTest {
    private static void at(Diagnostic d, int line, int column, String message) {
        assertThat(d.message()).isEqualTo(message);
        assertThat(d.span().line()).as("line of: " + message).isEqualTo(line);
        assertThat(d.span().column()).as("column of: " + message).isEqualTo(column);
    }

    @Test
    void cylinderAndConeTakeTheirAttributesAndDefaults() {
        Scene s = Scripts.scene(CAMERA + "Scene { Cylinder { from -> vec3(0,0,0) to -> vec3(0,2,0) }\n"
                + "Cone { from -> vec3(1,0,0) to -> vec3(1,1,0) radius -> 0.5 radius2 -> 0.25 capped -> false } }\n");
        Cylinder c = (Cylinder) s.entities().get(0);
        assertThat(c.to()).isEqualTo(new Vec3(0, 2, 0));
        assertThat(c.radius()).isEqualTo(1);
        assertThat(c.capped()).isTrue();
        Cone k = (Cone) s.entities().get(1);
        assertThat(k.radius()).isEqualTo(0.5);
        assertThat(k.radius2()).isEqualTo(0.25);
        assertThat(k.capped()).isFalse();
        Cone d = (Cone) Scripts.scene(CAMERA + "Scene { Cone { from -> vec3(0,0,0) to -> vec3(0,1,0) } }\n").entities().get(0);
        assertThat(d.radius()).isEqualTo(1);
        assertThat(d.radius2()).isEqualTo(0);
    }

    @Test
    void aTorusHasDefaultsForEverything() {
        dev.crt.scene.Torus t = (dev.crt.scene.Torus) Scripts.scene(CAMERA + "Scene { Torus { } }\n").entities().get(0);
        assertThat(t.center()).isEqualTo(Vec3.ZERO);
        assertThat(t.axis()).isEqualTo(Vec3.Y);
        assertThat(t.major()).isEqualTo(1);
        assertThat(t.minor()).isEqualTo(0.25);
        dev.crt.scene.Torus spindle = (dev.crt.scene.Torus) Scripts.scene(CAMERA
                + "Scene { Torus { axis -> vec3(0, 0, 2) major -> 0.5 minor -> 0.75 } }\n").entities().get(0);
        assertThat(spindle.axis()).isEqualTo(Vec3.Z);
        assertThat(spindle.minor()).isEqualTo(0.75);
    }

    @Test
    void aTorusNeedsAnAxisAndPositiveRadii() {
        at(error("t1 = Torus { axis -> vec3(0, 0, 0) }\n"), 1, 14, "a Torus's axis must not be the zero vector");
        at(error("t1 = Torus {\n  minor -> 0 }\n"), 2, 3, "minor must be > 0, got 0");
        at(error("t1 = Torus { major -> -1 }\n"), 1, 14, "major must be > 0, got -1");
    }

    @Test
    void aCylinderNeedsFromAndTo() {
        at(error("c = Cylinder { from -> vec3(0,0,0) }\n"), 1, 5, "Cylinder needs the attribute 'to'");
    }

    @Test
    void theAxisMustHaveALength() {
        at(error("c = Cylinder { from -> vec3(0,0,0)\n  to -> vec3(-0,0,0) }\n"), 2, 3, "a Cylinder's to must differ from its from");
        at(error("c = Cone { from -> vec3(1,1,1) to -> vec3(1,1,1) }\n"), 1, 32, "a Cone's to must differ from its from");
    }

    @Test
    void radiiAreCheckedWithTheirRanges() {
        at(error("c = Cylinder { from -> vec3(0,0,0) to -> vec3(0,1,0)\n  radius -> 0 }\n"), 2, 3,
                "radius must be > 0, got 0");
        at(error("c = Cone { from -> vec3(0,0,0) to -> vec3(0,1,0)\n  radius2 -> -1 }\n"), 2, 3,
                "radius2 must be >= 0, got -1");
        at(error("c = Cone { from -> vec3(0,0,0) to -> vec3(0,1,0) radius -> 0\n  radius2 -> 0 }\n"), 2, 3,
                "a Cone's radius and radius2 cannot both be 0");
    }

    @Test
    void cappedIsABoolean() {
        at(error("c = Cylinder { from -> vec3(0,0,0) to -> vec3(0,1,0)\n  capped -> 1 }\n"), 2, 3,
                "attribute 'capped' of Cylinder expects a boolean, got number");
    }

    @Test
    void anOpenTubeCannotBeACsgOperand() {
        at(error("tube = Cylinder { from -> vec3(0,0,0) to -> vec3(0,1,0) capped -> false }\n"
                + "s = Sphere { }\nu = s - tube\n"), 3, 5,
                "an open Cylinder (capped -> false) is a surface, not a solid, so it cannot be used in CSG");
        at(error("tube = Cone { from -> vec3(0,0,0) to -> vec3(0,1,0) capped -> false }\nu = tube + Sphere { }\n"), 2, 5,
                "an open Cone (capped -> false) is a surface, not a solid, so it cannot be used in CSG");
    }
}
