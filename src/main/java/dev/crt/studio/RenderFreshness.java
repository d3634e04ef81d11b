package dev.crt.studio;

/**
 * Keeps the render view's selection outlines to the text they were made from: the outline of a
 * render is drawn only while the script's text is the text that render compiled. An edit hides
 * it (the pixels no longer show that scene); undoing back to the rendered text, or the next
 * render, shows it again. Used on the Event Dispatch Thread only.
 */
final class RenderFreshness implements StudioModel.Listener {
    private final RenderView view;
    private ScriptDocument document;
    private String text;
    /** The document version whose text is known to be {@link #text}, so typing costs no comparison of the whole text. */
    private long knownVersion = -1;

    RenderFreshness(RenderView view) {
        this.view = view;
    }

    /** A render of {@code d} finished, compiled from {@code renderedText}. */
    void rendered(ScriptDocument d, String renderedText) {
        document = d;
        text = renderedText;
        knownVersion = -1;
        check();
    }

    /** True when the render view's picture is of the rendered document's text as it is now. */
    boolean isCurrent() {
        if (document == null) return true;
        if (document.version() == knownVersion) return true;
        // Lengths first: a keystroke in a long script should not copy the whole text when they differ.
        if (document.text().getLength() != text.length() || !document.content().equals(text)) return false;
        knownVersion = document.version();
        return true;
    }

    private void check() { view.setPictureCurrent(isCurrent()); }

    @Override
    public void documentChanged(ScriptDocument d) {
        if (d == document) check();
    }

    @Override
    public void closed(ScriptDocument d) {
        if (d != document) return;
        document = null;
        text = null;
        check();
    }
}
