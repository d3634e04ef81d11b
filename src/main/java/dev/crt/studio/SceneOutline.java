package dev.crt.studio;

import dev.crt.lang.CompileResult;
import dev.crt.lang.SourceMap;
import dev.crt.lang.SourceMap.Expr;
import dev.crt.lang.SourceMap.MacroCall;
import dev.crt.lang.SourceMap.ObjectInfo;
import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.Light;
import dev.crt.scene.Scene;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * The navigator's tree of a compiled script: Settings, Camera, Background, Lights and Entities, CSG
 * operations with their operands, macro-made entities under the call that made them. Each node
 * knows the code that wrote it; its key (the path of labels) stays the same across compiles as
 * long as the objects keep their names, so expansion and selection survive a recompile.
 */
final class SceneOutline {
    /** What a node stands for; the icon and the property sheet depend on it. */
    enum Kind { ROOT, SETTINGS, CAMERA, BACKGROUND, LIGHTS, LIGHT, ENTITIES, ENTITY, OPERATION, CALL }

    /** One node of the tree. {@code entityIndex} is the placed entity it belongs to (for the render view's highlight), else -1. */
    record Node(Kind kind, String label, String key, SourceSpan span, ObjectInfo info, MacroCall call, int entityIndex,
            List<Node> children) {
        /** The type written (Sphere, PointLight, Union…), or the label for groups. */
        String type() { return info != null ? info.type() : label; }

        boolean contains(int offset) { return span != null && span.line() > 0 && span.start() <= offset && offset < Math.max(span.end(), span.start() + 1); }

        @Override
        public String toString() { return label; }
    }

    private final SourceMap map;
    private final String text;

    private SceneOutline(SourceMap map, String text) {
        this.map = map;
        this.text = text;
    }

    /** The tree of a successful compile that recorded a source map (else null). */
    static Node of(CompileResult result, String text) {
        if (result == null || result.scene() == null || result.sourceMap() == null) return null;
        return new SceneOutline(result.sourceMap(), text).root(result.scene());
    }

    private Node root(Scene scene) {
        List<Node> top = new ArrayList<>();
        if (!map.settings().isEmpty()) {
            ObjectInfo first = map.settings().get(0);
            top.add(new Node(Kind.SETTINGS, "Settings", "Settings", first.span(), first, null, -1, List.of()));
        }
        SourceSpan camera = scene.settings().camera().span();
        ObjectInfo cameraInfo = camera.line() > 0 ? map.objectAt(camera.start()) : null;
        if (cameraInfo != null) top.add(leaf(Kind.CAMERA, cameraInfo, "", -1, null));
        ObjectInfo background = settingsObject("background");
        if (background != null) top.add(leaf(Kind.BACKGROUND, background, "", -1, null));
        List<Node> lights = new ArrayList<>();
        Map<String, Integer> seen = new HashMap<>();
        for (Light light : scene.settings().lights()) {
            ObjectInfo info = light.span().line() > 0 ? map.objectAt(light.span().start()) : null;
            String label = twin(info == null ? light.getClass().getSimpleName() : label(info), seen);
            lights.add(new Node(Kind.LIGHT, label, "Lights/" + label, info == null ? light.span() : info.span(),
                    info, null, -1, List.of()));
        }
        top.add(new Node(Kind.LIGHTS, "Lights", "Lights", null, null, null, -1, lights));

        List<Node> entities = new ArrayList<>();
        Map<MacroCall, List<Node>> calls = new IdentityHashMap<>();
        Map<MacroCall, String> callKeys = new IdentityHashMap<>();
        Map<MacroCall, Map<String, Integer>> callSeen = new IdentityHashMap<>();
        Map<String, Integer> entityKeys = new HashMap<>();
        List<Entity> placed = scene.entities();
        for (int i = 0; i < placed.size(); i++) {
            MacroCall call = map.callOf(i);
            if (call == null) {
                entities.add(entity(placed.get(i), i, "Entities", entityKeys, null));
                continue;
            }
            List<Node> group = calls.get(call);
            if (group == null) {
                group = new ArrayList<>();
                calls.put(call, group);
                String label = twin(callLabel(call), entityKeys);
                String key = "Entities/" + label;
                callKeys.put(call, key);
                callSeen.put(call, new HashMap<>());
                entities.add(new Node(Kind.CALL, label, key, call.span(), null, call, -1, group));
            }
            // Grouped under the top-level call; edited through the call that made it (a macro called from a macro).
            group.add(entity(placed.get(i), i, callKeys.get(call), callSeen.get(call), map.makerOf(i)));
        }
        top.add(new Node(Kind.ENTITIES, "Entities", "Entities", null, null, null, -1, entities));
        return new Node(Kind.ROOT, scene.sourceName(), "", null, null, null, -1, top);
    }

