package dev.crt.studio;

import dev.crt.studio.SceneOutline.Kind;
import dev.crt.studio.SceneOutline.Node;
import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.Icon;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextField;
import javax.swing.JTree;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeCellRenderer;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import javax.swing.tree.TreeSelectionModel;

/**
 * The Navigator panel: the current script's scene as a tree (see {@link SceneOutline}) with a
 * filter box. It is rebuilt after each successful compile, keeping which nodes were expanded and
 * selected; a selection made by the user is handed to the listener, one made in code is not.
 */
final class NavigatorPanel extends JPanel {
    private final JTextField filter = new JTextField();
    private final DefaultTreeModel model = new DefaultTreeModel(new DefaultMutableTreeNode("no scene"));
    private final JTree tree = new JTree(model);
    private Node outline;
    private Consumer<Node> onSelect = n -> {};
    private boolean adjusting;
    /** The keys of the nodes the user keeps open (the groups start open); a filter opens everything without changing it. */
    private final Set<String> expanded = new HashSet<>(Set.of("Lights", "Entities"));

    NavigatorPanel() {
        super(new BorderLayout());
        filter.setName("navigatorFilter");
        filter.putClientProperty("JTextField.placeholderText", "Filter by name or type");
        filter.getAccessibleContext().setAccessibleName("Filter the scene tree");
        filter.setToolTipText("Shows the objects whose type or name contains this text");
        filter.getDocument().addDocumentListener(new DocumentListener() {
            @Override public void insertUpdate(DocumentEvent e) { rebuild(); }
            @Override public void removeUpdate(DocumentEvent e) { rebuild(); }
            @Override public void changedUpdate(DocumentEvent e) {}
        });
        tree.setName("navigatorTree");
        tree.getAccessibleContext().setAccessibleName("Scene navigator");
        tree.setRootVisible(false);
        tree.setShowsRootHandles(true);
        tree.getSelectionModel().setSelectionMode(TreeSelectionModel.SINGLE_TREE_SELECTION);
        tree.setCellRenderer(new Renderer());
        tree.addTreeExpansionListener(new javax.swing.event.TreeExpansionListener() {
            @Override public void treeExpanded(javax.swing.event.TreeExpansionEvent e) { remember(e.getPath(), true); }

            @Override public void treeCollapsed(javax.swing.event.TreeExpansionEvent e) { remember(e.getPath(), false); }
        });
        tree.addTreeSelectionListener(e -> {
            if (adjusting) return;
            Node n = selected();
            if (n != null) onSelect.accept(n);
        });
        JPanel top = new JPanel(new BorderLayout());
        top.setBorder(BorderFactory.createEmptyBorder(2, 2, 2, 2));
        top.add(filter, BorderLayout.CENTER);
        add(top, BorderLayout.NORTH);
        add(new JScrollPane(tree), BorderLayout.CENTER);
    }

    JTree tree() { return tree; }

    JTextField filter() { return filter; }

    void onSelect(Consumer<Node> listener) { onSelect = listener; }

    /** The outline shown now (before filtering), or null. */
    Node outline() { return outline; }

    /** The selected node, or null. */
    Node selected() {
        TreePath p = tree.getSelectionPath();
        return p == null || !(((DefaultMutableTreeNode) p.getLastPathComponent()).getUserObject() instanceof Node n) ? null : n;
    }

    /** Shows a new outline (null: nothing compiled yet), keeping expansion and selection by node key. */
    void show(Node newOutline) {
        outline = newOutline;
        rebuild();
    }

    /** Selects the node with {@code key} without telling the listener; false when it is not shown. */
    boolean select(String key) {
        DefaultMutableTreeNode found = find((DefaultMutableTreeNode) model.getRoot(), key);
        adjusting = true;
        try {
            if (found == null) {
                tree.clearSelection();
                return false;
            }
            TreePath path = new TreePath(found.getPath());
            tree.setSelectionPath(path);
            tree.scrollPathToVisible(path);
            return true;
        } finally {
            adjusting = false;
        }
    }

    private void remember(TreePath path, boolean open) {
        if (adjusting || !filter.getText().isBlank()) return;
        if (((DefaultMutableTreeNode) path.getLastPathComponent()).getUserObject() instanceof Node n) {
            if (open) expanded.add(n.key());
            else expanded.remove(n.key());
        }
    }

    private void rebuild() {
        Node wasSelected = selected();
        String text = filter.getText().trim().toLowerCase(Locale.ROOT);
        DefaultMutableTreeNode root = new DefaultMutableTreeNode(outline == null ? "no scene" : outline);
        if (outline != null) for (Node child : outline.children()) add(root, child, text);
        adjusting = true;
        try {
            model.setRoot(root);
            List<DefaultMutableTreeNode> all = new ArrayList<>();
            collect(root, all);
            for (DefaultMutableTreeNode n : all) {
                if (!(n.getUserObject() instanceof Node node) || n.isLeaf()) continue;
                if (expanded.contains(node.key()) || !text.isEmpty()) tree.expandPath(new TreePath(n.getPath()));
            }
        } finally {
            adjusting = false;
        }
        if (wasSelected != null) select(wasSelected.key());
    }

