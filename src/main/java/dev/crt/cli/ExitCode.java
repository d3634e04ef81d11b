package dev.crt.cli;

/** The exit codes every crt command uses. */
public final class ExitCode {
    public static final int OK = 0;
    public static final int SCRIPT_ERROR = 1;
    public static final int USAGE = 2;
    public static final int FILE_ERROR = 3;
    /** crt preview: no OpenGL context could be made here, or the scene holds what the live view cannot draw. */
    public static final int NO_OPENGL = 4;

    private ExitCode() {}
}
