package dev.crt.studio;

import dev.crt.lang.CompileResult;
import dev.crt.lang.Diagnostic;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalInt;
import javax.swing.AbstractAction;
import javax.swing.Icon;
import javax.swing.JPanel;
import javax.swing.KeyStroke;
import javax.swing.ToolTipManager;
import javax.swing.event.HyperlinkEvent;
import javax.swing.text.BadLocationException;
import javax.swing.text.Element;
import org.fife.ui.autocomplete.AutoCompletion;
import org.fife.ui.rsyntaxtextarea.ErrorStrip;
import org.fife.ui.rsyntaxtextarea.LinkGenerator;
import org.fife.ui.rsyntaxtextarea.LinkGeneratorResult;
import org.fife.ui.rsyntaxtextarea.RSyntaxDocument;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.fife.ui.rsyntaxtextarea.Theme;
import org.fife.ui.rsyntaxtextarea.parser.AbstractParser;
import org.fife.ui.rsyntaxtextarea.parser.DefaultParseResult;
import org.fife.ui.rsyntaxtextarea.parser.DefaultParserNotice;
import org.fife.ui.rsyntaxtextarea.parser.ParseResult;
import org.fife.ui.rsyntaxtextarea.parser.ParserNotice;
import org.fife.ui.rtextarea.Gutter;
import org.fife.ui.rtextarea.RTextScrollPane;

/**
 * The editor of one script: highlighting, folding, bracket matching and occurrences from the
 * editor library; diagnostics of the latest background compile as squiggles, tooltips and gutter
 * marks; completion; go to definition.
 */
final class ScriptEditor extends JPanel implements ScriptDocument.Listener {
    private static final Icon ERROR_ICON = new MarkIcon(new Color(0xD32F2F));
    private static final Icon WARNING_ICON = new MarkIcon(new Color(0xF9A825));

    private final ScriptDocument document;
    private final RSyntaxTextArea area;
    private final RTextScrollPane scroll;
    private final DiagnosticsParser diagnostics = new DiagnosticsParser();
    private final FindBar findBar;

    ScriptEditor(ScriptDocument document) {
        super(new BorderLayout());
        this.document = document;
        area = new ScriptArea(30, 80);
        area.setDocument(document.text());
        area.setSyntaxEditingStyle(CrtTokenMaker.STYLE);
        area.setCodeFoldingEnabled(true);
        area.setBracketMatchingEnabled(true);
        area.setPaintMatchedBracketPair(true);
        area.setHighlightCurrentLine(true);
        area.setMarkOccurrences(true);
        area.setMarkOccurrencesDelay(200);
        area.setAntiAliasingEnabled(true);
        area.setTabSize(4);
        area.setTabsEmulated(true);
        area.setAutoIndentEnabled(true);
        area.setCloseCurlyBraces(true);
        area.setInsertPairedCharacters(false);
        area.addParser(diagnostics);
        area.setParserDelay(50);
        area.setLinkGenerator(new DefinitionLinks());
        area.getAccessibleContext().setAccessibleName("Script editor " + document.name());
        area.getAccessibleContext().setAccessibleDescription("The text of the script " + document.name());
        area.setName("editor");
        // Plain Swing tooltips, which screen readers and test tools read, rather than the library's focusable ones.
        area.setUseFocusableTips(false);
        ToolTipManager.sharedInstance().registerComponent(area);
        area.getInputMap().put(KeyStroke.getKeyStroke(KeyEvent.VK_F3, 0), "crt.goToDefinition");
        area.getActionMap().put("crt.goToDefinition", new AbstractAction("Go to definition") {
            @Override public void actionPerformed(java.awt.event.ActionEvent e) { goToDefinition(area.getCaretPosition()); }
        });
        // X11 delivers Ctrl+/ also as a typed '/', which would replace the selection that the
        // toggle comment of the same key press works on; Ctrl alone never types a character.
        area.addKeyListener(new java.awt.event.KeyAdapter() {
            @Override public void keyTyped(KeyEvent e) {
                if (e.isControlDown() && !e.isAltDown() && !e.isAltGraphDown()) e.consume();
            }
        });
        AutoCompletion completion = new AutoCompletion(new CompletionSource());
        completion.setTriggerKey(KeyStroke.getKeyStroke(KeyEvent.VK_SPACE, InputEvent.CTRL_DOWN_MASK));
        completion.setAutoCompleteSingleChoices(true);
        completion.setShowDescWindow(false);
        completion.install(area);
        scroll = new RTextScrollPane(area, true);
        scroll.setFoldIndicatorEnabled(true);
        scroll.setIconRowHeaderEnabled(true);
        findBar = new FindBar(area);
        findBar.setVisible(false);
        add(findBar, BorderLayout.NORTH);
        add(scroll, BorderLayout.CENTER);
        ErrorStrip strip = new ErrorStrip(area);
        add(strip, BorderLayout.LINE_END);
        document.addListener(this);
        if (document.result() != null) compiled(document, document.result());
    }

    ScriptDocument document() { return document; }

    RSyntaxTextArea area() { return area; }

    FindBar findBar() { return findBar; }

    void dispose() { document.removeListener(this); }

