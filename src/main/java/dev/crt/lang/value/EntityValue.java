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
 * million pairs of matrices. The runaway loop of the original CRT keeps one such value per turn,
 * so each is as small as it can be: the amount as three doubles, the kind as the record's class
 * (40 bytes with compressed pointers, where a kind field made it 48).
 */
public sealed interface EntityValue extends Value {
    /** The kinds of modifier a script writes inside {@code < >}. */
    enum ModifierKind { TRANSLATE, ROTATE, SCALE }

    static EntityValue of(Entity entity) { return new Built(entity); }

    /** The entity with every modifier applied, in the order written, each about the world origin. */
    Entity entity();

    default EntityValue modified(ModifierKind kind, Vec3 by) {
        return switch (kind) {
            case TRANSLATE -> new Translated(this, by.x(), by.y(), by.z());
            case ROTATE -> new Rotated(this, by.x(), by.y(), by.z());
            case SCALE -> new Scaled(this, by.x(), by.y(), by.z());
        };
    }

    @Override
    default String typeName() { return "entity"; }

    /** An entity as its constructor made it, before any modifier. */
    record Built(Entity entity) implements EntityValue {}

    /** {@code before <translate vec3(x, y, z)>}. */
    record Translated(EntityValue before, double x, double y, double z) implements Modified {
        @Override
        public Transform transform() { return Transform.translation(new Vec3(x, y, z)); }
    }

    /** {@code before <rotate vec3(x, y, z)>}, in degrees. */
    record Rotated(EntityValue before, double x, double y, double z) implements Modified {
        @Override
        public Transform transform() { return Transform.rotation(new Vec3(x, y, z)); }
    }

    /** {@code before <scale vec3(x, y, z)>}. */
    record Scaled(EntityValue before, double x, double y, double z) implements Modified {
        @Override
        public Transform transform() { return Transform.scaling(new Vec3(x, y, z)); }
    }

    /** One modifier applied to an entity value. */
    sealed interface Modified extends EntityValue permits Translated, Rotated, Scaled {
        EntityValue before();

        /** This modifier alone. */
        Transform transform();

        @Override
        default Entity entity() {
            List<Modified> inOrder = new ArrayList<>();
            EntityValue v = this;
            while (v instanceof Modified m) {
                inOrder.add(m);
                v = m.before();
            }
            Transform t = Transform.IDENTITY;
            for (int i = inOrder.size() - 1; i >= 0; i--) t = t.then(inOrder.get(i).transform());
            return ((Built) v).entity().transformed(t);
        }
    }
}
