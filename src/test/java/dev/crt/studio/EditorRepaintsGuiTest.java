package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.RepaintManager;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * What a keystroke repaints: the editor's text area repaints every visible line after a fold
 * reparse only when the folds changed, and for text typed at a line's start only that line
 * (ScriptArea); a changed tab title repaints the strip of tabs, not the script under it (ScriptTabs).
 */
@Tag("gui")
class EditorRepaintsGuiTest {
    private JFrame frame;
    private RepaintManager previous;

    @BeforeAll
    static void display() {
        GuiTestSupport.requireDisplay();
    }

    @AfterEach
    void close() {
        onEdt(() -> {
            if (previous != null) RepaintManager.setCurrentManager(previous);
            if (frame != null) frame.dispose();
        });
    }

    @Test
    void aFoldReparseRepaintsTheWholeAreaOnlyWhenTheFoldsChanged() {
        String text = "Scene {\n  Sphere { center -> vec3(0, 0, 0) radius -> 1 }\n}\n";
        ScriptArea area = shown(text, true);
        onEdt(() -> area.getFoldManager().reparse());
        assertThat(onEdt(() -> area.getFoldManager().getFoldCount())).isEqualTo(1);
        List<String> wholeArea = new ArrayList<>();
        recordRepaints(area, wholeArea, new ArrayList<>());

        // A keystroke inside the sphere's line: the same fold, no whole-area repaint from the reparse.
        onEdt(() -> area.insert("2", text.indexOf("radius -> 1") + "radius -> 1".length()));
        onEdt(() -> wholeArea.clear());
        onEdt(() -> area.getFoldManager().reparse());
        assertThat(onEdt(() -> area.getFoldManager().getFoldCount())).isEqualTo(1);
        assertThat(onEdt(() -> List.copyOf(wholeArea))).isEmpty();

        // A second block over two lines: a new fold, and the whole area repainted for it.
        onEdt(() -> area.append("Camera {\n}\n"));
        onEdt(() -> wholeArea.clear());
        onEdt(() -> area.getFoldManager().reparse());
        assertThat(onEdt(() -> area.getFoldManager().getFoldCount())).isEqualTo(2);
        assertThat(onEdt(() -> List.copyOf(wholeArea))).isNotEmpty();

        // Nothing stays marked: a repaint asked for afterwards goes through.
        onEdt(() -> wholeArea.clear());
        onEdt(() -> area.repaint());
        assertThat(onEdt(() -> List.copyOf(wholeArea))).isNotEmpty();
    }

    @Test
    void aCharacterTypedAtTheStartOfALineRepaintsThatLineOnly() {
        String text = "a = 1\nb = 2\nScene { Sphere { } }\n";
        ScriptArea area = shown(text, false);
        List<String> wholeArea = new ArrayList<>();
        List<int[]> regions = new ArrayList<>();
        recordRepaints(area, wholeArea, regions);

        // "x" at the start of the second line: that line is repainted, not the whole area.
        int lineHeight = onEdt(area::getLineHeight);
        onEdt(() -> area.insert("x", text.indexOf("b = 2")));
        assertThat(onEdt(() -> area.getText())).isEqualTo("a = 1\nxb = 2\nScene { Sphere { } }\n");
        assertThat(onEdt(() -> List.copyOf(wholeArea))).isEmpty();
        assertThat(onEdt(() -> regions.stream().anyMatch(r -> r[0] <= lineHeight && r[0] + r[1] >= 2 * lineHeight)))
                .as("the second line repainted").isTrue();

        // A line break typed there moves every line below it: the whole area is repainted.
        onEdt(() -> wholeArea.clear());
        onEdt(() -> area.insert("\n", text.indexOf("b = 2")));
        assertThat(onEdt(() -> List.copyOf(wholeArea))).isNotEmpty();

        // The view's own repaint takes the mark: a repaint asked for right after the insert goes through.
        onEdt(() -> {
            area.insert("y", area.getText().indexOf("Scene"));
            wholeArea.clear();
            area.repaint();
        });
        assertThat(onEdt(() -> List.copyOf(wholeArea))).isNotEmpty();
    }

