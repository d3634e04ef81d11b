package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.studio.SceneOutline.Node;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import javax.swing.SwingUtilities;
import javax.swing.tree.DefaultMutableTreeNode;
import org.junit.jupiter.api.Test;

/** The navigator's filter and its memory of the selection, without a window (Swing components work headless). */
class NavigatorPanelTest {
    private static Node outline(String text) {
        return SceneOutline.of(CrtCompiler.compile(Source.of("n.crt", text), CompileOptions.DEFAULT.withSourceMap()), text);
    }

    private static List<String> shown(NavigatorPanel panel) {
        List<String> labels = new ArrayList<>();
        collect((DefaultMutableTreeNode) panel.tree().getModel().getRoot(), labels);
        return labels;
    }

    private static void collect(DefaultMutableTreeNode n, List<String> out) {
        for (int i = 0; i < n.getChildCount(); i++) {
            DefaultMutableTreeNode child = (DefaultMutableTreeNode) n.getChildAt(i);
            out.add(((Node) child.getUserObject()).key());
            collect(child, out);
        }
    }

    @Test
    void theFilterShowsMatchesWithTheirGroupsAndTheSelectionSurvivesARecompile() throws Exception {
        String text;
        try (InputStream in = getClass().getResourceAsStream("objects.crt")) {
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        String script = text;
        SwingUtilities.invokeAndWait(() -> {
            NavigatorPanel panel = new NavigatorPanel();
            panel.show(outline(script));
            assertThat(shown(panel)).contains("Settings", "Camera", "Lights/PointLight", "Entities/Plane");
            panel.filter().setText("box");
            assertThat(shown(panel)).containsExactly("Entities", "Entities/Difference cut", "Entities/Difference cut/Box");
            panel.filter().setText("light");
            assertThat(shown(panel)).containsExactly("Lights", "Lights/PointLight");
            panel.filter().setText("");
            assertThat(panel.select("Entities/row(3, 0.3)/Sphere #2")).isTrue();
            // A recompile of an edited text (the argument changed, so the call's label changed too) keeps
            // what it can: a node of the same key stays selected, one that is gone leaves nothing selected.
            panel.show(outline(script.replace("radius -> 0.8", "radius -> 1.1")));
            assertThat(panel.selected().key()).isEqualTo("Entities/row(3, 0.3)/Sphere #2");
            panel.show(outline(script.replace("row(3, 0.3)", "row(3, 0.2)")));
            assertThat(panel.selected()).isNull();
        });
    }
}
