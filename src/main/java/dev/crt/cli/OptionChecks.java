package dev.crt.cli;

import dev.crt.lang.CompileOptions;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/** Turns option values into settings, reporting bad values as usage errors (exit code 2). */
final class OptionChecks {
    private OptionChecks() {}

    static CompileOptions compileOptions(CommandSpec spec, ScriptOptions options, double time) {
        try {
            return options.toCompileOptions(time);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    static void requireAtLeast(CommandSpec spec, Integer value, int min, String option) {
        if (value != null && value < min) {
            throw new ParameterException(spec.commandLine(), option + " must be at least " + min + ", got " + value);
        }
    }

    static void requireBetween(CommandSpec spec, Integer value, int min, int max, String option) {
        if (value != null && (value < min || value > max)) {
            throw new ParameterException(spec.commandLine(),
                    option + " must be from " + min + " to " + max + ", got " + value);
        }
    }
}
