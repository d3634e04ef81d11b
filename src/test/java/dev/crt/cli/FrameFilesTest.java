package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class FrameFilesTest {
    @TempDir
    Path dir;

    @Test
    void onlyFilesNamedLikeTheWritersTemporariesAreRemoved() throws IOException, CliFailure {
        Path frame = dir.resolve("f_01.png");
        Path leftover = Files.writeString(dir.resolve(".f_01.png.tmp-7c0ffee"), "half a frame");
        Path usersBackup = Files.writeString(dir.resolve(".f_01.png.tmp-backup"), "the user's own file");
        Path usersNotes = Files.writeString(dir.resolve(".f_01.png.tmp-1.txt"), "the user's own file");
        Path empty = Files.writeString(dir.resolve(".f_01.png.tmp-"), "the user's own file");

        assertThat(FrameFiles.removeLeftovers(List.of(frame))).isEqualTo(1);

        assertThat(Files.exists(leftover)).isFalse();
        assertThat(Files.exists(usersBackup)).isTrue();
        assertThat(Files.exists(usersNotes)).isTrue();
        assertThat(Files.exists(empty)).isTrue();
    }
}
