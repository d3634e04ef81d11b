package dev.crt.lang.value;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Entity;
import java.util.ArrayList;
import java.util.List;

/**
 * An entity with the modifiers applied to it since it was built. Each modifier is one small
 * value linked to the one before, and they are folded into the entity's transform only when the
 * entity is placed or combined: a loop that moves a sphere ten million times must not build ten
 * million pairs of matrices (the amount is kept as three doubles for the same reason).
 */
public record EntityValue(Entity base, ModifierKind kind, double x, double y, double z, EntityValue before)
        implements Value {
    /** The kinds of modifier a script writes inside {@code < >}. */
    public enum ModifierKind { TRANSLATE, ROTATE, SCALE }

    public static EntityValue of(Entity entity) { return new EntityValue(entity, null, 0, 0, 0, null); }

    public EntityValue modified(ModifierKind k, Vec3 by) { return new EntityValue(base, k, by.x(), by.y(), by.z(), this); }

    /** The entity with every modifier applied, in the order written, each about the world origin. */
    public Entity entity() {
        if (kind == null) return base;
        List<EntityValue> inOrder = new ArrayList<>();
        for (EntityValue m = this; m.kind != null; m = m.before) inOrder.add(m);
        Transform t = Transform.IDENTITY;
        for (int i = inOrder.size() - 1; i >= 0; i--) {
            EntityValue m = inOrder.get(i);
            Vec3 amount = new Vec3(m.x, m.y, m.z);
            t = t.then(switch (m.kind) {
                case TRANSLATE -> Transform.translation(amount);
                case ROTATE -> Transform.rotation(amount);
                case SCALE -> Transform.scaling(amount);
            });
        }
        return base.transformed(t);
    }

    @Override
    public String typeName() { return "entity"; }
}
