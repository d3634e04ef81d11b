package dev.crt.cli;

import picocli.CommandLine.Option;

/** The {@code --time} option of commands that compile one moment of a script. */
final class TimeOption {
    @Option(names = "--time", paramLabel = "T", description = "Value of the time variable t (default: ${DEFAULT-VALUE}).")
    double time = 0;
}
