package dev.crt.scene;

import java.util.List;

/** A compiled script: its settings and the entities its Scene blocks placed. Immutable. */
public record Scene(String sourceName, Settings settings, List<Entity> entities) {
    public Scene {
        entities = List.copyOf(entities);
    }

    public Scene withSettings(Settings s) { return new Scene(sourceName, s, entities); }
}
