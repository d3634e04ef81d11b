package dev.crt.cli;

/** The exit codes every crt command uses. */
public final class ExitCode {
    public static final int OK = 0;
    public static final int SCRIPT_ERROR = 1;
    public static final int USAGE = 2;
    public static final int FILE_ERROR = 3;
    /** crt preview: no OpenGL context could be made here, or the scene holds what the live view cannot draw. */
    public static final int NO_OPENGL = 4;
    /** A bug in CRT, or a render that ran out of memory after all (EX_SOFTWARE). */
    public static final int INTERNAL_ERROR = 70;
    /** Cancelled with Ctrl-C (SIGINT), as shells report it. */
    public static final int CANCELLED = 130;
    /** Stopped by SIGTERM, as shells report it. */
    public static final int TERMINATED = 143;

    /** The line every command's --help ends with. */
    static final String HELP_LINE = "Exit codes: 0 success, 1 the script has errors, 2 bad usage, 3 a file could not be"
            + " read or written, 4 no OpenGL (crt preview), 70 internal error or out of memory, 130 cancelled (Ctrl-C), 143 terminated (SIGTERM).";

    /** The exit code of a compile with errors: 70 when the heap was full, else 1 (the script has errors). */
    static int ofErrors(dev.crt.lang.CompileResult result) {
        return result.outOfMemory() ? INTERNAL_ERROR : SCRIPT_ERROR;
    }

    private ExitCode() {}
}
