package dev.crt.geom;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class TransformTest {
    @Test
    void rotateNinetyAboutYTakesXToMinusZ() {
        Vec3 p = Transform.rotation(new Vec3(0, 90, 0)).applyToPoint(Vec3.X);
        assertThat(p).isEqualTo(new Vec3(0, 0, -1));
    }

    @Test
    void rotationsApplyAboutXThenYThenZ() {
        // x by 90 takes +y to +z; then y by 90 takes +z to +x.
        Vec3 p = Transform.rotation(new Vec3(90, 90, 0)).applyToPoint(Vec3.Y);
        assertThat(p).isEqualTo(new Vec3(1, 0, 0));
    }

    @Test
    void thenAppliesInOrderAndInverseUndoes() {
        Transform t = Transform.scaling(new Vec3(2, 3, 4))
                .then(Transform.rotation(new Vec3(10, 20, 30)))
                .then(Transform.translation(new Vec3(5, -6, 7)));
        Vec3 p = new Vec3(0.3, -1.2, 2.5);
        Vec3 q = t.applyToPoint(p);
        Vec3 manual = Transform.translation(new Vec3(5, -6, 7)).applyToPoint(
                Transform.rotation(new Vec3(10, 20, 30)).applyToPoint(new Vec3(0.6, -3.6, 10)));
        assertThat(q.minus(manual).length()).isLessThan(1e-12);
        assertThat(t.inverse().applyToPoint(q).minus(p).length()).isLessThan(1e-12);
    }

    @Test
    void normalsStayPerpendicularUnderNonUniformScale() {
        Transform t = Transform.scaling(new Vec3(1, 4, 1)).then(Transform.rotation(new Vec3(0, 0, 30)));
        Vec3 tangent = new Vec3(1, -1, 0);
        Vec3 normal = new Vec3(1, 1, 0);
        assertThat(t.applyToVector(tangent).dot(t.applyToNormal(normal))).isCloseTo(0, within(1e-12));
    }
}
