package dev.crt.lang;

import dev.crt.scene.SourceSpan;

/** Prints a diagnostic the way compilers do: location, severity, message, the line, a caret, the call chain. */
public final class DiagnosticFormatter {
    private DiagnosticFormatter() {}

    /**
     * {@code scene.crt:12:8: error: message}, then (when the span is in {@code sourceText}) the source
     * line and a {@code ^~~~} under the span's part on that line, then one line per call-chain entry.
     * Lines are separated by '\n'; there is no trailing line break.
     */
    public static String format(Diagnostic d, String sourceText) {
        SourceSpan span = d.span();
        StringBuilder out = new StringBuilder();
        out.append(span.file()).append(':').append(span.line()).append(':').append(span.column())
                .append(": ").append(d.severity().label()).append(": ").append(d.message());
        if (sourceText != null && span.line() >= 1 && span.start() >= 0 && span.start() <= sourceText.length()) {
            appendSourceLine(out, sourceText, span);
        }
        for (String call : d.callChain()) out.append('\n').append("  ").append(call);
        return out.toString();
    }

    private static void appendSourceLine(StringBuilder out, String text, SourceSpan span) {
        int start = span.start();
        int lineStart = start;
        while (lineStart > 0 && !isBreak(text.charAt(lineStart - 1))) lineStart--;
        int lineEnd = start;
        while (lineEnd < text.length() && !isBreak(text.charAt(lineEnd))) lineEnd++;
        out.append('\n').append(text, lineStart, lineEnd).append('\n');
        // Tabs are copied so that the caret lines up however wide the terminal draws them.
        for (int i = lineStart; i < start; i++) out.append(text.charAt(i) == '\t' ? '\t' : ' ');
        out.append('^');
        int end = Math.min(Math.max(span.end(), start), lineEnd);
        for (int i = start + 1; i < end; i++) out.append('~');
    }

    private static boolean isBreak(char c) { return c == '\n' || c == '\r'; }
}
