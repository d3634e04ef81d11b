package dev.crt.lang.value;

import java.util.List;

/** A list of values of any types, indexed from 0. */
public record ListValue(List<Value> items) implements Value {
    public static final ListValue EMPTY = new ListValue(List.of());

    public ListValue {
        items = List.copyOf(items);
    }

    @Override
    public String typeName() { return "list"; }
}
