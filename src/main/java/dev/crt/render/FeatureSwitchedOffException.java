package dev.crt.render;

/** A render refused because the scene uses a feature this run has switched off with -Dcrt.without (see Features). */
public final class FeatureSwitchedOffException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    FeatureSwitchedOffException(String message) {
        super(message);
    }
}
