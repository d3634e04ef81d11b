package dev.crt.studio;

import dev.crt.geom.Vec3;
import dev.crt.lang.SourceMap;
import dev.crt.lang.SourceMap.Expr;
import dev.crt.lang.SourceMap.MacroCall;
import dev.crt.lang.SourceMap.ObjectInfo;
import dev.crt.scene.Rgb;
import dev.crt.studio.PropertyTypes.Spec;
import dev.crt.studio.PropertyTypes.Type;
import dev.crt.studio.SceneOutline.Kind;
import dev.crt.studio.SceneOutline.Node;
import java.awt.BorderLayout;
import java.awt.Color;
import java.beans.PropertyEditor;
import java.beans.PropertyVetoException;
import java.lang.reflect.InvocationTargetException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;
import javax.swing.UIManager;
import org.openide.explorer.propertysheet.PropertySheet;
import org.openide.nodes.AbstractNode;
import org.openide.nodes.Children;
import org.openide.nodes.PropertySupport;
import org.openide.nodes.Sheet;

/**
 * The Properties panel: the selected navigator node's attributes in a NetBeans property sheet.
 * Literal attributes (and those that come from a variable assigned once with a literal, or from a
 * literal macro argument) are editable, and an edit becomes an edit of the script through
 * {@link Writer}; attributes computed by an expression are shown read-only with the expression.
 */
final class PropertiesPanel extends JPanel {
    /** Writes a new literal into the script; returns null when done, else why it was not. */
    interface Writer {
        /** For an attribute of an object (in place, through its variable or macro argument, or inserted). */
        String write(ObjectInfo object, MacroCall call, String attribute, String literal);

        /** In place of a literal expression (a macro call's argument), {@code what} naming it. */
        String replace(Expr literalExpr, String literal, String what);
    }

    /**
     * Built at the first selection, not with the window: loading it takes 0.5 to 1.2 s of the EDT
     * cold (measured on the loaded 2-core machine), which start-up and the first keystrokes should not wait for.
     */
    private PropertySheet sheet;
    private final JLabel placeholder = new JLabel("Select an object in the navigator or the script", JLabel.CENTER);
    private final JLabel message = new JLabel(" ");
    private final JLabel title = new JLabel("Nothing selected");
    private Writer writer;
    private Node shown;
    private SourceMap map;

    PropertiesPanel() {
        super(new BorderLayout());
        placeholder.setEnabled(false);
        title.setName("propertiesTitle");
        title.setBorder(BorderFactory.createEmptyBorder(3, 6, 3, 6));
        message.setName("propertiesMessage");
        message.getAccessibleContext().setAccessibleName("Properties message");
        message.setBorder(BorderFactory.createEmptyBorder(3, 6, 3, 6));
        add(title, BorderLayout.NORTH);
        add(placeholder, BorderLayout.CENTER);
        add(message, BorderLayout.SOUTH);
    }

    void writer(Writer w) { writer = w; }

    PropertySheet sheet() {
        if (sheet == null) {
            sheet = new PropertySheet();
            sheet.setName("propertySheet");
            sheet.getAccessibleContext().setAccessibleName("Properties");
            try {
                sheet.setSortingMode(PropertySheet.UNSORTED);
            } catch (PropertyVetoException e) {
                // The sheet keeps its own order then; nothing is lost.
            }
            sheet.setDescriptionAreaVisible(true);
            remove(placeholder);
            add(sheet, BorderLayout.CENTER);
            revalidate();
            repaint();
        }
        return sheet;
    }

    JLabel message() { return message; }

    Node shown() { return shown; }

    /**
     * Takes {@code node} as the one shown and makes the sheet's node of it, whose property sets are
     * the sheet's rows (null for none); {@link #show} puts it in the sheet.
     */
    org.openide.nodes.Node sheetNode(Node node, SourceMap sourceMap) {
        shown = node;
        map = sourceMap;
        return node == null || sourceMap == null ? null : new ObjectNode(node, sourceMap);
    }

    /** Says what happened to the last edit: done (plain) or refused (in red). */
    void say(String text, boolean refused) {
        message.setText(text == null || text.isEmpty() ? " " : text);
        message.setToolTipText(text);
        message.setForeground(refused ? new Color(0xC62828) : UIManager.getColor("Label.foreground"));
    }

