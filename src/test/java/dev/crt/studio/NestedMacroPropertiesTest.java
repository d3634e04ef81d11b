package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.lang.SourceMap.Expr;
import dev.crt.lang.SourceMap.MacroCall;
import dev.crt.lang.SourceMap.ObjectInfo;
import dev.crt.studio.SceneOutline.Node;
import java.util.ArrayList;
import java.util.List;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** The property sheet of entities a macro called from a macro made: what it offers to edit, and where the edit goes. */
class NestedMacroPropertiesTest {
    private static final String TEXT = """
            leaf = Macro (size) { Sphere { radius -> size } }
            pair = Macro (s) {
              leaf(s)
              leaf(s * 2)
            }
            Scene { pair(0.4) }
            """;

    private static org.openide.nodes.Node.Property<?> property(org.openide.nodes.Node node, String displayName) {
        for (org.openide.nodes.Node.PropertySet set : node.getPropertySets()) {
            for (org.openide.nodes.Node.Property<?> p : set.getProperties()) if (p.getDisplayName().equals(displayName)) return p;
        }
        throw new AssertionError("no property " + displayName);
    }

    @Test
    void theSheetEditsTheTopLevelArgumentAndShowsAComputedOneReadOnlyWithTheReason() throws Exception {
        CompileResult r = CrtCompiler.compile(Source.of("p.crt", TEXT), CompileOptions.DEFAULT.withSourceMap());
        assertThat(r.hasErrors()).isFalse();
        Node outline = SceneOutline.of(r, TEXT);
        List<String> written = new ArrayList<>();
        SwingUtilities.invokeAndWait(() -> {
            PropertiesPanel panel = new PropertiesPanel();
            panel.writer(new PropertiesPanel.Writer() {
                @Override public String write(ObjectInfo object, MacroCall call, String attribute, String literal) {
                    try {
                        written.add(ScriptEdits.setAttribute(TEXT, r.sourceMap(), object, call, attribute, literal).applyTo(TEXT));
                        return null;
                    } catch (ScriptEdits.Refused refused) {
                        return refused.getMessage();
                    }
                }

                @Override public String replace(Expr literalExpr, String literal, String what) { return "not expected"; }
            });
            // Both spheres sit under the top-level call pair(0.4) in the tree.
            Node first = SceneOutline.find(outline, "Entities/pair(0.4)/Sphere");
            Node second = SceneOutline.find(outline, "Entities/pair(0.4)/Sphere #2");
            // The sheet's node, as the sheet would show it (the sheet itself is not built: it writes preferences).
            org.openide.nodes.Node.Property<?> radius = property(panel.sheetNode(first, r.sourceMap()), "radius (= size)");
            assertThat(radius.canWrite()).isTrue();
            assertThat(radius.getShortDescription()).contains("argument s of the call pair(…) at line 6");
            try {
                @SuppressWarnings("unchecked")
                org.openide.nodes.Node.Property<Object> p = (org.openide.nodes.Node.Property<Object>) radius;
                p.setValue(0.5);
            } catch (ReflectiveOperationException e) {
                throw new AssertionError(e);
            }
            assertThat(written).containsExactly(TEXT.replace("pair(0.4)", "pair(0.5)"));

            org.openide.nodes.Node.Property<?> computed = property(panel.sheetNode(second, r.sourceMap()), "radius");
            assertThat(computed.canWrite()).isFalse();
            assertThat(computed.getShortDescription()).contains("size = s * 2 of the call leaf(…) at line 4").contains("computed");
        });
    }
}
