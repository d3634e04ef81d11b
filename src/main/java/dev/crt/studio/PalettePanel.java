package dev.crt.studio;

import java.awt.BorderLayout;
import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.Transferable;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.List;
import java.util.function.BiConsumer;
import javax.swing.DropMode;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.ListSelectionModel;
import javax.swing.TransferHandler;
import javax.swing.text.JTextComponent;

/**
 * The Insert menu's items as a dockable palette: drag one onto the editor to insert it where it
 * is dropped (on a new line after the statement there), or double-click it (or press Enter) to
 * insert it at the caret. The insertion itself is {@link ObjectPanels}'s, checked to compile.
 */
final class PalettePanel extends JPanel {
    /** What a palette item carries while it is dragged: its name ("Sphere", "Point light"…). */
    static final DataFlavor ITEM = localFlavor();

    private final JList<String> list;

    /** A flavor of this JVM only, so that no text dragged from elsewhere is taken for a palette item. */
    private static DataFlavor localFlavor() {
        return new DataFlavor(DataFlavor.javaJVMLocalObjectMimeType + ";class=java.lang.String", "CRT palette item");
    }

    /** {@code insert} gets the item and the text offset to insert at, or −1 for the caret. */
    PalettePanel(List<String> items, BiConsumer<String, Integer> insert) {
        super(new BorderLayout());
        list = new JList<>(items.toArray(String[]::new));
        list.setName("paletteList");
        list.getAccessibleContext().setAccessibleName("Palette");
        list.getAccessibleContext().setAccessibleDescription("Drag an item onto the script, or double-click it, to insert it");
        list.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        list.setDragEnabled(true);
        list.setTransferHandler(new TransferHandler() {
            @Override public int getSourceActions(JComponent c) { return COPY; }

            @Override protected Transferable createTransferable(JComponent c) {
                String item = list.getSelectedValue();
                return item == null ? null : new Item(item);
            }
        });
        list.addMouseListener(new MouseAdapter() {
            @Override public void mouseClicked(MouseEvent e) {
                int at = list.locationToIndex(e.getPoint());
                if (e.getClickCount() == 2 && at >= 0) insert.accept(list.getModel().getElementAt(at), -1);
            }
        });
        list.getInputMap().put(KeyStroke.getKeyStroke(KeyEvent.VK_ENTER, 0), "crt.insert");
        list.getActionMap().put("crt.insert", new javax.swing.AbstractAction() {
            @Override public void actionPerformed(java.awt.event.ActionEvent e) {
                if (list.getSelectedValue() != null) insert.accept(list.getSelectedValue(), -1);
            }
        });
        JLabel hint = new JLabel("Drag onto the script, or double-click");
        hint.setEnabled(false);
        add(new JScrollPane(list), BorderLayout.CENTER);
        add(hint, BorderLayout.SOUTH);
    }

    JList<String> items() { return list; }

    /**
     * A transfer handler for the editor that takes palette items, inserting them where they are
     * dropped, and passes everything else (text, files) to {@code delegate}.
     */
    static TransferHandler dropInto(JTextComponent area, TransferHandler delegate, BiConsumer<String, Integer> insert) {
        area.setDropMode(DropMode.INSERT);
        return new TransferHandler() {
            @Override public boolean canImport(TransferSupport s) {
                if (s.isDataFlavorSupported(ITEM)) {
                    if (s.isDrop()) s.setDropAction(COPY);
                    return true;
                }
                return delegate != null && delegate.canImport(s);
            }

            @Override public boolean importData(TransferSupport s) {
                if (!s.isDataFlavorSupported(ITEM)) return delegate != null && delegate.importData(s);
                try {
                    String item = (String) s.getTransferable().getTransferData(ITEM);
                    int at = s.isDrop() && s.getDropLocation() instanceof JTextComponent.DropLocation d ? d.getIndex() : -1;
                    javax.swing.SwingUtilities.invokeLater(() -> insert.accept(item, at));
                    return true;
                } catch (UnsupportedFlavorException | java.io.IOException e) {
                    return false;
                }
            }

            @Override public int getSourceActions(JComponent c) { return delegate == null ? NONE : delegate.getSourceActions(c); }

            @Override public void exportAsDrag(JComponent comp, java.awt.event.InputEvent e, int action) {
                if (delegate != null) delegate.exportAsDrag(comp, e, action);
            }

            @Override public void exportToClipboard(JComponent comp, java.awt.datatransfer.Clipboard clip, int action) {
                if (delegate != null) delegate.exportToClipboard(comp, clip, action);
            }
        };
    }

    /** A dragged palette item. */
    private record Item(String name) implements Transferable {
        @Override public DataFlavor[] getTransferDataFlavors() { return new DataFlavor[] {ITEM}; }

        @Override public boolean isDataFlavorSupported(DataFlavor f) { return ITEM.equals(f); }

        @Override public Object getTransferData(DataFlavor f) throws UnsupportedFlavorException {
            if (!ITEM.equals(f)) throw new UnsupportedFlavorException(f);
            return name;
        }
    }
}