    /** Adds {@code n} under {@code parent} when it or a descendant matches the filter. */
    private static boolean add(DefaultMutableTreeNode parent, Node n, String filter) {
        DefaultMutableTreeNode t = new DefaultMutableTreeNode(n);
        boolean any = filter.isEmpty() || n.label().toLowerCase(Locale.ROOT).contains(filter);
        for (Node child : n.children()) any |= add(t, child, filter);
        // A group with no matching object is hidden while filtering; unfiltered, Lights and Entities always show.
        if (any || (filter.isEmpty() && n.kind() != Kind.ROOT)) {
            parent.add(t);
            return true;
        }
        return false;
    }

    private static void collect(DefaultMutableTreeNode n, List<DefaultMutableTreeNode> out) {
        out.add(n);
        for (int i = 0; i < n.getChildCount(); i++) collect((DefaultMutableTreeNode) n.getChildAt(i), out);
    }

    private static DefaultMutableTreeNode find(DefaultMutableTreeNode n, String key) {
        if (n.getUserObject() instanceof Node node && node.key().equals(key)) return n;
        for (int i = 0; i < n.getChildCount(); i++) {
            DefaultMutableTreeNode found = find((DefaultMutableTreeNode) n.getChildAt(i), key);
            if (found != null) return found;
        }
        return null;
    }

    private static final class Renderer extends DefaultTreeCellRenderer {
        @Override
        public Component getTreeCellRendererComponent(JTree tree, Object value, boolean sel, boolean expanded, boolean leaf,
                int row, boolean hasFocus) {
            super.getTreeCellRendererComponent(tree, value, sel, expanded, leaf, row, hasFocus);
            if (((DefaultMutableTreeNode) value).getUserObject() instanceof Node n) {
                setIcon(new KindIcon(n));
                setToolTipText(n.span() != null && n.span().line() > 0 ? n.type() + ", line " + n.span().line() : n.label());
            }
            return this;
        }
    }

    /** A small drawn glyph per kind of node: a ball for spheres, a cube for boxes, a bulb for lights… */
    static final class KindIcon implements Icon {
        private final String glyph;

        KindIcon(Node n) {
            glyph = switch (n.kind()) {
                case SETTINGS -> "settings";
                case CAMERA -> "camera";
                case BACKGROUND -> "background";
                case LIGHTS, ENTITIES -> "group";
                case LIGHT -> "light";
                case CALL -> "call";
                case OPERATION -> n.type();
                default -> n.type();
            };
        }

        @Override public int getIconWidth() { return 16; }

        @Override public int getIconHeight() { return 16; }

        @Override
        public void paintIcon(Component c, Graphics g0, int x, int y) {
            Graphics2D g = (Graphics2D) g0.create();
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.translate(x, y);
            g.setStroke(new BasicStroke(1.3f));
            switch (glyph) {
                case "Sphere" -> { fill(g, 0x3F7FD0); g.fillOval(2, 2, 12, 12); }
                case "Box" -> { fill(g, 0xD08A3F); g.fillRect(3, 3, 10, 10); }
                case "Plane" -> { fill(g, 0x6A9A4A); g.fillPolygon(new int[] {1, 11, 15, 5}, new int[] {12, 12, 5, 5}, 4); }
                case "Cylinder", "Cone", "Torus", "Mesh" -> { fill(g, 0x8A6AC0); g.fillRoundRect(3, 2, 10, 12, 6, 6); }
                case "Union", "Difference", "Intersection" -> {
                    fill(g, 0x3F7FD0);
                    g.drawOval(1, 3, 9, 9);
                    g.drawOval(6, 3, 9, 9);
                    g.setFont(g.getFont().deriveFont(java.awt.Font.BOLD, 9f));
                    String op = glyph.equals("Union") ? "+" : glyph.equals("Difference") ? "−" : "^";
                    g.drawString(op, 6, 11);
                }
                case "light" -> { fill(g, 0xE0B020); g.fillOval(4, 1, 9, 9); g.fillRect(6, 10, 5, 4); }
                case "camera" -> { fill(g, 0x505860); g.fillRect(1, 5, 10, 8); g.fillPolygon(new int[] {11, 15, 15}, new int[] {9, 5, 13}, 3); }
                case "background" -> { fill(g, 0x7FB0E0); g.fillRect(1, 2, 14, 6); fill(g, 0x4A6A3A); g.fillRect(1, 8, 14, 6); }
                case "settings" -> { fill(g, 0x707070); g.drawOval(3, 3, 10, 10); g.fillOval(6, 6, 4, 4); }
                case "call" -> { fill(g, 0x2E8B57); g.setFont(g.getFont().deriveFont(java.awt.Font.BOLD, 11f)); g.drawString("ƒ", 4, 13); }
                default -> { fill(g, 0x909090); g.drawRect(2, 3, 12, 10); }
            }
            g.dispose();
        }

        private static void fill(Graphics2D g, int rgb) { g.setColor(new Color(rgb)); }
    }
}