    /** Shows the properties of {@code node} as written in the compile that {@code sourceMap} describes. */
    void show(Node node, SourceMap sourceMap) {
        org.openide.nodes.Node shownNode = sheetNode(node, sourceMap);
        title.setText(node == null ? "Nothing selected" : node.label() + (node.span() != null && node.span().line() > 0
                ? "  (line " + node.span().line() + ")" : ""));
        if (node == null && sheet == null) return;
        sheet().getAccessibleContext().setAccessibleDescription(node == null ? "" : "Properties of " + node.label());
        sheet.setNodes(shownNode == null ? new org.openide.nodes.Node[0] : new org.openide.nodes.Node[] {shownNode});
    }

    /** Shows the same node again, with the values as written now (after a refused edit). */
    private void refresh() { SwingUtilities.invokeLater(() -> show(shown, map)); }

    private final class ObjectNode extends AbstractNode {
        private final Node node;
        /**
         * The compile the node was made from: the sheet builds its rows later, on the library's
         * own thread, by when the panel may already show another compile or nothing.
         */
        private final SourceMap map;

        ObjectNode(Node node, SourceMap map) {
            super(Children.LEAF);
            this.node = node;
            this.map = map;
            setName(node.label());
            setDisplayName(node.label());
        }

        @Override
        protected Sheet createSheet() {
            Sheet s = Sheet.createDefault();
            Sheet.Set main = Sheet.createPropertiesSet();
            main.setDisplayName(node.label());
            s.put(main);
            if (node.kind() == Kind.SETTINGS) {
                settings(main);
            } else if (node.kind() == Kind.CALL) {
                call(main, node.call());
            } else if (node.info() != null && node.kind() == Kind.OPERATION) {
                main.put(text("operation", node.info().type(), "The CSG operation: + is a union, - a difference, ^ an intersection"));
                if (node.info().variable() != null) main.put(text("variable", node.info().variable(), "The variable it is assigned to"));
            } else if (node.info() != null) {
                object(s, main, node.info(), node.call());
            }
            return s;
        }

        private void settings(Sheet.Set set) {
            // Later Settings blocks override earlier ones: each attribute is edited where it was written last.
            Map<String, ObjectInfo> where = new LinkedHashMap<>();
            for (ObjectInfo block : map.settings()) for (String a : block.attributes().keySet()) where.put(a, block);
            ObjectInfo last = map.settings().get(map.settings().size() - 1);
            for (Spec spec : PropertyTypes.of("Settings").values()) set.put(property(map, where.getOrDefault(spec.name(), last), null, spec));
        }

        private void call(Sheet.Set set, MacroCall call) {
            set.put(text("macro", call.macro(), "The macro this call runs"));
            for (int i = 0; i < call.arguments().size() && i < call.parameters().size(); i++) {
                Expr arg = call.arguments().get(i);
                String parameter = call.parameters().get(i);
                Type type = switch (arg.kind()) {
                    case NUMBER -> Type.NUMBER;
                    case VECTOR -> Type.VECTOR;
                    case COLOR -> Type.COLOR;
                    case STRING -> Type.STRING;
                    case BOOLEAN -> Type.BOOLEAN;
                    default -> null;
                };
                if (type == null) {
                    set.put(text(parameter, "= " + arg.text(), "Computed by an expression: edit it in the script"));
                    continue;
                }
                Spec spec = new Spec(parameter, type, arg.text(), Double.NEGATIVE_INFINITY, false, Double.POSITIVE_INFINITY, false, List.of());
                set.put(editable(spec, parameter, parse(spec, arg.text()), "The argument of this call: every entity the call makes changes",
                        lit -> writer.replace(arg, lit, "changed the argument " + parameter + " of " + call.macro() + "(…) at line "
                                + call.span().line())));
            }
        }

        private void object(Sheet s, Sheet.Set main, ObjectInfo info, MacroCall call) {
            Map<String, Spec> specs = PropertyTypes.of(info.type());
            for (Spec spec : specs.values()) {
                if (spec.type() == Type.MATERIAL) material(s, info, call);
                else main.put(property(map, info, call, spec));
            }
            for (Map.Entry<String, Expr> e : info.attributes().entrySet()) {
                if (!specs.containsKey(e.getKey())) main.put(text(e.getKey(), e.getValue().text(), "Written in the script"));
            }
        }

