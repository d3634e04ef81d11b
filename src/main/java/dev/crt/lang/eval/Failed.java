package dev.crt.lang.eval;

/**
 * Unwinds a statement whose error was already reported (or that read a variable whose
 * assignment failed), so that one mistake gives one diagnostic rather than a cascade.
 */
final class Failed extends RuntimeException {
    static final Failed INSTANCE = new Failed();

    private Failed() { super(null, null, false, false); }
}
