package dev.crt.studio;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Cursor;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.time.LocalTime;
import java.time.format.DateTimeFormatter;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextPane;
import javax.swing.UIManager;
import javax.swing.text.AttributeSet;
import javax.swing.text.BadLocationException;
import javax.swing.text.Element;
import javax.swing.text.SimpleAttributeSet;
import javax.swing.text.StyleConstants;
import javax.swing.text.StyledDocument;

/**
 * Messages of the compiler and the renderer, each with its time; errors in red. A click on a
 * {@code file:line:col} place opens it in the editor.
 */
final class ConsolePanel extends JPanel {
    /** Where a console place points: the file as the compiler named it, 1-based line and column. */
    interface PlaceOpener {
        void open(String file, int line, int column);
    }

    /** The kind of a message, for its colour. */
    enum Kind { INFO, WARNING, ERROR }

    static final Pattern PLACE = Pattern.compile("([^\\s:]*[^\\s:\\d][^\\s:]*):(\\d+):(\\d+)");
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss");
    private static final int MAX_CHARS = 200_000;

    /** Lines are not wrapped: wrapping a long console makes every append lay out the whole text again. */
    private final JTextPane text = new JTextPane() {
        @Override public boolean getScrollableTracksViewportWidth() {
            return getParent() == null || getUI().getPreferredSize(this).width <= getParent().getSize().width;
        }
    };
    private PlaceOpener opener = (f, l, c) -> {};

    ConsolePanel() {
        super(new BorderLayout());
        text.setEditable(false);
        text.setName("console");
        text.getAccessibleContext().setAccessibleName("Console");
        text.setFont(new java.awt.Font(java.awt.Font.MONOSPACED, java.awt.Font.PLAIN, 12));
        add(new JScrollPane(text), BorderLayout.CENTER);
        MouseAdapter mouse = new MouseAdapter() {
            @Override public void mouseClicked(MouseEvent e) {
                Place p = placeAt(text.viewToModel2D(e.getPoint()));
                if (p != null) opener.open(p.file, p.line, p.column);
            }

            @Override public void mouseMoved(MouseEvent e) {
                boolean link = placeAt(text.viewToModel2D(e.getPoint())) != null;
                text.setCursor(Cursor.getPredefinedCursor(link ? Cursor.HAND_CURSOR : Cursor.TEXT_CURSOR));
            }
        };
        text.addMouseListener(mouse);
        text.addMouseMotionListener(mouse);
    }

    void onPlaceClicked(PlaceOpener o) { opener = o; }

    JTextPane text() { return text; }

    /** Appends one message with the time now. */
    void log(Kind kind, String message) {
        StyledDocument doc = text.getStyledDocument();
        SimpleAttributeSet base = new SimpleAttributeSet();
        if (kind == Kind.ERROR) StyleConstants.setForeground(base, new Color(0xE53935));
        else if (kind == Kind.WARNING) StyleConstants.setForeground(base, new Color(0xF57C00));
        else {
            Color fg = UIManager.getColor("TextPane.foreground");
            if (fg != null) StyleConstants.setForeground(base, fg);
        }
        String line = LocalTime.now().format(TIME) + "  " + message + "\n";
        try {
            int start = doc.getLength();
            doc.insertString(start, line, base);
            Matcher m = PLACE.matcher(line);
            while (m.find()) {
                SimpleAttributeSet link = new SimpleAttributeSet(base);
                StyleConstants.setUnderline(link, true);
                doc.setCharacterAttributes(start + m.start(), m.end() - m.start(), link, false);
            }
            if (doc.getLength() > MAX_CHARS) doc.remove(0, doc.getLength() - MAX_CHARS);
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        }
        text.setCaretPosition(doc.getLength());
    }

    private record Place(String file, int line, int column) {}

    private Place placeAt(int offset) {
        if (offset < 0) return null;
        StyledDocument doc = text.getStyledDocument();
        Element lineElement = doc.getDefaultRootElement().getElement(doc.getDefaultRootElement().getElementIndex(offset));
        try {
            String line = doc.getText(lineElement.getStartOffset(), lineElement.getEndOffset() - lineElement.getStartOffset());
            int at = offset - lineElement.getStartOffset();
            Matcher m = PLACE.matcher(line);
            while (m.find()) {
                if (m.start() <= at && at < m.end()) {
                    return new Place(m.group(1), Integer.parseInt(m.group(2)), Integer.parseInt(m.group(3)));
                }
            }
        } catch (BadLocationException | NumberFormatException e) {
            return null;
        }
        return null;
    }

    /** The attributes at {@code offset}, for tests of the colours. */
    AttributeSet attributesAt(int offset) {
        return text.getStyledDocument().getCharacterElement(offset).getAttributes();
    }
}
