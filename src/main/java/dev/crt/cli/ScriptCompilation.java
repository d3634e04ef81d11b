package dev.crt.cli;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Diagnostic;
import dev.crt.lang.DiagnosticFormatter;
import dev.crt.lang.ScriptFiles;
import dev.crt.lang.Source;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/** Reads and compiles one script file for a command, printing its diagnostics. */
final class ScriptCompilation {
    private ScriptCompilation() {}

    /** Reads {@code file}; a missing or unreadable file is a CliFailure with exit code 3. */
    static Source read(Path file) throws CliFailure {
        if (isStandardInput(file)) {
            try {
                return ScriptFiles.read("<stdin>", System.in.readAllBytes());
            } catch (IOException e) {
                throw new CliFailure(ExitCode.FILE_ERROR, "cannot read the standard input: " + plain(e));
            }
        }
        if (Files.isDirectory(file)) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot read " + file + ": it is a folder, not a script");
        }
        try {
            return ScriptFiles.read(file);
        } catch (NoSuchFileException e) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot read " + file + ": no such file");
        } catch (IOException e) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot read " + file + ": " + plain(e));
        }
    }

    /** '-' names the standard input, as it does for most Unix commands. */
    static boolean isStandardInput(Path file) { return file.toString().equals("-"); }

    /** Compiles {@code source}, printing every diagnostic to {@code err}. */
    static CompileResult compile(Source source, CompileOptions options, PrintWriter err) {
        CompileResult result = CrtCompiler.compile(source, options);
        for (Diagnostic d : result.diagnostics()) {
            err.println(DiagnosticFormatter.format(d, source.text()));
        }
        err.flush();
        return result;
    }

    static String plain(IOException e) {
        String m = e.getMessage();
        return m == null || m.isBlank() ? e.getClass().getSimpleName() : m;
    }
}
