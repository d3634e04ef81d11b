package dev.crt.lang.value;

/** A string, already unescaped. */
public record StringValue(String value) implements Value {
    @Override
    public String typeName() { return "string"; }

    @Override
    public String toString() { return '"' + value + '"'; }
}
