package dev.crt.lang.value;

import dev.crt.lang.parser.CRTParser;
import java.util.List;

/** A macro: its parameter names and the body statements it runs on each call. */
public record MacroValue(List<String> parameters, List<CRTParser.StatementContext> body) implements Value {
    public MacroValue {
        parameters = List.copyOf(parameters);
        body = List.copyOf(body);
    }

    @Override
    public String typeName() { return "macro"; }
}