    @Test
    void aChangedTabTitleRepaintsTheStripOfTabsOnly() {
        javax.swing.JPanel script = new javax.swing.JPanel();
        ScriptTabs tabs = onEdt(() -> {
            ScriptTabs t = new ScriptTabs();
            t.addTab("dice.crt", script);
            frame = new JFrame("EditorRepaintsGuiTest");
            frame.add(t);
            frame.setSize(500, 400);
            frame.setVisible(true);
            return t;
        });
        waitFor("the script to show", 10, () -> script.isShowing() && script.getY() > 0);
        List<java.awt.Rectangle> dirty = new ArrayList<>();
        onEdt(() -> {
            previous = RepaintManager.currentManager(tabs);
            RepaintManager.setCurrentManager(new RepaintManager() {
                @Override
                public void addDirtyRegion(JComponent c, int x, int y, int w, int h) {
                    if (c == tabs) dirty.add(new java.awt.Rectangle(x, y, w, h));
                    super.addDirtyRegion(c, x, y, w, h);
                }
            });
        });
        int strip = onEdt(() -> script.getY());
        onEdt(() -> tabs.setTitleAt(0, "*dice.crt"));
        // The strip, and nothing below it (the tab itself may ask for its own rectangle too: rollover, selection).
        assertThat(onEdt(() -> List.copyOf(dirty))).contains(new java.awt.Rectangle(0, 0, onEdt(() -> tabs.getWidth()), strip))
                .allSatisfy(r -> assertThat(r.y + r.height).isLessThanOrEqualTo(strip));
        assertThat(onEdt(() -> tabs.getTitleAt(0))).isEqualTo("*dice.crt");
        waitFor("the longer title laid out", 10, () -> tabs.getBoundsAt(0).width > 0 && tabs.getBoundsAt(0).y + tabs.getBoundsAt(0).height <= strip);
        // Any other repaint of the tabbed pane is whole, as before.
        onEdt(() -> dirty.clear());
        onEdt(() -> tabs.repaint());
        assertThat(onEdt(() -> List.copyOf(dirty))).contains(new java.awt.Rectangle(0, 0, onEdt(() -> tabs.getWidth()), onEdt(() -> tabs.getHeight())));
    }

    /** A script area holding {@code text} (folding on or off), shown in a window of its own. */
    private ScriptArea shown(String text, boolean folding) {
        ScriptArea area = onEdt(() -> {
            CrtTokenMaker.register();
            ScriptArea a = new ScriptArea(20, 60);
            a.setSyntaxEditingStyle(CrtTokenMaker.STYLE);
            a.setCodeFoldingEnabled(folding);
            a.setText(text);
            frame = new JFrame("EditorRepaintsGuiTest");
            frame.add(new org.fife.ui.rtextarea.RTextScrollPane(a));
            frame.setSize(500, 400);
            frame.setVisible(true);
            return a;
        });
        waitFor("the area to show", 10, area::isShowing);
        return area;
    }

    /** From now on, every repaint of {@code area} asked for goes into {@code regions} (y, height), and those of all of it into {@code wholeArea}. */
    private void recordRepaints(ScriptArea area, List<String> wholeArea, List<int[]> regions) {
        onEdt(() -> {
            previous = RepaintManager.currentManager(area);
            RepaintManager.setCurrentManager(new RepaintManager() {
                @Override
                public void addDirtyRegion(JComponent c, int x, int y, int w, int h) {
                    if (c == area && w >= area.getWidth() && h >= area.getHeight()) wholeArea.add(w + "x" + h);
                    if (c == area) regions.add(new int[] {y, h});
                    super.addDirtyRegion(c, x, y, w, h);
                }
            });
        });
    }
}
