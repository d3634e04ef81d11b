package dev.crt.lang.eval;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.SortedMap;
import java.util.TreeMap;

/**
 * The words the compiler knows, read from its own tables, for tools such as the studio's
 * completion: object types with their attributes, the Settings attributes, built-in functions.
 */
public final class Vocabulary {
    /** The keywords of the grammar (grammar/CRT.g4), other than type names. */
    public static final List<String> KEYWORDS = List.of("Settings", "Scene", "Macro", "while", "if", "else",
            "true", "false", "translate", "rotate", "scale");

    /** Variables every script has without assigning them. */
    public static final List<String> PREDEFINED_VARIABLES = List.of("t");

    private Vocabulary() {}

    /** Every object type with its attribute names, both sorted. */
    public static SortedMap<String, List<String>> objectTypes() {
        SortedMap<String, List<String>> types = new TreeMap<>();
        for (Map.Entry<String, java.util.Set<String>> e : ObjectBuilder.attributeNames().entrySet()) {
            types.put(e.getKey(), e.getValue().stream().sorted().toList());
        }
        return Collections.unmodifiableSortedMap(types);
    }

    /** The attributes a Settings block takes, sorted. */
    public static List<String> settingsAttributes() {
        return SettingsState.ATTRIBUTES.stream().sorted().toList();
    }

    /** Built-in function names with their signatures as diagnostics print them, sorted by name. */
    public static SortedMap<String, String> builtins() {
        SortedMap<String, String> all = new TreeMap<>();
        for (String name : Builtins.names()) all.put(name, Builtins.signature(name));
        return Collections.unmodifiableSortedMap(all);
    }
}
