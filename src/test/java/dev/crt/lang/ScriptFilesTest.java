package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ScriptFilesTest {
    @TempDir
    Path dir;

    private Source write(byte[] bytes) throws IOException {
        Path file = dir.resolve("file.crt");
        Files.write(file, bytes);
        return ScriptFiles.read(file);
    }

    @Test
    void readsUtf8WithoutTheByteOrderMark() throws IOException {
        Source s = write("\uFEFFx = \"é\"\r\ny = 1\r\n".getBytes(StandardCharsets.UTF_8));
        assertThat(s.text()).isEqualTo("x = \"é\"\r\ny = 1\r\n");
        assertThat(s.name()).isEqualTo(dir.resolve("file.crt").toString());
        assertThat(s.isText()).isTrue();
        assertThat(s.file()).isEqualTo(dir.resolve("file.crt"));
    }

    @Test
    void crlfLinesAndColumnsAfterTheBom() throws IOException {
        Source s = write("\uFEFFa = 1\r\nb = a +\r\n  \"s\"\r\n".getBytes(StandardCharsets.UTF_8));
        Diagnostic d = CrtCompiler.compile(s, CompileOptions.DEFAULT).diagnostics().get(0);
        assertThat(d.span().line()).isEqualTo(2);
        assertThat(d.span().column()).isEqualTo(5);
        assertThat(s.text().substring(d.span().start(), d.span().end())).isEqualTo("a +\r\n  \"s\"");
    }

    @Test
    void invalidUtf8IsADiagnosticNamingTheByte() throws IOException {
        byte[] bytes = "Scene { }\n-- caf".getBytes(StandardCharsets.US_ASCII);
        byte[] withBad = new byte[bytes.length + 2];
        System.arraycopy(bytes, 0, withBad, 0, bytes.length);
        withBad[bytes.length] = (byte) 0xC3;
        withBad[bytes.length + 1] = (byte) 0x28;
        Source s = write(withBad);
        assertThat(s.isText()).isFalse();
        CompileResult r = CrtCompiler.compile(s, CompileOptions.DEFAULT);
        assertThat(r.scene()).isNull();
        assertThat(DiagnosticFormatter.format(r.diagnostics().get(0), s.text()).lines().findFirst().orElseThrow())
                .isEqualTo(dir.resolve("file.crt") + ":2:7: error: not a text file (invalid UTF-8 at byte 16)");
    }

    @Test
    void asciiAndOtherTextDecodeAsUtf8() throws IOException {
        // ASCII takes a shorter way than other text; both give what a UTF-8 decoder gives.
        for (String text : List.of("", "Scene { Sphere { } }\n", "x = \"\u00e9\u20ac\"\n", "x = \"\uD83D\uDE00\"",
                "-- a replacement character written on purpose: \uFFFD\n", "\u00ff\u0080\u07ff")) {
            Source s = write(text.getBytes(StandardCharsets.UTF_8));
            assertThat(s.isText()).as(text).isTrue();
            assertThat(s.text()).isEqualTo(text);
        }
    }

    @Test
    void aLoneBadByteIsReportedThoughItDecodesToOneCharacter() throws IOException {
        // Each of these bytes alone is not UTF-8 and decodes to one replacement character: as
        // many characters as bytes, like ASCII, and still not text.
        for (int bad : new int[] {0x80, 0xBF, 0xC3, 0xFF}) {
            Source s = write(new byte[] {'x', ' ', '=', ' ', '1', '\n', (byte) bad, '\n'});
            assertThat(s.isText()).as("byte %x", bad).isFalse();
            assertThat(s.decodingProblem()).isEqualTo("not a text file (invalid UTF-8 at byte 6)");
            assertThat(s.problemOffset()).isEqualTo(6);
        }
    }

    @Test
    void binaryFilesWithNulBytesAreNotText() throws IOException {
        Source s = write(new byte[] {'P', 'K', 3, 4, 0, 0, 0, 1});
        CompileResult r = CrtCompiler.compile(s, CompileOptions.DEFAULT);
        assertThat(r.scene()).isNull();
        assertThat(r.diagnostics()).singleElement()
                .satisfies(d -> assertThat(d.message()).isEqualTo("not a text file (NUL byte at byte 4)"));
        // The line is echoed with its control bytes escaped, and the caret under the NUL.
        assertThat(DiagnosticFormatter.format(r.diagnostics().get(0), s.text()))
                .isEqualTo(dir.resolve("file.crt") + ":1:5: error: not a text file (NUL byte at byte 4)\n"
                        + "PK\\u0003\\u0004\\u0000\\u0000\\u0000\\u0001\n"
                        + " ".repeat(14) + "^~~~~~");
    }

    @Test
    void aMissingFileThrows() {
        assertThatThrownBy(() -> ScriptFiles.read(dir.resolve("nope.crt"))).isInstanceOf(NoSuchFileException.class);
    }
}
