package dev.crt.studio;

import dev.crt.lang.eval.Vocabulary;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.swing.text.JTextComponent;
import org.fife.ui.autocomplete.BasicCompletion;
import org.fife.ui.autocomplete.Completion;
import org.fife.ui.autocomplete.DefaultCompletionProvider;

/**
 * Completion for Ctrl+Space: inside an object literal where an attribute name goes, the attributes
 * of that type; elsewhere types, keywords, the script's variables and macros, and built-in functions.
 * Every word comes from the compiler's tables ({@link Vocabulary}) or from the script itself.
 */
final class CompletionSource extends DefaultCompletionProvider {
    @Override
    protected List<Completion> getCompletionsImpl(JTextComponent comp) {
        String typed = getAlreadyEnteredText(comp);
        String text = comp.getText();
        int caret = Math.min(comp.getCaretPosition(), text.length());
        List<Completion> all = candidates(text, caret);
        String prefix = typed.toLowerCase(Locale.ROOT);
        List<Completion> matching = new ArrayList<>();
        for (Completion c : all) {
            if (c.getInputText().toLowerCase(Locale.ROOT).startsWith(prefix)) matching.add(c);
        }
        return matching;
    }

    List<Completion> candidates(String text, int caret) {
        ScriptWords.Context context = ScriptWords.contextAt(text, caret);
        List<Completion> out = new ArrayList<>();
        if (context.attributeName()) {
            List<String> attributes = context.type().equals("Settings") ? Vocabulary.settingsAttributes()
                    : Vocabulary.objectTypes().getOrDefault(context.type(), List.of());
            for (String a : attributes) out.add(new BasicCompletion(this, a + " -> ", "attribute of " + context.type()) {
                @Override public String getInputText() { return a; }
            });
            return out;
        }
        for (Map.Entry<String, Boolean> v : ScriptWords.assignedNames(ScriptWords.lex(text)).entrySet()) {
            out.add(new BasicCompletion(this, v.getKey(), v.getValue() ? "macro" : "variable"));
        }
        for (String v : Vocabulary.PREDEFINED_VARIABLES) out.add(new BasicCompletion(this, v, "the time of the frame"));
        for (Map.Entry<String, String> b : Vocabulary.builtins().entrySet()) {
            out.add(new BasicCompletion(this, b.getKey() + "(", b.getValue()) {
                @Override public String getInputText() { return b.getKey(); }
            });
        }
        for (String type : Vocabulary.objectTypes().keySet()) out.add(new BasicCompletion(this, type, "type"));
        for (String k : Vocabulary.KEYWORDS) out.add(new BasicCompletion(this, k, "keyword"));
        return out;
    }
}
