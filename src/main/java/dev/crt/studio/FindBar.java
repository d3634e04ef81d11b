package dev.crt.studio;

import java.awt.FlowLayout;
import java.awt.event.KeyEvent;
import javax.swing.AbstractAction;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.KeyStroke;
import org.fife.ui.rtextarea.RTextArea;
import org.fife.ui.rtextarea.SearchContext;
import org.fife.ui.rtextarea.SearchEngine;
import org.fife.ui.rtextarea.SearchResult;

/** Find and replace above the editor (Ctrl+F, Ctrl+H); Enter finds the next match, Esc closes. */
final class FindBar extends JPanel {
    private final RTextArea area;
    private final JTextField find = new JTextField(18);
    private final JTextField replace = new JTextField(14);
    private final JLabel replaceLabel = new JLabel("Replace:");
    private final JButton replaceOne = new JButton("Replace");
    private final JButton replaceAll = new JButton("Replace all");
    private final JCheckBox matchCase = new JCheckBox("Match case");
    private final JLabel status = new JLabel(" ");
    private final JPanel replaceRow = new JPanel(new FlowLayout(FlowLayout.LEADING, 4, 2));

    FindBar(RTextArea area) {
        // Two rows: in one, both do not fit beside the find field in a half-window editor.
        super();
        setLayout(new javax.swing.BoxLayout(this, javax.swing.BoxLayout.Y_AXIS));
        this.area = area;
        find.setName("find");
        find.getAccessibleContext().setAccessibleName("Find");
        replace.setName("replace");
        replace.getAccessibleContext().setAccessibleName("Replace with");
        JButton next = new JButton("Next");
        JButton previous = new JButton("Previous");
        JButton close = new JButton("×");
        close.getAccessibleContext().setAccessibleName("Close find");
        JPanel findRow = new JPanel(new FlowLayout(FlowLayout.LEADING, 4, 2));
        findRow.add(new JLabel("Find:"));
        findRow.add(find);
        findRow.add(previous);
        findRow.add(next);
        findRow.add(matchCase);
        findRow.add(close);
        findRow.add(status);
        replaceRow.add(replaceLabel);
        replaceRow.add(replace);
        replaceRow.add(replaceOne);
        replaceRow.add(replaceAll);
        add(findRow);
        add(replaceRow);
        next.addActionListener(e -> find(true));
        previous.addActionListener(e -> find(false));
        find.addActionListener(e -> find(true));
        replace.addActionListener(e -> replace(false));
        replaceOne.addActionListener(e -> replace(false));
        replaceAll.addActionListener(e -> replace(true));
        close.addActionListener(e -> close());
        AbstractAction closeAction = new AbstractAction() {
            @Override public void actionPerformed(java.awt.event.ActionEvent e) { close(); }
        };
        getInputMap(JComponent.WHEN_ANCESTOR_OF_FOCUSED_COMPONENT).put(KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), "closeFind");
        getActionMap().put("closeFind", closeAction);
    }

    /** Shows the bar, with the replace fields when {@code withReplace}, seeded with the selection. */
    void open(boolean withReplace) {
        replaceRow.setVisible(withReplace);
        String selected = area.getSelectedText();
        if (selected != null && !selected.contains("\n")) find.setText(selected);
        setVisible(true);
        revalidate();
        find.selectAll();
        find.requestFocusInWindow();
    }

    private void close() {
        setVisible(false);
        SearchEngine.markAll(area, new SearchContext(""));
        area.requestFocusInWindow();
    }

    private SearchContext context(boolean forward) {
        SearchContext c = new SearchContext(find.getText(), matchCase.isSelected());
        c.setSearchForward(forward);
        c.setSearchWrap(true);
        c.setMarkAll(true);
        c.setReplaceWith(replace.getText());
        return c;
    }

    private void find(boolean forward) {
        if (find.getText().isEmpty()) return;
        SearchResult r = SearchEngine.find(area, context(forward));
        status.setText(r.wasFound() ? r.getMarkedCount() + " matches" : "not found");
    }

    private void replace(boolean all) {
        if (find.getText().isEmpty()) return;
        SearchResult r = all ? SearchEngine.replaceAll(area, context(true)) : SearchEngine.replace(area, context(true));
        status.setText(all ? r.getCount() + " replaced" : r.wasFound() ? "replaced" : "not found");
    }
}