    @Override
    public void compiled(ScriptDocument d, CompileResult result) {
        diagnostics.show(result.diagnostics());
        area.forceReparsing(diagnostics);
        Gutter gutter = scroll.getGutter();
        gutter.removeAllTrackingIcons();
        for (Diagnostic diag : result.diagnostics()) {
            int line = diag.span().line() - 1;
            if (line < 0 || line >= area.getLineCount()) continue;
            try {
                gutter.addLineTrackingIcon(line, diag.isError() ? ERROR_ICON : WARNING_ICON, diag.message());
            } catch (BadLocationException e) {
                // The text shrank since the compile; the next compile marks it again.
            }
        }
    }

    /** Puts the caret at {@code offset}, scrolls there and takes the focus. */
    void goTo(int offset) {
        int at = Math.max(0, Math.min(offset, document.text().getLength()));
        area.setCaretPosition(at);
        try {
            var r = area.modelToView2D(at);
            if (r != null) area.scrollRectToVisible(r.getBounds());
        } catch (BadLocationException e) {
            // The offset was clamped above; nothing to scroll to otherwise.
        }
        area.requestFocusInWindow();
    }

    /**
     * Selects the code in [start, end) and scrolls to it without taking the focus: another panel
     * (the live view) asked, and its keys must keep working.
     */
    void showCode(int start, int end) {
        int length = document.text().getLength();
        int from = Math.max(0, Math.min(start, length));
        area.select(from, Math.max(from, Math.min(end, length)));
        try {
            var r = area.modelToView2D(from);
            if (r != null) area.scrollRectToVisible(r.getBounds());
        } catch (BadLocationException e) {
            // The offset was clamped above; nothing to scroll to otherwise.
        }
    }

    /** Puts the caret at 1-based {@code line}, {@code column}. */
    void goTo(int line, int column) {
        Element root = document.text().getDefaultRootElement();
        int l = Math.max(0, Math.min(line - 1, root.getElementCount() - 1));
        Element e = root.getElement(l);
        goTo(Math.min(e.getStartOffset() + Math.max(0, column - 1), e.getEndOffset() - 1));
    }

    boolean goToDefinition(int offset) {
        OptionalInt def = ScriptWords.definitionAt(document.content(), offset);
        def.ifPresent(this::goTo);
        return def.isPresent();
    }

    void applyTheme(boolean dark) {
        String name = dark ? "/org/fife/ui/rsyntaxtextarea/themes/dark.xml" : "/org/fife/ui/rsyntaxtextarea/themes/idea.xml";
        try (InputStream in = RSyntaxTextArea.class.getResourceAsStream(name)) {
            if (in != null) Theme.load(in).apply(area);
        } catch (IOException e) {
            // The library ships these themes; without one the editor keeps its colours.
        }
    }

    @Override
    public boolean requestFocusInWindow() { return area.requestFocusInWindow(); }

    /** Shows the latest compile's diagnostics to the editor library as parser notices. */
    private static final class DiagnosticsParser extends AbstractParser {
        private List<Diagnostic> shown = List.of();

        void show(List<Diagnostic> list) { shown = list; }

        @Override
        public ParseResult parse(RSyntaxDocument doc, String style) {
            DefaultParseResult result = new DefaultParseResult(this);
            int length = doc.getLength();
            Element root = doc.getDefaultRootElement();
            result.setParsedLines(0, root.getElementCount() - 1);
            for (Diagnostic d : shown) {
                int start = Math.max(0, Math.min(d.span().start(), length));
                int end = Math.max(start + 1, Math.min(d.span().end(), length));
                if (start >= length) start = Math.max(0, length - 1);
                int len = Math.max(1, Math.min(end, length) - start);
                DefaultParserNotice n = new DefaultParserNotice(this, d.message(), root.getElementIndex(start), start, len);
                n.setLevel(d.isError() ? ParserNotice.Level.ERROR : ParserNotice.Level.WARNING);
                n.setToolTipText(tooltip(d));
                result.addNotice(n);
            }
            return result;
        }

        private static String tooltip(Diagnostic d) {
            List<String> lines = new ArrayList<>();
            lines.add((d.isError() ? "error: " : "warning: ") + d.message());
            lines.addAll(d.callChain());
            return String.join("\n", lines);
        }
    }

    /** Ctrl+click on a variable or macro name goes to where it is assigned. */
    private final class DefinitionLinks implements LinkGenerator {
        @Override
        public LinkGeneratorResult isLinkAtOffset(RSyntaxTextArea textArea, int offs) {
            ScriptWords.Word word = ScriptWords.identifierAt(document.content(), offs);
            if (word == null || ScriptWords.definitionAt(document.content(), offs).isEmpty()) return null;
            return new LinkGeneratorResult() {
                @Override public HyperlinkEvent execute() {
                    goToDefinition(word.start());
                    return null;
                }

                @Override public int getSourceOffset() { return word.start(); }
            };
        }
    }

    /** A small round mark for the gutter. */
    private record MarkIcon(Color color) implements Icon {
        @Override
        public void paintIcon(Component c, Graphics g, int x, int y) {
            Graphics2D g2 = (Graphics2D) g.create();
            g2.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g2.setColor(color);
            g2.fillOval(x + 2, y + 2, 10, 10);
            g2.dispose();
        }

        @Override public int getIconWidth() { return 14; }

        @Override public int getIconHeight() { return 14; }
    }
}