        /** The material as a set of its own (the sheet shows it as an expandable group). */
        private void material(Sheet s, ObjectInfo entity, MacroCall call) {
            Expr m = entity.attributes().get("material");
            Sheet.Set set = new Sheet.Set();
            set.setName("material");
            ObjectInfo info = m == null ? null : SceneOutline.resolve(map, m);
            String shared = m != null && m.kind() == SourceMap.Kind.VARIABLE ? " (variable " + m.name() + ", shared)" : "";
            set.setDisplayName("Material" + shared);
            s.put(set);
            if (m != null && info == null) {
                set.put(text("material", m.text(), "Computed by an expression: edit it in the script"));
                return;
            }
            for (Spec spec : PropertyTypes.of("Material").values()) {
                if (info != null) set.put(property(map, info, call, spec));
                else set.put(defaultMaterial(entity, call, spec));
            }
        }

        /** A property of the default material: setting it writes {@code material -> Material { … }} into the entity. */
        private org.openide.nodes.Node.Property<?> defaultMaterial(ObjectInfo entity, MacroCall call, Spec spec) {
            return editable(spec, spec.name(), parse(spec, spec.defaultText()), "Not written: the default. Setting it adds a material",
                    literal -> writer.write(entity, call, "material", "Material { " + spec.name() + " -> " + literal + " }"));
        }
    }

    /**
     * One attribute of {@code info}, of the compile {@code map} describes: editable when the script
     * lets it be rewritten as a literal, else read-only text.
     */
    private org.openide.nodes.Node.Property<?> property(SourceMap map, ObjectInfo info, MacroCall call, Spec spec) {
        Expr e = info.attributes().get(spec.name());
        String name = spec.name();
        if (spec.type() == Type.OTHER || spec.type() == Type.MATERIAL) {
            return text(name, e == null ? "(not written)" : e.text(), "Edit it in the script");
        }
        String literal;
        String note;
        if (e == null) {
            literal = spec.defaultText();
            note = "Not written: the default" + (literal == null ? " is computed" : "") + ". Setting it adds the attribute to the script";
        } else if (e.kind().isLiteral()) {
            literal = e.text();
            note = info.inMacro() ? "Written inside a macro, for every call of it" : "Written in the script";
        } else if (e.kind() == SourceMap.Kind.VARIABLE && map.definitions().get(e.name()) != null
                && map.definitions().get(e.name()).kind().isLiteral()) {
            literal = map.definitions().get(e.name()).text();
            note = "From the variable " + e.name() + ": editing changes the variable (and everything that reads it)";
            name = name + " (= " + e.name() + ")";
        } else if (e.kind() == SourceMap.Kind.PARAMETER) {
            ScriptEdits.Argument arg;
            try {
                arg = ScriptEdits.argument(info, call, spec.name(), e.name());
            } catch (ScriptEdits.Refused why) {
                return text(spec.name(), "= " + e.text(), why.getMessage());
            }
            literal = arg.literal().text();
            note = "From the argument " + arg.parameter() + " of the call " + arg.call().macro() + "(…) at line "
                    + arg.call().span().line() + ": editing changes the argument";
            name = name + " (= " + e.name() + ")";
        } else {
            return text(spec.name(), "= " + e.text(), "Computed by the expression " + e.text() + ": edit it in the script");
        }
        Object value;
        try {
            value = parse(spec, literal);
        } catch (RuntimeException wrongKind) {
            return text(spec.name(), "= " + literal, "Not a " + spec.type().name().toLowerCase() + " literal: edit it in the script");
        }
        String range = spec.describe();
        return editable(spec, name, value, note + (range.isEmpty() ? "" : "; allowed: " + range),
                lit -> writer.write(info, call, spec.name(), lit));
    }

