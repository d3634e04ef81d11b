package dev.crt.cli;

import java.nio.file.Path;
import java.util.Locale;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

/** The {@code --pass} option of {@code crt render} and {@code crt preview}: the picture, or an id or depth pass. */
final class PassOption {
    /** What a command writes. */
    enum Pass { COLOR, ID, DEPTH }

    @Option(names = "--pass", paramLabel = "PASS",
            description = {"What to write: color (the picture, default); id (each top-level entity's 1-based index k",
                    "as the flat colour (k mod 256, k/256 mod 256, k/65536), background black; .png or .ppm);",
                    "depth (distance along the ray, +Infinity for background; one-channel .pfm)."})
    String pass = "color";

    /** The pass asked for, checked against the output's type; a mismatch is a usage error. */
    Pass pass(CommandSpec spec, Path out) {
        Pass p;
        try {
            p = Pass.valueOf(pass.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(),
                    "--pass must be color, id or depth, got '" + pass + "'");
        }
        String ext = OutputFiles.extension(out);
        if (p == Pass.DEPTH && !ext.equals("pfm")) {
            throw new ParameterException(spec.commandLine(), "--pass depth writes a .pfm file, not " + out);
        }
        if (p == Pass.ID && ext.equals("pfm")) {
            throw new ParameterException(spec.commandLine(), "--pass id writes a .png or .ppm file, not " + out);
        }
        return p;
    }

    /** The default output name for this pass: the script's name with .pfm for depth, else .png. */
    Path defaultOutput(Path script) {
        Path png = RenderCommand.defaultOutput(script);
        if (!pass.equalsIgnoreCase("depth")) return png;
        String name = png.getFileName().toString();
        return Path.of(name.substring(0, name.length() - 4) + ".pfm");
    }
}
