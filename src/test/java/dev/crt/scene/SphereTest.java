package dev.crt.scene;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import org.junit.jupiter.api.Test;

/** A sphere holds its centre as three numbers (no Vec3 of its own) and acts as when it held one. */
class SphereTest {
    @Test
    void theCentreComesBackAsItWasGivenAndEqualSpheresAreEqual() {
        Material m = Material.DEFAULT;
        Sphere a = new Sphere(new Vec3(1.5, -0.0, 1e300), 2, m, Transform.IDENTITY, null);
        assertThat(a.center()).isEqualTo(new Vec3(1.5, -0.0, 1e300));
        assertThat(a.x()).isEqualTo(1.5);
        assertThat(a).isEqualTo(new Sphere(1.5, -0.0, 1e300, 2, m, Transform.IDENTITY, null))
                .hasSameHashCodeAs(new Sphere(1.5, -0.0, 1e300, 2, m, Transform.IDENTITY, null))
                .isNotEqualTo(new Sphere(1.5, 0.0, 1e300, 2, m, Transform.IDENTITY, null));
        Transform t = Transform.translation(new Vec3(1, 2, 3));
        Sphere moved = a.transformed(t);
        assertThat(moved.center()).isEqualTo(a.center());
        assertThat(moved.transform()).isEqualTo(Transform.IDENTITY.then(t));
        assertThat(moved.radius()).isEqualTo(2);
    }
}
