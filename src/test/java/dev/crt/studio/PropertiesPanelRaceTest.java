package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.studio.SceneOutline.Node;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/**
 * The property sheet builds a node's rows later, on the library's own thread: by then the panel
 * may show another compile or nothing (a compile with errors, a closed tab). The rows are those of
 * the compile the node was made from, never a failure.
 */
class PropertiesPanelRaceTest {
    private static final String TEXT = """
            red = Material { color -> rgb(0.9, 0.1, 0.1) }
            Settings { width -> 64 }
            Scene { Sphere { radius -> 2 material -> red } }
            """;

    @Test
    void aNodeBuildsTheRowsOfItsOwnCompileAfterThePanelHasMovedOn() throws Exception {
        CompileResult r = CrtCompiler.compile(Source.of("p.crt", TEXT), CompileOptions.DEFAULT.withSourceMap());
        assertThat(r.hasErrors()).isFalse();
        Node outline = SceneOutline.of(r, TEXT);
        org.openide.nodes.Node[] made = new org.openide.nodes.Node[2];
        SwingUtilities.invokeAndWait(() -> {
            PropertiesPanel panel = new PropertiesPanel();
            made[0] = panel.sheetNode(SceneOutline.find(outline, "Entities/Sphere"), r.sourceMap());
            made[1] = panel.sheetNode(SceneOutline.find(outline, "Settings"), r.sourceMap());
            // The next compile failed: the panel shows nothing, while the sheet's thread has yet to ask for the rows.
            assertThat(panel.sheetNode(null, null)).isNull();
        });
        StringBuilder rows = new StringBuilder();
        for (org.openide.nodes.Node n : made) {
            for (org.openide.nodes.Node.PropertySet set : n.getPropertySets()) {
                for (org.openide.nodes.Node.Property<?> p : set.getProperties()) rows.append(p.getDisplayName()).append(';');
            }
        }
        assertThat(rows.toString()).contains("radius;").contains("reflectivity;").contains("width;");
    }
}
