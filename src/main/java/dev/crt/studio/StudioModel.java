package dev.crt.studio;

import dev.crt.lang.CompileResult;
import dev.crt.scene.Entity;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * What the studio shows: the open scripts, which one is current, and the entity selected in it.
 * Every panel (editor, render view, and the navigator, property sheet and animation panels to come)
 * subscribes here instead of talking to the others. Used on the Event Dispatch Thread only.
 */
public final class StudioModel {
    /** Told about the studio's state, on the Event Dispatch Thread. */
    public interface Listener {
        default void opened(ScriptDocument document) {}

        default void closed(ScriptDocument document) {}

        /** The current document changed (null when none is open). */
        default void currentChanged(ScriptDocument document) {}

        /** Any open document's text, file or modified flag changed. */
        default void documentChanged(ScriptDocument document) {}

        /** A compile of {@code document} finished. */
        default void compiled(ScriptDocument document, CompileResult result) {}

        /** An entity of the current document's scene was selected (index in scene.entities()), or cleared (null). */
        default void selected(ScriptDocument document, Entity entity, int index) {}

        /** The scene time t the studio looks at changed (the animation panel's scrub position). */
        default void timeChanged(double t) {}
    }

    private final List<ScriptDocument> documents = new ArrayList<>();
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private final ScriptDocument.Listener relay = new ScriptDocument.Listener() {
        @Override public void changed(ScriptDocument d) { listeners.forEach(l -> l.documentChanged(d)); }

        @Override public void compiled(ScriptDocument d, CompileResult r) { listeners.forEach(l -> l.compiled(d, r)); }
    };
    private ScriptDocument current;
    private int untitled;
    private ScriptDocument selectedDocument;
    private Entity selectedEntity;
    private int selectedIndex = -1;

    public List<ScriptDocument> documents() { return List.copyOf(documents); }

    public ScriptDocument current() { return current; }

    /** A new, empty, unsaved script. */
    public ScriptDocument newDocument() {
        ScriptDocument d = new ScriptDocument("untitled-" + (++untitled) + ".crt");
        add(d);
        return d;
    }

    /** A document with the text of {@code file}, read at {@code time}. */
    public ScriptDocument open(String content, Path file, java.nio.file.attribute.FileTime time) {
        ScriptDocument d = new ScriptDocument("untitled-" + (++untitled) + ".crt");
        d.load(content, file, time);
        add(d);
        return d;
    }

    /** The open document of {@code file}, if any. */
    public Optional<ScriptDocument> find(Path file) {
        Path wanted = file.toAbsolutePath().normalize();
        return documents.stream().filter(d -> d.file() != null && d.file().toAbsolutePath().normalize().equals(wanted)).findFirst();
    }

    /** The open document whose compiler name is {@code name} (as diagnostics print it). */
    public Optional<ScriptDocument> findByName(String name) {
        return documents.stream().filter(d -> d.source().name().equals(name) || d.name().equals(name)).findFirst();
    }

    private void add(ScriptDocument d) {
        documents.add(d);
        d.addListener(relay);
        listeners.forEach(l -> l.opened(d));
        setCurrent(d);
    }

    public void setCurrent(ScriptDocument d) {
        if (d == current) return;
        current = d;
        listeners.forEach(l -> l.currentChanged(d));
    }

    public void close(ScriptDocument d) {
        int at = documents.indexOf(d);
        if (at < 0) return;
        documents.remove(at);
        d.removeListener(relay);
        listeners.forEach(l -> l.closed(d));
        if (selectedDocument == d) select(d, null, -1);
        if (current == d) setCurrent(documents.isEmpty() ? null : documents.get(Math.min(at, documents.size() - 1)));
    }

    /**
     * Selects {@code entity}, number {@code index} of {@code d}'s scene (null and −1 clear the
     * selection) and tells every listener, also the panel that asked: the render view, the live
     * view and the navigator all select through here, so each shows what another picked.
     */
    public void select(ScriptDocument d, Entity entity, int index) {
        selectedDocument = entity == null ? null : d;
        selectedEntity = entity;
        selectedIndex = entity == null ? -1 : index;
        listeners.forEach(l -> l.selected(d, entity, selectedIndex));
    }

    public void addListener(Listener l) { listeners.add(l); }

    public void removeListener(Listener l) { listeners.remove(l); }

    /** The scene time t the studio looks at (the Animation panel's scrub position): 0 until it is scrubbed. */
    private double time;

    public double time() { return time; }

    /** Sets the studio's t and tells the listeners ({@link Listener#timeChanged}) when it changed. */
    public void setTime(double t) {
        if (t == time) return;
        time = t;
        listeners.forEach(l -> l.timeChanged(t));
    }

    /** Selects entity {@code index} of the scene of {@code d}'s latest compile; out of range (or −1) clears. */
    public void select(ScriptDocument d, int index) {
        CompileResult r = d == null ? null : d.result();
        List<Entity> entities = r == null || r.scene() == null ? List.of() : r.scene().entities();
        if (index >= 0 && index < entities.size()) select(d, entities.get(index), index);
        else select(d, null, -1);
    }

    /** The document whose entity is selected, or null when nothing is. */
    public ScriptDocument selectedDocument() { return selectedDocument; }

    /** The selected entity, or null. */
    public Entity selectedEntity() { return selectedEntity; }

    /** The selected entity's index in its scene's entities(), or −1. */
    public int selectedIndex() { return selectedIndex; }

}