    private Node entity(Entity e, int index, String parentKey, Map<String, Integer> seen, MacroCall call) {
        if (e instanceof Csg c) {
            ObjectInfo info = map.operation(c.span());
            String label = twin(info == null ? c.operation().name() : label(info), seen);
            String key = parentKey + "/" + label;
            Map<String, Integer> inner = new HashMap<>();
            List<Node> operands = List.of(entity(c.left(), index, key, inner, call), entity(c.right(), index, key, inner, call));
            return new Node(Kind.OPERATION, label, key, c.span(), info, call, index, operands);
        }
        ObjectInfo info = e.span().line() > 0 ? map.objectAt(e.span().start()) : null;
        String label = twin(info == null ? e.getClass().getSimpleName() : label(info), seen);
        return new Node(Kind.ENTITY, label, parentKey + "/" + label, e.span(), info, call, index, List.of());
    }

    private Node leaf(Kind kind, ObjectInfo info, String parentKey, int index, MacroCall call) {
        String label = label(info);
        return new Node(kind, label, parentKey + label, info.span(), info, call, index, List.of());
    }

    /** The object literal a Settings attribute names, written in place or through a variable assigned once. */
    private ObjectInfo settingsObject(String attribute) {
        Expr e = null;
        for (ObjectInfo block : map.settings()) if (block.attributes().containsKey(attribute)) e = block.attributes().get(attribute);
        return e == null ? null : resolve(map, e);
    }

    /** The object literal an expression is, directly or through a variable assigned once; else null. */
    static ObjectInfo resolve(SourceMap map, Expr e) {
        if (e.kind() == SourceMap.Kind.OBJECT) return map.objectAt(e.start());
        if (e.kind() == SourceMap.Kind.VARIABLE) {
            Expr def = map.definitions().get(e.name());
            if (def != null && def.kind() == SourceMap.Kind.OBJECT) return map.objectAt(def.start());
        }
        return null;
    }

    /** "Sphere ball", or just "Sphere" when it was not assigned to a variable. */
    static String label(ObjectInfo info) { return info.variable() == null ? info.type() : info.type() + " " + info.variable(); }

    private String callLabel(MacroCall call) {
        String written = text.substring(call.span().start(), Math.min(call.span().end(), text.length())).replaceAll("\\s+", " ");
        return written.length() > 40 ? written.substring(0, 39) + "…" : written;
    }

    /** The label, numbered from the second sibling of the same label on ("Sphere", "Sphere #2"…), so that twins keep apart. */
    private static String twin(String label, Map<String, Integer> seen) {
        int n = seen.merge(label, 1, Integer::sum);
        return n == 1 ? label : label + " #" + n;
    }

    /** The node with the smallest piece of code that holds {@code offset} (the innermost object there), or null. */
    static Node at(Node root, int offset) {
        Node[] best = {null};
        visit(root, n -> {
            if (n.kind() == Kind.ROOT || !n.contains(offset)) return;
            int size = n.span().end() - n.span().start();
            if (best[0] == null || size <= best[0].span().end() - best[0].span().start()) best[0] = n;
        });
        return best[0];
    }

    private static void visit(Node n, java.util.function.Consumer<Node> action) {
        if (n == null) return;
        action.accept(n);
        for (Node child : n.children()) visit(child, action);
    }

    /** The first node with the key, or null. */
    static Node find(Node root, String key) {
        if (root == null) return null;
        if (root.key().equals(key)) return root;
        for (Node child : root.children()) {
            Node found = find(child, key);
            if (found != null) return found;
        }
        return null;
    }

    /** The outermost node of placed entity {@code index}, or null. */
    static Node ofEntity(Node root, int index) {
        if (root == null) return null;
        if (root.entityIndex() == index) return root;
        for (Node child : root.children()) {
            Node found = ofEntity(child, index);
            if (found != null) return found;
        }
        return null;
    }
}