    private org.openide.nodes.Node.Property<?> editable(Spec spec, String name, Object value, String note,
            java.util.function.Function<String, String> write) {
        @SuppressWarnings({"rawtypes", "unchecked"})
        PropertySupport.ReadWrite<Object> p = new PropertySupport.ReadWrite(spec.name(), valueClass(spec), name, note) {
            private Object current = value;
            private PropertyEditor plainEditor;

            @Override public Object getValue() { return current; }

            @Override
            public void setValue(Object v) throws IllegalArgumentException, InvocationTargetException {
                if (v == null || v.equals(current)) return;
                String refused = check(spec, v);
                if (refused == null) refused = write.apply(literal(spec, v));
                if (refused != null) {
                    say(refused, true);
                    refresh();
                    return;
                }
                current = v;
            }

            @Override
            public PropertyEditor getPropertyEditor() {
                return switch (spec.type()) {
                    case VECTOR -> new ValueEditors.VectorEditor();
                    case COLOR -> new ValueEditors.ColorEditor();
                    case CHOICE -> new ValueEditors.ChoiceEditor(spec.choices());
                    default -> {
                        if (plainEditor == null) plainEditor = ValueEditors.plain(getValueType());
                        yield plainEditor != null ? plainEditor : super.getPropertyEditor();
                    }
                };
            }
        };
        return p;
    }

    private static org.openide.nodes.Node.Property<String> text(String name, String value, String note) {
        return new PropertySupport.ReadOnly<>(name, String.class, name, note) {
            @Override public String getValue() { return value; }

            private PropertyEditor plain;

            @Override
            public PropertyEditor getPropertyEditor() {
                if (plain == null) plain = ValueEditors.plain(String.class);
                return plain != null ? plain : super.getPropertyEditor();
            }
        };
    }

    private static Class<?> valueClass(Spec spec) {
        return switch (spec.type()) {
            case VECTOR -> Vec3.class;
            case COLOR -> Rgb.class;
            case NUMBER -> Double.class;
            case INTEGER -> Integer.class;
            case BOOLEAN -> Boolean.class;
            default -> String.class;
        };
    }

    /** The value a literal of the spec's kind writes; throws when the literal is of another kind. */
    static Object parse(Spec spec, String literal) {
        if (literal == null) return null;
        String t = literal.trim();
        return switch (spec.type()) {
            case VECTOR -> {
                if (!t.startsWith("vec3")) throw new IllegalArgumentException("not a vec3");
                double[] v = ScriptEdits.parseTriple(t);
                yield new Vec3(v[0], v[1], v[2]);
            }
            case COLOR -> {
                if (!t.startsWith("rgb")) throw new IllegalArgumentException("not an rgb");
                double[] v = ScriptEdits.parseTriple(t);
                yield new Rgb(v[0], v[1], v[2]);
            }
            case NUMBER -> ScriptEdits.parseNumber(t);
            case INTEGER -> {
                double d = ScriptEdits.parseNumber(t);
                if (d != Math.rint(d)) throw new IllegalArgumentException("not a whole number");
                yield (int) d;
            }
            case BOOLEAN -> {
                if (!t.equals("true") && !t.equals("false")) throw new IllegalArgumentException("not a boolean");
                yield Boolean.valueOf(t);
            }
            default -> {
                if (!t.startsWith("\"")) throw new IllegalArgumentException("not a string");
                yield ScriptEdits.parseString(t);
            }
        };
    }

    /** The literal a script writes for {@code v}. */
    static String literal(Spec spec, Object v) {
        return switch (spec.type()) {
            case VECTOR -> { Vec3 x = (Vec3) v; yield ScriptEdits.vec3(x.x(), x.y(), x.z()); }
            case COLOR -> { Rgb c = (Rgb) v; yield ScriptEdits.rgb(c.r(), c.g(), c.b()); }
            case NUMBER -> ScriptEdits.number(((Number) v).doubleValue());
            case INTEGER -> Integer.toString(((Number) v).intValue());
            case BOOLEAN -> v.toString();
            default -> ScriptEdits.string(v.toString());
        };
    }

    /** Null when {@code v} is allowed for the attribute, else the sentence that says what is. */
    static String check(Spec spec, Object v) {
        if (v instanceof Number n && (spec.type() == Type.NUMBER || spec.type() == Type.INTEGER)) {
            double d = n.doubleValue();
            if (!Double.isFinite(d) || !spec.contains(d)) return spec.name() + " must be " + spec.describe() + ", not " + ScriptEdits.number(d);
        }
        if (spec.type() == Type.CHOICE && !spec.choices().contains(v.toString())) {
            return spec.name() + " must be one of " + String.join(", ", spec.choices());
        }
        return null;
    }
}
