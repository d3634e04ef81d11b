package dev.crt.lang.value;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.lang.value.EntityValue.ModifierKind;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Sphere;
import java.lang.reflect.RecordComponent;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

class EntityValueTest {
    private static final Sphere BALL = new Sphere(Vec3.ZERO, 1, Material.DEFAULT, Transform.IDENTITY, SourceSpan.NONE);

    @Test
    void withoutModifiersTheEntityAndItsSharedIdentityTransformAreKept() {
        Entity e = EntityValue.of(BALL).entity();
        assertThat(e).isSameAs(BALL);
        assertThat(e.transform()).isSameAs(Transform.IDENTITY);
    }

    @Test
    void modifiersApplyInTheOrderWritten() {
        EntityValue ball = EntityValue.of(BALL);
        Vec3 moveThenScale = ball.modified(ModifierKind.TRANSLATE, new Vec3(1, 0, 0))
                .modified(ModifierKind.SCALE, new Vec3(2, 2, 2)).entity().transform().applyToPoint(Vec3.ZERO);
        Vec3 scaleThenMove = ball.modified(ModifierKind.SCALE, new Vec3(2, 2, 2))
                .modified(ModifierKind.TRANSLATE, new Vec3(1, 0, 0)).entity().transform().applyToPoint(Vec3.ZERO);
        assertThat(moveThenScale).isEqualTo(new Vec3(2, 0, 0));
        assertThat(scaleThenMove).isEqualTo(new Vec3(1, 0, 0));
        Vec3 turned = ball.modified(ModifierKind.TRANSLATE, new Vec3(1, 0, 0))
                .modified(ModifierKind.ROTATE, new Vec3(0, 0, 90)).entity().transform().applyToPoint(Vec3.ZERO);
        assertThat(turned).isEqualTo(new Vec3(0, 1, 0));
    }

    @Test
    void aModifierKeepsOnlyItsAmountAndTheValueBefore() {
        // A runaway loop keeps one of these per turn until the loop budget stops it: every field
        // added here costs ten million times its size before the budget's diagnostic can be given.
        for (Class<?> modifier : EntityValue.Modified.class.getPermittedSubclasses()) {
            assertThat(Arrays.stream(modifier.getRecordComponents()).map(RecordComponent::getName))
                    .as(modifier.getSimpleName()).containsExactly("before", "x", "y", "z");
        }
        assertThat(EntityValue.Modified.class.getPermittedSubclasses()).hasSize(3);
    }
}
