package dev.crt.lang.value;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Entity;
import java.util.ArrayList;
import java.util.List;

/**
 * An entity with the modifiers applied to it since it was built. The modifiers stay a chain of
 * values, one per modifier, and are folded into the entity's transform only when the entity is
 * placed or combined: a loop that moves a sphere ten million times must not build ten million
 * pairs of matrices.
 */
public record EntityValue(Entity base, ModifierKind kind, Vec3 amount, EntityValue before) implements Value {
    /** The kinds of modifier a script writes inside {@code < >}. */
    public enum ModifierKind { TRANSLATE, ROTATE, SCALE }

    public static EntityValue of(Entity entity) { return new EntityValue(entity, null, null, null); }

    public EntityValue modified(ModifierKind k, Vec3 by) { return new EntityValue(base, k, by, this); }

    /** The entity with every modifier applied, in the order written, each about the world origin. */
    public Entity entity() {
        if (kind == null) return base;
        List<EntityValue> inOrder = new ArrayList<>();
        for (EntityValue m = this; m.kind != null; m = m.before) inOrder.add(m);
        Transform t = Transform.IDENTITY;
        for (int i = inOrder.size() - 1; i >= 0; i--) {
            EntityValue m = inOrder.get(i);
            t = t.then(switch (m.kind) {
                case TRANSLATE -> Transform.translation(m.amount);
                case ROTATE -> Transform.rotation(m.amount);
                case SCALE -> Transform.scaling(m.amount);
            });
        }
        return base.transformed(t);
    }

    @Override
    public String typeName() { return "entity"; }
}
