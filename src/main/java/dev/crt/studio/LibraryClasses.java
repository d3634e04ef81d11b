package dev.crt.studio;

/**
 * Loads, on a background thread, the property sheet's classes that its first paint with a row
 * needs. The NetBeans library is compiled for an old class-file version, which Java's start-up
 * cache cannot hold, so without this each of them is read from the jar and defined on the Event
 * Dispatch Thread the first time the sheet shows an object: 30 classes, up to 77 ms measured,
 * just when the first compile's result arrives and the user starts to type (docs/studio.md).
 * Classes are only loaded here, not initialised, so no static initialiser runs off the EDT.
 */
final class LibraryClasses {
    private static final String[] SHEET = {
        "org.openide.explorer.propertysheet.SheetColumnModel$1",
        "org.openide.awt.GraphicsUtils",
        "org.openide.awt.HtmlRenderer",
        "org.openide.awt.HtmlRenderer$Renderer",
        "org.openide.awt.HtmlRendererImpl",
        "org.openide.awt.HtmlRendererImpl$Type",
        "org.openide.awt.HtmlLabelUI",
        "org.openide.explorer.propertysheet.RendererFactory",
        "org.openide.explorer.propertysheet.IconPanel",
        "org.openide.explorer.propertysheet.RadioInplaceEditor",
        "org.openide.explorer.propertysheet.RendererFactory$RadioRenderer",
        "org.openide.explorer.propertysheet.IncrementPropertyValueSupport",
        "org.openide.explorer.propertysheet.ComboInplaceEditor",
        "org.openide.explorer.propertysheet.RendererFactory$ComboboxRenderer",
        "org.openide.explorer.propertysheet.CheckboxInplaceEditor",
        "org.openide.explorer.propertysheet.RendererFactory$CheckboxRenderer",
        "org.openide.explorer.propertysheet.RendererFactory$StringRenderer",
        "org.openide.explorer.propertysheet.RendererFactory$ExceptionRenderer",
        "org.openide.explorer.propertysheet.RendererFactory$ToolkitPropertyChangeListenerProxy",
        "org.openide.explorer.propertysheet.RendererFactory$1",
        "org.openide.util.WeakListeners",
        "org.openide.util.WeakListenerImpl",
        "org.openide.util.WeakListenerImpl$PropertyChange",
        "org.openide.util.WeakListenerImpl$ListenerReference",
        "org.openide.util.WeakListenerImpl$ListenerReference$1",
        "org.openide.explorer.propertysheet.NodePropertyModel",
        "org.openide.nodes.Node$IndexedProperty",
        "org.openide.explorer.propertysheet.ExPropertyEditor",
        "org.openide.explorer.propertysheet.RendererFactory$ExceptionPropertyEditor",
        "org.openide.explorer.propertysheet.PropUtils$NoPropertyEditorEditor",
    };

    private LibraryClasses() {}

    /** Starts loading the classes on a daemon thread of low priority; returns at once. */
    static void preload() {
        Thread t = new Thread(() -> load(SHEET), "crt-preload-classes");
        t.setDaemon(true);
        t.setPriority(Thread.MIN_PRIORITY);
        t.start();
    }

    /** Loads each class that exists; returns how many did (a name a later library version dropped is skipped). */
    static int load(String... names) {
        ClassLoader loader = LibraryClasses.class.getClassLoader();
        int loaded = 0;
        for (String name : names) {
            try {
                Class.forName(name, false, loader);
                loaded++;
            } catch (ClassNotFoundException | LinkageError e) {
                // Only a warm-up: the EDT loads whatever is missing when it needs it, as before.
            }
        }
        return loaded;
    }

    /** How many classes {@link #preload} asks for. */
    static int count() {
        return SHEET.length;
    }

    /** The names {@link #preload} loads. */
    static String[] names() {
        return SHEET.clone();
    }
}
