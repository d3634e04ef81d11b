package dev.crt.lang;

/** Compiles a CRT script into a Scene, or into diagnostics. Never throws for any input text. */
public final class CrtCompiler {
    private CrtCompiler() {}

    public static CompileResult compile(Source source, CompileOptions options) {
        throw new UnsupportedOperationException("the compiler lands with issue 2");
    }
}
