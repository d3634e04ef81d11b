package dev.crt.lang;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/** Reading script files as UTF-8 text. */
public final class ScriptFiles {
    private static final byte[] BOM = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};

    private ScriptFiles() {}

    /**
     * Reads {@code file} as UTF-8 without a leading byte-order mark. Bytes that are not UTF-8 text
     * (malformed sequences, NUL bytes of a binary file) do not throw: the Source then carries the
     * decoding problem, which compiling reports as a diagnostic at the line and column of the bad byte.
     * @throws IOException only when the file cannot be read at all
     */
    public static Source read(Path file) throws IOException {
        return decode(file.toString(), Files.readAllBytes(file), file);
    }

    /** A script that is not a file (the standard input) named {@code name}, decoded as {@link #read} does. */
    public static Source read(String name, byte[] bytes) {
        return decode(name, bytes, null);
    }

    private static Source decode(String name, byte[] bytes, Path file) {
        int skip = startsWithBom(bytes) ? BOM.length : 0;
        int length = bytes.length - skip;
        // Most scripts are ASCII. String's own decoding checks and copies such bytes in loops the
        // JVM compiled while it started, where the CharsetDecoder below runs loops of its own that
        // start interpreted (a tenth of a 2 MB script's compile in a fresh process). As many
        // chars as bytes and no replacement character: every byte was ASCII.
        String text = new String(bytes, skip, length, StandardCharsets.UTF_8);
        if (text.length() != length || text.indexOf('\uFFFD') >= 0) {
            ByteBuffer in = ByteBuffer.wrap(bytes, skip, length);
            CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT);
            CharBuffer out = CharBuffer.allocate(bytes.length);
            CoderResult result = decoder.decode(in, out, true);
            if (result.isError()) {
                // The bytes before the bad one decode alike either way: its character offset in the
                // lossy text is how many characters were decoded before it.
                return new Source(name, text, file, "not a text file (invalid UTF-8 at byte " + in.position() + ")",
                        out.position());
            }
            decoder.flush(out);
            text = out.flip().toString();
        }
        int nul = text.indexOf('\0');
        if (nul >= 0) {
            int byteOffset = skip + text.substring(0, nul).getBytes(StandardCharsets.UTF_8).length;
            return new Source(name, text, file, "not a text file (NUL byte at byte " + byteOffset + ")", nul);
        }
        return new Source(name, text, file);
    }

    private static boolean startsWithBom(byte[] bytes) {
        return bytes.length >= 3 && bytes[0] == BOM[0] && bytes[1] == BOM[1] && bytes[2] == BOM[2];
    }
}
