package dev.crt.studio;

import dev.crt.lang.CompileResult;
import dev.crt.lang.Source;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.text.BadLocationException;
import org.fife.ui.rsyntaxtextarea.RSyntaxDocument;

/**
 * One open script: its text, the file it belongs to (none while unsaved), whether it has unsaved
 * changes, and the result of its latest compile. Lives on the Event Dispatch Thread; panels listen
 * to it rather than to the editor.
 */
public final class ScriptDocument {
    /** Told about a document's changes, on the Event Dispatch Thread. */
    public interface Listener {
        /** The text, the file or the modified flag changed. */
        default void changed(ScriptDocument document) {}

        /** A compile of the current text finished. */
        default void compiled(ScriptDocument document, CompileResult result) {}
    }

    static {
        CrtTokenMaker.register();
    }

    private final RSyntaxDocument text = new RSyntaxDocument(CrtTokenMaker.STYLE);
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private final String untitledName;
    private Path file;
    private FileTime diskTime;
    private boolean modified;
    /** The text as last loaded or saved: undoing back to it makes the script unmodified again. */
    private String savedText = "";
    private long version;
    private CompileResult result;
    private long resultVersion = -1;
    private boolean loading;

    ScriptDocument(String untitledName) {
        this.untitledName = untitledName;
        text.addDocumentListener(new DocumentListener() {
            @Override public void insertUpdate(DocumentEvent e) { edited(); }
            @Override public void removeUpdate(DocumentEvent e) { edited(); }
            @Override public void changedUpdate(DocumentEvent e) {}
        });
    }

    private void edited() {
        version++;
        if (loading) return;
        // Comparing lengths first keeps typing into a long script from copying it on every key.
        modified = text.getLength() != savedText.length() || !content().equals(savedText);
        fire();
    }

    /** Replaces the whole text, as when a file is read: not an edit the user made. */
    void load(String content, Path from, FileTime time) {
        loading = true;
        try {
            text.remove(0, text.getLength());
            text.insertString(0, content, null);
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        } finally {
            loading = false;
        }
        file = from;
        diskTime = time;
        modified = false;
        savedText = content;
        fire();
    }

    public RSyntaxDocument text() { return text; }

    /** The whole text now. */
    public String content() {
        try {
            return text.getText(0, text.getLength());
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The file this script is saved in, or null for a new script. */
    public Path file() { return file; }

    /** The name diagnostics and the window title use: the file name, or "untitled-N.crt". */
    public String name() { return file == null ? untitledName : file.getFileName().toString(); }

    public boolean isModified() { return modified; }

    /** Grows with every edit; a compile result belongs to the version it compiled. */
    public long version() { return version; }

    FileTime diskTime() { return diskTime; }

    void saved(Path to, FileTime time) {
        savedText = content();
        file = to;
        diskTime = time;
        modified = false;
        fire();
    }

    void setDiskTime(FileTime time) { diskTime = time; }

    /** Marks a recovered buffer as unsaved work. */
    void markModified() {
        modified = true;
        fire();
    }

    /** The script as the compiler sees it. */
    public Source source() {
        return new Source(file == null ? untitledName : file.toString(), content(), file);
    }

    /** The latest compile result, or null before the first compile. */
    public CompileResult result() { return result; }

    /** True when {@link #result()} compiled the text as it is now. */
    public boolean resultIsCurrent() { return result != null && resultVersion == version; }

    void compiled(CompileResult r, long ofVersion) {
        result = r;
        resultVersion = ofVersion;
        for (Listener l : listeners) l.compiled(this, r);
    }

    public void addListener(Listener l) { listeners.add(l); }

    public void removeListener(Listener l) { listeners.remove(l); }

    private void fire() {
        for (Listener l : listeners) l.changed(this);
    }
}
